// The worked example of docs/modbus-register-map.md is real: its request
// frames are replayed byte for byte over a TCP socket to the simulated
// controller (session ids fixed for the example), and the replies must be
// the documented bytes. When the protocol changes, print the new example
// with BEZCAM_PRINT_DOC_EXAMPLE=1 and paste it into the document.
#include <arpa/inet.h>
#include <cstdlib>
#include <gtest/gtest.h>
#include <iostream>
#include <netinet/in.h>
#include <regex>
#include <sys/socket.h>
#include <unistd.h>

#include "bezcam/link/crc32.hpp"
#include "bezcam/sim/sim_server.hpp"
#include "support/link_test_util.hpp"

using namespace bezcam;
using namespace bezcam::link;
using namespace bezcam::sim;

namespace {

using Bytes = std::vector<std::uint8_t>;

std::string hex(const Bytes& b) {
  std::string s;
  char buf[4];
  for (std::size_t i = 0; i < b.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%02X", b[i]);
    s += (i ? " " : "") + std::string(buf);
  }
  return s;
}

// Modbus TCP request: MBAP (transaction id, protocol 0, length, unit 1) + PDU.
Bytes frame(std::uint16_t tid, const Bytes& pdu) {
  const auto len = static_cast<std::uint16_t>(pdu.size() + 1);
  Bytes f(7 + pdu.size());
  f[0] = static_cast<std::uint8_t>(tid >> 8);
  f[1] = static_cast<std::uint8_t>(tid);
  f[4] = static_cast<std::uint8_t>(len >> 8);
  f[5] = static_cast<std::uint8_t>(len);
  f[6] = 1;
  std::copy(pdu.begin(), pdu.end(), f.begin() + 7);
  return f;
}
void put(Bytes& b, std::uint16_t v) {
  b.push_back(static_cast<std::uint8_t>(v >> 8));
  b.push_back(static_cast<std::uint8_t>(v));
}
Bytes fc16(std::uint16_t addr, const std::vector<std::uint16_t>& regs) {
  Bytes p{16};
  put(p, addr);
  put(p, static_cast<std::uint16_t>(regs.size()));
  p.push_back(static_cast<std::uint8_t>(2 * regs.size()));
  for (auto r : regs) put(p, r);
  return p;
}
Bytes fc23(std::uint16_t raddr, std::uint16_t rn, std::uint16_t waddr, const std::vector<std::uint16_t>& regs) {
  Bytes p{23};
  put(p, raddr);
  put(p, rn);
  put(p, waddr);
  put(p, static_cast<std::uint16_t>(regs.size()));
  p.push_back(static_cast<std::uint8_t>(2 * regs.size()));
  for (auto r : regs) put(p, r);
  return p;
}
Bytes read(std::uint8_t fc, std::uint16_t addr, std::uint16_t n) {
  Bytes p{fc};
  put(p, addr);
  put(p, n);
  return p;
}

struct Step {
  std::string what;
  Bytes request;
  bool wait_final = false;  // let the controller finish executing first
};

// The example: a 3-line program in two chunks.
const std::string kProgram = "G21 G90\nG00 X10. Y5.\nM30\n";
constexpr std::uint32_t kToken = 0x1234ABCD, kSession = 0x2A2A0001;

std::vector<Step> steps() {
  const std::string c1 = kProgram.substr(0, 14), c2 = kProgram.substr(14);
  return {
      {"read the status block, registers 0-15 (FC 03)", frame(1, read(3, 0, 16))},
      {"OPEN with token 1234ABCD, program of " + std::to_string(kProgram.size()) + " bytes (FC 16 at 0x0100)",
       frame(2, fc16(reg::command, encode_command(Command::open,
                                                  std::array<std::uint32_t, 2>{
                                                      kToken, static_cast<std::uint32_t>(kProgram.size())})))},
      {"read session and state, registers 4-7 (FC 03)", frame(3, read(3, 4, 4))},
      {"chunk 1, 14 bytes \"G21 G90\\nG00 X1\", and read registers 4-13 back (FC 23)",
       frame(4, fc23(4, 10, reg::chunk, encode_chunk({kSession, 1, c1})))},
      {"chunk 2, " + std::to_string(c2.size()) + " bytes \"0. Y5.\\nM30\\n\", and read registers 4-13 back (FC 23)",
       frame(5, fc23(4, 10, reg::chunk, encode_chunk({kSession, 2, c2})))},
      {"chunk 2 again (a retransmission): acknowledged, not applied",
       frame(6, fc23(4, 10, reg::chunk, encode_chunk({kSession, 2, c2})))},
      {"chunk 4 (a gap): refused with exception 03", frame(7, fc16(reg::chunk, encode_chunk({kSession, 4, "X1\n"})))},
      {"why? last_reject, register 15 (FC 04)", frame(8, read(4, 15, 1))},
      {"COMMIT: token, session, " + std::to_string(kProgram.size()) + " bytes, CRC-32 of the program (FC 16 at 0x0100)",
       frame(9, fc16(reg::command, encode_command(Command::commit,
                                                  std::array<std::uint32_t, 4>{
                                                      kToken, kSession, static_cast<std::uint32_t>(kProgram.size()),
                                                      crc32(kProgram)})))},
      {"once executed: registers 4-21, state DONE, 3 lines, 1 motion block, CRC-32 (FC 04)", frame(10, read(4, 4, 18)),
       true},
      {"a write to the read-only status: exception 02", frame(11, Bytes{6, 0x00, 0x06, 0x00, 0x00})},
  };
}

Bytes exchange(int fd, const Bytes& req) {
  EXPECT_EQ(::send(fd, req.data(), req.size(), 0), static_cast<ssize_t>(req.size()));
  Bytes rsp(7);
  std::size_t got = 0;
  while (got < 7) {
    const ssize_t n = ::recv(fd, rsp.data() + got, 7 - got, 0);
    if (n <= 0) return {};
    got += static_cast<std::size_t>(n);
  }
  const std::size_t len = (rsp[4] << 8 | rsp[5]) - 1u;
  rsp.resize(7 + len);
  while (got < rsp.size()) {
    const ssize_t n = ::recv(fd, rsp.data() + got, rsp.size() - got, 0);
    if (n <= 0) return {};
    got += static_cast<std::size_t>(n);
  }
  return rsp;
}

}  // namespace

TEST(DocsExample, TheWorkedTransferIsByteExact) {
  ControllerConfig cfg;
  cfg.profile = load_machine_profile("generic");
  cfg.buffer_bytes = 256;
  cfg.first_session = kSession;
  SimController ctl(cfg);
  ModbusServer server(ctl, ServerConfig{});
  server.start();
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(server.port());
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);

  std::string example;
  for (const auto& s : steps()) {
    if (s.wait_final) ASSERT_TRUE(ctl.wait_final(std::chrono::seconds(5)));
    const Bytes rsp = exchange(fd, s.request);
    ASSERT_FALSE(rsp.empty()) << s.what;
    example += "# " + s.what + "\n> " + hex(s.request) + "\n< " + hex(rsp) + "\n";
  }
  ::close(fd);
  server.stop();
  if (const char* p = std::getenv("BEZCAM_PRINT_DOC_EXAMPLE"); p && std::string(p) == "1") std::cout << example;

  // The document holds the same lines in its example block.
  const std::string doc = test::slurp(std::string(BEZCAM_SOURCE_DIR) + "/docs/modbus-register-map.md");
  const auto begin = doc.find("```text\n# read the status block");
  ASSERT_NE(begin, std::string::npos) << "the worked example is missing from docs/modbus-register-map.md";
  const auto end = doc.find("```", begin + 7);
  EXPECT_EQ(doc.substr(begin + 8, end - begin - 8), example)
      << "docs/modbus-register-map.md's worked example is out of date; print it with BEZCAM_PRINT_DOC_EXAMPLE=1";
}
