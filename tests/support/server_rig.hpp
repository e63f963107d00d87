#pragma once
// A simulated controller behind its Modbus TCP server on a loopback port the
// system chooses, recording the lines its executor takes and its trace, for
// the tests that drive it over real sockets (sim_server_test.cpp,
// abuse_test.cpp).
#include <arpa/inet.h>
#include <array>
#include <chrono>
#include <gtest/gtest.h>
#include <memory>
#include <mutex>
#include <netinet/in.h>
#include <string>
#include <string_view>
#include <sys/socket.h>
#include <unistd.h>
#include <vector>

#include "bezcam/link/streamer.hpp"
#include "bezcam/link/transport.hpp"
#include "bezcam/sim/sim_server.hpp"

namespace bezcam::test {

struct ServerRig {
  std::mutex m;
  std::vector<std::string> lines;
  std::string trace;
  std::unique_ptr<sim::SimController> ctl;
  std::unique_ptr<sim::ModbusServer> server;

  // The generic profile unless `cfg` names one; host and port are chosen here.
  explicit ServerRig(sim::ControllerConfig cfg, sim::ServerConfig scfg = {}) {
    if (cfg.profile.name.empty()) cfg.profile = load_machine_profile("generic");
    cfg.on_line = [this](long, std::string_view t) {
      std::lock_guard lk(m);
      lines.emplace_back(t);
    };
    cfg.trace = [this](std::string_view t, bool restart) {
      std::lock_guard lk(m);
      if (restart) trace.clear();
      trace += t;
    };
    ctl = std::make_unique<sim::SimController>(std::move(cfg));
    scfg.host = "127.0.0.1";
    scfg.port = 0;
    server = std::make_unique<sim::ModbusServer>(*ctl, scfg);
    server->start();
  }
  ~ServerRig() {
    server->stop();
    ctl->stop();
  }
  ServerRig(const ServerRig&) = delete;
  ServerRig& operator=(const ServerRig&) = delete;

  link::Endpoint ep() const { return {"127.0.0.1", server->port()}; }
  std::vector<std::string> executed() {
    std::lock_guard lk(m);
    return lines;
  }
  // A raw TCP connection to the server (the caller closes it).
  int raw() const {
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(server->port());
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    EXPECT_EQ(::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
    return fd;
  }
};

inline link::Status read_status(link::ModbusClient& c) {
  std::array<std::uint16_t, link::reg::status_count> r{};
  c.read_holding(0, r);
  return link::Status::decode(r);
}

// Sender options for a test: a short timeout per request, generous totals.
inline link::StreamOptions quick_stream(std::chrono::milliseconds timeout, std::chrono::seconds totals) {
  link::StreamOptions o;
  o.timeout = timeout;
  o.retries = 5;
  o.retry_time = totals;
  o.stall_timeout = totals;
  return o;
}

}  // namespace bezcam::test
