// libFuzzer target: the bytes a client sends on one connection, as they
// arrive on the socket -> libmodbus's framing and the simulated
// controller's request handling, through serve_connection(), the very loop
// ModbusServer runs per connection (sim_server.hpp).
//
// The input is written into one end of a socketpair and that end is shut,
// so the loop sees the stream followed by the end of the connection: no
// timing, no waiting. Replies are drained after each request. A program the
// stream committed is then executed to its end (DONE or ALARM), which must
// come quickly. Findings: crashes, sanitizer reports, leaks, a controller
// that does not finish, and a broken invariant of the status block.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

#include "bezcam/sim/sim_server.hpp"

namespace {

void drain(int fd) {
  char b[4096];
  while (::read(fd, b, sizeof b) > 0) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace bezcam;
  using namespace bezcam::link;
  using namespace bezcam::sim;
  if (size > 64 * 1024) return 0;  // more than a socket buffer: nothing new to find
  static const MachineProfile generic = load_machine_profile("generic");
  int sv[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0) return 0;
  const int big = 256 * 1024;
  ::setsockopt(sv[1], SOL_SOCKET, SO_SNDBUF, &big, sizeof big);
  ::setsockopt(sv[0], SOL_SOCKET, SO_RCVBUF, &big, sizeof big);
  std::size_t off = 0;
  while (off < size) {
    const ssize_t n = ::write(sv[1], data + off, size - off);
    if (n <= 0) break;
    off += static_cast<std::size_t>(n);
  }
  ::shutdown(sv[1], SHUT_WR);
  ::fcntl(sv[1], F_SETFL, ::fcntl(sv[1], F_GETFL) | O_NONBLOCK);

  ControllerConfig cfg;
  cfg.profile = generic;
  cfg.buffer_bytes = 256;           // the docs' worked example
  cfg.first_session = 0x2A2A0001u;  // its session id, so its frames are seeds that go deep
  {
    SimController ctl(cfg);
    ServerConfig scfg;
    scfg.idle_timeout = std::chrono::milliseconds(1000);  // never reached: the stream ends
    scfg.frame_timeout = std::chrono::milliseconds(1000);
    const std::atomic<bool> stop{false};
    const ConnId id = ctl.connection_opened();
    serve_connection(ctl, id, sv[0], scfg, stop, [&] { drain(sv[1]); });
    ctl.connection_closed(id);
    const Status st = ctl.status();
    // The buffer never holds more than it has; what was acknowledged was
    // applied in order, and fits the protocol's counters.
    if (st.buffer_free > st.buffer_capacity || st.ack_bytes < st.ack_seq) __builtin_trap();
    if (st.state == State::finishing && !ctl.wait_final(std::chrono::seconds(20))) __builtin_trap();
  }
  ::close(sv[0]);
  ::close(sv[1]);
  return 0;
}
