#pragma once
/// Modbus TCP server in front of a SimController: libmodbus on the
/// controller's side (modbus_tcp_pi_listen, modbus_receive, modbus_reply,
/// modbus_reply_exception), one thread per connection so that a slow or
/// silent client never holds up the others.
///
/// Safe defaults: loopback only unless told otherwise; at most
/// `max_connections` connections (when full, the connection silent the
/// longest, never the transfer's owner, is closed to make room); a
/// connection silent for `idle_timeout` is closed; a request must arrive
/// whole within `frame_timeout` between bytes; every receive buffer is one
/// Modbus ADU (260 bytes).
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <list>
#include <mutex>
#include <string>
#include <thread>

#include "bezcam/sim/sim_controller.hpp"

namespace bezcam::sim {

struct ServerConfig {
  std::string host = "127.0.0.1";  ///< address to bind; 127.0.0.1 unless told otherwise
  std::uint16_t port = 0;          ///< 0: a free port chosen by the system (see port())
  int max_connections = 8;         ///< 2..64
  std::chrono::milliseconds idle_timeout{30000};
  std::chrono::milliseconds frame_timeout{500};
  std::chrono::milliseconds send_timeout{2000};  ///< a client that does not read its replies is dropped
};

/// Serves one client on the connected stream socket `fd` until the client
/// closes it, a request breaks the protocol, a timeout of `cfg` (idle,
/// frame) runs out, or `stop` becomes true: libmodbus reads each request
/// (one ADU of at most 260 bytes), the controller answers it as connection
/// `id`, libmodbus sends the reply. This is ModbusServer's per-connection
/// loop; it neither closes `fd` nor opens or closes the connection with the
/// controller. Public so that a socketpair can drive exactly this code (the
/// frame fuzzer, tests/fuzz/fuzz_modbus_frames.cpp). `on_request` (may be
/// empty) runs after each request is received, before it is answered.
void serve_connection(SimController& ctl, ConnId id, int fd, const ServerConfig& cfg, const std::atomic<bool>& stop,
                      const std::function<void()>& on_request = {});

class ModbusServer {
 public:
  /// Binds and listens. Throws IoError("sim.listen", HOST:PORT, ...) when
  /// the address cannot be bound, InputError("sim.config") for bad limits.
  ModbusServer(SimController& controller, ServerConfig cfg);
  /// stop().
  ~ModbusServer();
  ModbusServer(const ModbusServer&) = delete;
  ModbusServer& operator=(const ModbusServer&) = delete;

  /// The bound port (the system's choice when the config said 0).
  std::uint16_t port() const { return port_; }
  const std::string& host() const { return cfg_.host; }

  /// Accepts and serves until stop(); returns after every connection has
  /// been closed.
  void run();
  /// run() in a background thread.
  void start();
  /// Asks run() to return: thread-safe, idempotent, returns at once (from a
  /// signal-waiting thread, for instance). run() closes every connection
  /// before it returns; the destructor waits for start()'s thread.
  void stop();

 private:
  struct Conn {
    ConnId id = 0;
    int fd = -1;
    bool closed = false;  // fd released (guarded by mu_)
    std::atomic<std::int64_t> last_ms{0};
    std::thread th;
  };
  void serve(Conn* c);
  void evict_one_locked();
  void reap_locked(bool all);

  SimController& ctl_;
  ServerConfig cfg_;
  int listen_fd_ = -1;
  int wake_[2] = {-1, -1};
  std::uint16_t port_ = 0;
  std::mutex mu_;
  std::condition_variable closed_cv_;  // a connection released its socket
  std::list<Conn> conns_;
  std::atomic<bool> stopping_{false};
  std::mutex wake_mu_;  // stop()'s write against the destructor's close
  std::thread bg_;
};

}  // namespace bezcam::sim
