#pragma once
/// The sender: streams a G-code program to a controller over Modbus TCP
/// following docs/modbus-register-map.md. Flow control (never more than the
/// controller's buffer_free), sequence numbers, resume after a dropped
/// connection from the controller's acknowledged position, detection of a
/// restarted controller, CRC-32 confirmation of the whole program.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "bezcam/link/register_map.hpp"
#include "bezcam/link/transport.hpp"

namespace bezcam::link {

/// A snapshot for progress displays.
struct StreamProgress {
  std::uint64_t bytes_acked = 0, bytes_total = 0;
  std::uint64_t lines_acked = 0, lines_total = 0;  ///< complete lines inside the acknowledged bytes
  std::uint32_t lines_executed = 0;
  double seconds = 0;  ///< since the transfer was opened
  double rate = 0;     ///< bytes per second acknowledged, over the whole transfer
  State state = State::idle;
  int reconnects = 0;
  bool waiting = false;  ///< the controller's buffer is full: waiting for it to execute
};

struct StreamOptions {
  /// Per request (connect, read, write): a controller silent this long is
  /// taken as lost and the connection is replaced.
  std::chrono::milliseconds timeout{2000};
  /// Reconnection attempts after a lost connection before giving up; the
  /// count restarts whenever the controller acknowledges new bytes.
  int retries = 5;
  /// Bound on the time spent reconnecting after one loss.
  std::chrono::milliseconds retry_time{20000};
  /// The controller may go this long without taking a byte or executing a
  /// line (a full buffer on a slow machine) before the sender gives up.
  std::chrono::milliseconds stall_timeout{60000};
  /// Payload per chunk, 1..228 (0: the controller's maximum).
  std::uint16_t chunk_bytes = 0;
  /// Called after every acknowledgement and every status poll.
  std::function<void(const StreamProgress&)> on_progress;
  /// Called with a sentence on notable events (lost connection, resume).
  std::function<void(const std::string&)> on_event;
  /// Set (by a signal handler: Ctrl-C, SIGTERM) to stop: the sender sends
  /// ABORT, so the controller stops at once (alarm "aborted", spindle off)
  /// rather than waiting for the session timeout, and throws
  /// ControllerError errc::link_cancelled saying what was acknowledged and
  /// executed. Checked between requests: within one request timeout.
  const std::atomic<bool>* cancel = nullptr;
};

struct StreamResult {
  std::uint32_t session = 0, crc = 0;
  std::uint64_t bytes = 0, lines = 0, chunks = 0;
  std::uint32_t lines_executed = 0, blocks_executed = 0;
  /// The controller's count of machine time stood waiting for data (ms)
  /// and of those stalls (status registers starved_ms, stalls).
  std::uint32_t starved_ms = 0, stalls = 0;
  int reconnects = 0;
  double seconds = 0;
};

/// Streams `program` to the controller at `to` and waits until it reports
/// DONE, which it does only after confirming the program's length and
/// CRC-32 and executing every line.
///
/// Throws InputError (empty program, NUL byte, larger than 4 GiB: exit 2),
/// IoError (cannot connect, or the connection could not be restored within
/// `retries` / `retry_time`: exit 3), ControllerError (busy with another
/// sender, alarm with its line and message, restarted controller, stalled:
/// exit 4).
StreamResult stream_program(std::string_view program, const Endpoint& to, const StreamOptions& opt = {});

/// The same over connections made by `connect` (a Modbus TCP one, an
/// in-process one for tests: sim/in_process_transport.hpp); `peer` names
/// the controller in messages (the place of the errors above). Throws as
/// above; IoError also when `connect` throws it.
StreamResult stream_program(std::string_view program, const TransportFactory& connect, const std::string& peer,
                            const StreamOptions& opt = {});

/// What a controller says about itself: its status registers, the alarm
/// text and the profile it enforces.
struct ControllerReport {
  Status status;
  std::string alarm_text, machine;
};
/// Reads the controller's status (IoError when it cannot be reached,
/// link.protocol when it is not a bezcam controller).
ControllerReport controller_status(const Endpoint& to, std::chrono::milliseconds timeout);
/// The operator's stop: aborts whatever transfer the controller holds
/// (ABORT with token 0 and the open session, docs/modbus-register-map.md),
/// whoever sent it, and returns the state after. A controller with no open
/// transfer is left as it is.
ControllerReport abort_controller(const Endpoint& to, std::chrono::milliseconds timeout);

}  // namespace bezcam::link
