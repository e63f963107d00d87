#pragma once
/// A link::Transport that hands each request straight to a SimController
/// (handle_frame) in the caller's thread: no socket, no server thread. It
/// lets the sender's retry and resume logic be tested deterministically,
/// with faults placed at exact requests, alongside the socket tests.
#include <cstdint>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "bezcam/link/transport.hpp"
#include "bezcam/sim/sim_controller.hpp"

namespace bezcam::sim {

/// Faults of the link itself (the controller has its own: ControllerConfig).
/// Requests are counted 1-based over every connection of one InProcessLink,
/// reads included; each listed number fires once.
struct LinkFaults {
  /// The N-th request is lost with its connection before the controller
  /// sees it: the caller gets IoError and the request had no effect.
  std::vector<std::uint64_t> drop_before;
  /// The N-th request reaches the controller and takes effect, then the
  /// connection drops before the reply: IoError although it was applied.
  std::vector<std::uint64_t> drop_after;
  /// These connection attempts fail with IoError (1-based, over the link's
  /// life: the first connection is attempt 1).
  std::vector<int> failed_connects;
};

/// Counters, for tests to check what went over the link.
struct LinkStats {
  std::uint64_t requests = 0;  ///< every request attempted, dropped ones included
  int connects = 0;            ///< connection attempts, failed ones included
  int open = 0;                ///< connections currently open
};

/// The in-process link to one controller: makes connections (factory())
/// that share one set of faults and counters. Must outlive the connections
/// it makes only through the shared state the factory holds, so it may be
/// destroyed first. The controller must outlive every connection.
class InProcessLink {
 public:
  explicit InProcessLink(SimController& controller, LinkFaults faults = {});

  /// A factory for link::stream_program(); the timeout is ignored (a
  /// request is answered before the call returns).
  link::TransportFactory factory() const;
  /// One connection now (for tests that drive requests by hand). Throws
  /// IoError like the factory.
  std::unique_ptr<link::Transport> connect() const;
  LinkStats stats() const;

  /// What a connection shares with the link (public for the connection
  /// class in the implementation file).
  struct Shared {
    // A constructor, not an aggregate: clang 14 (clang-tidy, the fuzz
    // build) cannot make_shared an aggregate from parenthesised arguments.
    Shared(SimController& c, LinkFaults f) : ctl(c), faults(std::move(f)) {}
    SimController& ctl;
    LinkFaults faults;
    LinkStats stats;
    std::mutex m;
  };

 private:
  std::shared_ptr<Shared> shared_;
};

}  // namespace bezcam::sim
