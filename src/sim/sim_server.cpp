#include "bezcam/sim/sim_server.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <linux/sockios.h>
#include <modbus/modbus.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include "bezcam/error.hpp"

namespace bezcam::sim {

namespace {

std::int64_t now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

void set_timeout(modbus_t* ctx, int (*setter)(modbus_t*, uint32_t, uint32_t), std::chrono::milliseconds t) {
  const auto ms = std::max<long long>(1, t.count());
  setter(ctx, static_cast<uint32_t>(ms / 1000), static_cast<uint32_t>((ms % 1000) * 1000));
}

// Registers the per-connection mapping covers: everything up to the end of
// the largest chunk write FC 16 could carry (validated before it is used).
constexpr int kHoldingRegs = reg::chunk + MODBUS_MAX_WRITE_REGISTERS;

}  // namespace

ModbusServer::ModbusServer(SimController& controller, ServerConfig cfg) : ctl_(controller), cfg_(std::move(cfg)) {
  if (cfg_.max_connections < 2 || cfg_.max_connections > 64)
    throw InputError(errc::sim_config, Place::at_register("max connections"),
                     "must be between 2 and 64, found " + std::to_string(cfg_.max_connections));
  const std::string where = cfg_.host + ":" + std::to_string(cfg_.port);
  const std::string service = std::to_string(cfg_.port);
  modbus_t* ctx = modbus_new_tcp_pi(cfg_.host.c_str(), service.c_str());
  if (!ctx)
    throw IoError(errc::sim_listen, Place::at_file(where),
                  std::string("cannot create a Modbus context: ") + std::strerror(errno));
  listen_fd_ = modbus_tcp_pi_listen(ctx, 16);
  const int err = errno;
  modbus_free(ctx);
  if (listen_fd_ < 0)
    throw IoError(errc::sim_listen, Place::at_file(where),
                  std::string("cannot listen: ") + std::strerror(err) +
                      "; choose another port (0 lets the system pick a free one)");
  // Non-blocking so that accept() never hangs when a client vanished
  // between poll() and accept().
  ::fcntl(listen_fd_, F_SETFL, ::fcntl(listen_fd_, F_GETFL) | O_NONBLOCK);
  ::fcntl(listen_fd_, F_SETFD, FD_CLOEXEC);
  sockaddr_storage ss{};
  socklen_t len = sizeof ss;
  if (::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&ss), &len) == 0) {
    if (ss.ss_family == AF_INET) port_ = ntohs(reinterpret_cast<sockaddr_in*>(&ss)->sin_port);
    if (ss.ss_family == AF_INET6) port_ = ntohs(reinterpret_cast<sockaddr_in6*>(&ss)->sin6_port);
  }
  if (::pipe2(wake_, O_CLOEXEC | O_NONBLOCK) != 0) {
    ::close(listen_fd_);
    throw IoError(errc::sim_listen, Place::at_file(where),
                  std::string("cannot create a pipe: ") + std::strerror(errno));
  }
}

ModbusServer::~ModbusServer() {
  stop();
  if (bg_.joinable()) bg_.join();
  std::lock_guard lk(wake_mu_);  // a late stop() from another thread has finished writing
  if (listen_fd_ >= 0) ::close(listen_fd_);
  for (int& fd : wake_)
    if (fd >= 0) ::close(fd), fd = -1;
}

void ModbusServer::start() {
  bg_ = std::thread([this] { run(); });
}

void ModbusServer::stop() {
  std::lock_guard lk(wake_mu_);
  if (!stopping_.exchange(true) && wake_[1] >= 0) {
    const char b = 1;
    [[maybe_unused]] const auto n = ::write(wake_[1], &b, 1);
  }
}

void ModbusServer::reap_locked(bool all) {
  for (auto it = conns_.begin(); it != conns_.end();) {
    // A closed connection's thread touches nothing guarded by mu_ any more,
    // so it can be joined here.
    if (it->closed || all) {
      if (it->th.joinable()) it->th.join();
      it = conns_.erase(it);
    } else {
      ++it;
    }
  }
}

void ModbusServer::evict_one_locked() {
  const ConnId owner = ctl_.owner();
  Conn* victim = nullptr;
  for (auto& c : conns_)
    if (!c.closed && c.id != owner && (!victim || c.last_ms.load() < victim->last_ms.load())) victim = &c;
  if (victim) ::shutdown(victim->fd, SHUT_RDWR);  // its thread sees the end of the stream and leaves
}

// The accept loop: poll() on the listening socket and the wake pipe, with
// a 1 s timeout so finished connection threads are joined even when nobody
// connects.
void ModbusServer::run() {
  while (!stopping_) {
    pollfd p[2] = {{listen_fd_, POLLIN, 0}, {wake_[0], POLLIN, 0}};
    const int n = ::poll(p, 2, 1000);
    if (n < 0 && errno != EINTR) break;
    if (stopping_ || (p[1].revents & POLLIN)) break;
    {
      std::lock_guard lk(mu_);
      reap_locked(false);
    }
    if (!(p[0].revents & POLLIN)) continue;
    const int fd = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd < 0) continue;
    const int one = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    const auto snd = cfg_.send_timeout.count();
    timeval tv{static_cast<time_t>(snd / 1000), static_cast<suseconds_t>((snd % 1000) * 1000)};
    ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
    std::unique_lock lk(mu_);
    auto open_count = [&] {
      std::size_t live = 0;
      for (const auto& c : conns_) live += c.closed ? 0 : 1;
      return live;
    };
    if (open_count() >= static_cast<std::size_t>(cfg_.max_connections)) {
      evict_one_locked();
      // The evicted thread takes mu_ to release its socket: wait for it, so
      // that never more than max_connections are served at once.
      closed_cv_.wait(lk, [&] { return stopping_ || open_count() < static_cast<std::size_t>(cfg_.max_connections); });
      reap_locked(false);
    }
    auto& c = conns_.emplace_back();
    c.id = ctl_.connection_opened();
    c.fd = fd;
    c.last_ms = now_ms();
    c.th = std::thread([this, &c] { serve(&c); });
  }
  // Stopping: wake every connection thread and wait for them.
  {
    std::lock_guard lk(mu_);
    for (auto& c : conns_)
      if (!c.closed) ::shutdown(c.fd, SHUT_RDWR);
  }
  std::lock_guard lk(mu_);
  for (auto& c : conns_)
    if (c.th.joinable()) {
      // Threads only need mu_ to mark themselves closed; release it while
      // joining each one.
      mu_.unlock();
      c.th.join();
      mu_.lock();
    }
  conns_.clear();
}

void serve_connection(SimController& ctl, ConnId id, int fd, const ServerConfig& cfg, const std::atomic<bool>& stop,
                      const std::function<void()>& on_request) {
  modbus_t* ctx = modbus_new_tcp("127.0.0.1", 502);  // address unused: the socket is given
  modbus_mapping_t* map =
      ctx ? modbus_mapping_new_start_address(0, 0, 0, 0, 0, kHoldingRegs, 0, reg::readable_end) : nullptr;
  if (ctx && map) {
    modbus_set_socket(ctx, fd);
    // Indication timeout: how long a request may take to start (idle
    // connections); byte timeout: how long between its bytes (half frames).
    // Its own context and mapping per connection: a libmodbus context is
    // not thread-safe, and modbus_reply then never reads shared memory.
    set_timeout(ctx, modbus_set_indication_timeout, cfg.idle_timeout);
    set_timeout(ctx, modbus_set_byte_timeout, cfg.frame_timeout);
    set_timeout(ctx, modbus_set_response_timeout, cfg.frame_timeout);
    std::uint8_t req[MODBUS_TCP_MAX_ADU_LENGTH];
    // The wait for a request is cut in slices no longer than the send
    // timeout: between requests the connection is checked for replies the
    // client does not take. A client that pipelines requests and never reads
    // can fill both directions of the connection (its sends wait for our
    // window, our replies for its window) while this thread waits for a
    // request: then its queue of unsent replies stops moving, and it is
    // dropped after the send timeout, as if a send had timed out.
    const auto slice = std::max<long long>(1, std::min(cfg.idle_timeout, cfg.send_timeout).count());
    auto last_request = std::chrono::steady_clock::now(), stuck_since = last_request;
    int stuck_bytes = -1;
    while (!stop) {
      pollfd p{fd, POLLIN, 0};
      const int ready = ::poll(&p, 1, static_cast<int>(slice));
      if (ready < 0 && errno == EINTR) continue;
      if (ready < 0) break;
      if (ready == 0) {
        const auto now = std::chrono::steady_clock::now();
        if (now - last_request >= cfg.idle_timeout) break;  // silent for too long
        int unsent = 0;
        if (::ioctl(fd, SIOCOUTQ, &unsent) != 0) unsent = 0;
        if (unsent > 0 && unsent == stuck_bytes) {
          if (now - stuck_since >= cfg.send_timeout) break;  // replies not taken
        } else {
          stuck_bytes = unsent;
          stuck_since = now;
        }
        continue;
      }
      const int rc = modbus_receive(ctx, req);
      if (rc < 0) break;  // closed, half a frame for too long, or garbage
      last_request = std::chrono::steady_clock::now();
      stuck_bytes = -1;
      if (rc == 0) continue;
      if (on_request) on_request();
      const FrameReply r = ctl.handle_frame(id, std::span<const std::uint8_t>(req, static_cast<std::size_t>(rc)));
      if (r.drop) break;
      int sent = 0;
      if (r.exception != 0) {
        sent = modbus_reply_exception(ctx, req, static_cast<unsigned>(r.exception));
      } else {
        // The controller produced the values; modbus_reply frames them.
        std::uint16_t* tab = r.read_input ? map->tab_input_registers : map->tab_registers;
        std::copy(r.regs.begin(), r.regs.end(), tab + r.read_addr);
        sent = modbus_reply(ctx, req, rc, map);
      }
      if (sent < 0) break;
    }
    modbus_set_socket(ctx, -1);  // the caller closes the socket
  }
  if (map) modbus_mapping_free(map);
  if (ctx) modbus_free(ctx);
}

void ModbusServer::serve(Conn* c) {
  serve_connection(ctl_, c->id, c->fd, cfg_, stopping_, [c] { c->last_ms = now_ms(); });
  // Tell the controller before the slot is freed: the accept loop opens the
  // next connection as soon as it is, and the count readers see must never
  // exceed the cap.
  ctl_.connection_closed(c->id);
  {
    std::lock_guard lk(mu_);
    ::close(c->fd);
    c->closed = true;
  }
  closed_cv_.notify_all();
}

}  // namespace bezcam::sim
