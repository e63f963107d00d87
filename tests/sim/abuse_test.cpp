// The simulated controller under abuse, over real sockets on 127.0.0.1
// (ports chosen by the system): a storm of connections and floods of reads
// while a transfer runs, garbage and frames dribbled byte by byte, a client
// that never reads its replies, connection churn. The controller stays
// responsive to the legitimate sender and readers, caps what it holds, and
// executes exactly the program sent. (sim_server_test.cpp covers idle
// connections, half frames and the cap without traffic.) Loops are bounded,
// readiness is awaited with poll(), nothing sleeps.
#include <arpa/inet.h>
#include <atomic>
#include <fcntl.h>
#include <future>
#include <gtest/gtest.h>
#include <mutex>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

#include "bezcam/error.hpp"
#include "bezcam/link/crc32.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/link/transport.hpp"
#include "bezcam/sim/sim_server.hpp"
#include "support/link_test_util.hpp"
#include "support/server_rig.hpp"

using namespace bezcam;
using namespace bezcam::link;
using namespace bezcam::sim;
using namespace std::chrono_literals;

namespace {

using Rig = test::ServerRig;
using test::read_status;

StreamOptions quick() { return test::quick_stream(3000ms, 20s); }

// Streams `program` in the background; `opened` is ready once the
// controller has accepted the transfer (the sender owns it from then on).
struct Transfer {
  std::promise<void> opened_p;
  std::shared_future<void> opened = opened_p.get_future().share();
  std::atomic<bool> signalled{false};
  std::future<StreamResult> result;
  Transfer(const std::string& program, const Endpoint& ep) {
    auto opt = quick();
    opt.on_event = [this](const std::string& e) {
      if (e.rfind("transfer opened", 0) == 0 && !signalled.exchange(true)) opened_p.set_value();
    };
    result = std::async(std::launch::async, [program, ep, opt] { return stream_program(program, ep, opt); });
  }
};

// Waits up to `ms` for fd to be readable (data or end of stream).
bool readable(int fd, int ms) {
  pollfd p{fd, POLLIN, 0};
  return ::poll(&p, 1, ms) == 1;
}

// What the server did with a request: closed the connection, or answered
// with a Modbus exception (function code + 0x80); "" when neither within 5 s.
std::string fate(int fd) {
  std::vector<std::uint8_t> got;
  char b[512];
  for (int i = 0; i < 100; ++i) {
    if (!readable(fd, 5000)) return "";
    const ssize_t n = ::recv(fd, b, sizeof b, 0);
    if (n <= 0) return got.empty() ? "closed" : "";
    got.insert(got.end(), b, b + n);
    if (got.size() >= 9) return (got[7] & 0x80) ? "exception" : "";
  }
  return "";
}

std::vector<std::uint8_t> read_request(std::uint16_t tid, std::uint16_t addr, std::uint16_t n) {
  return {static_cast<std::uint8_t>(tid >> 8),
          static_cast<std::uint8_t>(tid),
          0,
          0,
          0,
          6,
          1,
          3,
          static_cast<std::uint8_t>(addr >> 8),
          static_cast<std::uint8_t>(addr),
          static_cast<std::uint8_t>(n >> 8),
          static_cast<std::uint8_t>(n)};
}

}  // namespace

TEST(Abuse, AStormOfConnectionsWhileATransferRunsLeavesTheProgramIntact) {
  ControllerConfig cfg;
  cfg.buffer_bytes = 512;
  cfg.exec_delay = 200us;  // keeps the transfer running through the storm
  ServerConfig scfg;
  scfg.max_connections = 6;
  Rig rig(cfg, scfg);
  const std::string program = test::zigzag_program(1500);
  Transfer t(program, rig.ep());
  ASSERT_EQ(t.opened.wait_for(20s), std::future_status::ready);
  // 16 clients at once, each connecting 4 times and reading: more than the
  // cap, so some are closed to make room; never the sender.
  std::atomic<int> served{0}, evicted{0}, over_cap{0};
  std::vector<std::thread> storm;
  for (int i = 0; i < 16; ++i)
    storm.emplace_back([&] {
      for (int k = 0; k < 4; ++k) {
        try {
          ModbusClient c(rig.ep(), 3000ms);
          for (int r = 0; r < 10; ++r) {
            const Status s = read_status(c);
            if (s.magic != kMagic) ADD_FAILURE() << "garbled status";
            if (s.connections > scfg.max_connections) ++over_cap;
            ++served;
          }
        } catch (const IoError&) {
          ++evicted;  // closed to make room, or refused while full
        }
      }
    });
  for (auto& th : storm) th.join();
  const StreamResult r = t.result.get();
  EXPECT_EQ(r.crc, crc32(program));
  EXPECT_EQ(rig.executed(), test::split_lines(program));  // every line once, in order, byte for byte
  EXPECT_EQ(over_cap.load(), 0);
  EXPECT_GT(served.load(), 0);
  // Afterwards a reader is answered at once, and the connections are back
  // within the cap.
  ModbusClient c(rig.ep(), 3000ms);
  const Status s = read_status(c);
  EXPECT_EQ(s.state, State::done);
  EXPECT_LE(s.connections, scfg.max_connections);
}

TEST(Abuse, FloodsOfReadsWhileATransferRunsNeitherStallNorCorruptIt) {
  ControllerConfig cfg;
  cfg.buffer_bytes = 512;
  cfg.exec_delay = 100us;
  ServerConfig scfg;
  Rig rig(cfg, scfg);
  const std::string program = test::zigzag_program(2000);
  Transfer t(program, rig.ep());
  ASSERT_EQ(t.opened.wait_for(20s), std::future_status::ready);
  std::atomic<bool> done{false};
  std::atomic<int> reads{0}, while_receiving{0};
  std::vector<std::thread> flood;
  for (int i = 0; i < 4; ++i)
    flood.emplace_back([&, i] {
      ModbusClient c(rig.ep(), 3000ms);
      std::uint32_t last_ack = 0;
      for (int k = 0; k < 5000 && !done; ++k) {  // bounded: at most 5000 reads each
        if (i % 2 == 0) {
          const Status s = read_status(c);
          if (s.ack_bytes < last_ack) ADD_FAILURE() << "acknowledgement went back";
          if (s.buffer_free > s.buffer_capacity) ADD_FAILURE() << "buffer holds more than its capacity";
          last_ack = s.ack_bytes;
          if (s.state == State::receiving) ++while_receiving;
        } else {
          std::array<std::uint16_t, 125> in{};
          c.read_input(0, in);
          if (in[0] != kMagic) ADD_FAILURE() << "garbled input registers";
        }
        ++reads;
      }
    });
  const StreamResult r = t.result.get();
  done = true;
  for (auto& th : flood) th.join();
  EXPECT_EQ(r.crc, crc32(program));
  EXPECT_EQ(rig.executed(), test::split_lines(program));
  EXPECT_GT(while_receiving.load(), 0);      // the reads did overlap the transfer
  EXPECT_EQ(rig.ctl->status().rejects, 0u);  // and never disturbed the sender's requests
}

TEST(Abuse, GarbageIsDroppedDribbledFramesAreAnsweredAndOthersServed) {
  ControllerConfig cfg;
  ServerConfig scfg;
  scfg.frame_timeout = 300ms;
  Rig rig(cfg, scfg);
  ModbusClient reader(rig.ep(), 3000ms);
  // Frames that contradict themselves: another protocol id, an MBAP length
  // that is not the frame's, a length far beyond one ADU.
  const std::vector<std::vector<std::uint8_t>> garbage = {
      {0, 1, 0, 5, 0, 6, 1, 3, 0, 0, 0, 1},
      {0, 1, 0, 0, 0, 9, 1, 3, 0, 0, 0, 1},
      {0, 1, 0, 0, 0xFF, 0xFF, 1, 3, 0, 0, 0, 1},
      {0, 1, 0, 0, 0, 2, 1, 0x2B},
  };
  for (const auto& g : garbage) {
    const int fd = rig.raw();
    ASSERT_EQ(::send(fd, g.data(), g.size(), MSG_NOSIGNAL), static_cast<ssize_t>(g.size()));
    // A frame that contradicts itself closes the connection; an unknown
    // function gets exception 01. Never a hang.
    EXPECT_EQ(fate(fd), g[7] == 0x2B ? "exception" : "closed") << int(g[5]);
    ::close(fd);
    EXPECT_EQ(read_status(reader).magic, kMagic);  // others are served meanwhile
  }
  // A legitimate request dribbled one byte per send arrives whole.
  const int fd = rig.raw();
  const int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  const auto req = read_request(7, 0, 2);
  for (const auto b : req) ASSERT_EQ(::send(fd, &b, 1, MSG_NOSIGNAL), 1);
  std::vector<std::uint8_t> reply;
  for (int i = 0; i < 100 && reply.size() < 13; ++i) {
    ASSERT_TRUE(readable(fd, 5000));
    std::uint8_t b[64];
    const ssize_t n = ::recv(fd, b, sizeof b, 0);
    ASSERT_GT(n, 0);
    reply.insert(reply.end(), b, b + n);
  }
  ASSERT_EQ(reply.size(), 13u);  // MBAP 7 + FC + count + 2 registers
  EXPECT_EQ(reply[7], 3);
  EXPECT_EQ((reply[9] << 8) | reply[10], kMagic);
  ::close(fd);
}

TEST(Abuse, AClientThatNeverReadsItsRepliesIsDroppedWhileOthersAreServed) {
  ControllerConfig cfg;
  ServerConfig scfg;
  scfg.send_timeout = 300ms;
  Rig rig(cfg, scfg);
  const int fd = rig.raw();
  const int small = 4096;
  ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &small, sizeof small);
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
  // Pipelined reads of 125 registers (259-byte replies), never read: the
  // server's replies back up until its send times out and it lets go.
  std::vector<std::uint8_t> batch;
  for (int i = 0; i < 256; ++i) {
    const auto r = read_request(static_cast<std::uint16_t>(i), 0, 125);
    batch.insert(batch.end(), r.begin(), r.end());
  }
  // Dropped: the client's socket reports it, or, sooner, the server's own
  // connection count does (the closed socket's FIN waits behind the replies
  // the client never read, and TCP's backoff can delay the reset for seconds
  // on a loaded machine).
  bool dropped = false;
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  long long sent = 0;
  int rounds = 0, last_connections = -1;
  for (int round = 0; !dropped && std::chrono::steady_clock::now() < deadline; ++round, ++rounds) {
    pollfd p{fd, POLLOUT, 0};
    const int ready = ::poll(&p, 1, 100);
    if (ready == 1 && (p.revents & (POLLERR | POLLHUP))) {
      dropped = true;
      break;
    }
    if (ready == 1) {
      const ssize_t n = ::send(fd, batch.data(), batch.size(), MSG_NOSIGNAL);
      if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) dropped = true;
      if (n > 0) sent += n;
    }
    if (ready != 1 || round % 64 == 0) {
      // Meanwhile another client is answered (one thread per connection);
      // once it is the only connection, the flooder was let go.
      ModbusClient c(rig.ep(), 3000ms);
      const Status st = read_status(c);
      EXPECT_EQ(st.magic, kMagic);
      last_connections = st.connections;
      if (st.connections <= 1) dropped = true;
    }
  }
  EXPECT_TRUE(dropped) << "the server kept a client that does not read its replies: " << rounds << " rounds, " << sent
                       << " bytes of requests sent, " << last_connections << " connections at the last status";
  ::close(fd);
  const std::string program = test::zigzag_program(100);
  const StreamResult r = stream_program(program, rig.ep(), quick());
  EXPECT_EQ(r.crc, crc32(program));
  EXPECT_EQ(rig.executed(), test::split_lines(program));
}

TEST(Abuse, ConnectionChurnLeavesNothingBehind) {
  ControllerConfig cfg;
  ServerConfig scfg;
  scfg.frame_timeout = 200ms;
  Rig rig(cfg, scfg);
  for (int i = 0; i < 90; ++i) {
    const int fd = rig.raw();
    if (i % 3 == 1) {  // half a frame, then gone
      const std::uint8_t half[] = {0, 1, 0, 0, 0, 6, 1};
      ::send(fd, half, sizeof half, MSG_NOSIGNAL);
    } else if (i % 3 == 2) {  // a whole request, gone before the reply
      const auto req = read_request(1, 0, 4);
      ::send(fd, req.data(), req.size(), MSG_NOSIGNAL);
    }
    ::close(fd);
  }
  // Every one of them is released: polled (each poll a round trip, the loop
  // bounded) until only this reader is left.
  ModbusClient reader(rig.ep(), 3000ms);
  std::uint16_t connections = 0;
  for (int i = 0; i < 20000; ++i) {
    connections = read_status(reader).connections;
    if (connections == 1) break;
  }
  EXPECT_EQ(connections, 1);
  const std::string program = test::zigzag_program(50);
  EXPECT_EQ(stream_program(program, rig.ep(), quick()).crc, crc32(program));
}
