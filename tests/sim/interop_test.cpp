// Interoperability: a third-party Modbus master (mbpoll, from Debian's
// package, listed in .ci/packages) reads the status registers of the
// simulator process while a transfer runs, with holding (FC 03) and input
// (FC 04) reads, and gets a standard exception for a write to them.
#include <cstdio>
#include <future>
#include <gtest/gtest.h>
#include <regex>

#include "bezcam/link/register_map.hpp"
#include "bezcam/link/streamer.hpp"
#include "support/link_test_util.hpp"

using namespace bezcam;
using namespace bezcam::link;

namespace {

// mbpoll prints one "[address]: value" line per register.
std::map<int, long long> values(const std::string& out) {
  std::map<int, long long> v;
  static const std::regex line(R"(\[(\d+)\]:\s+(-?\d+|0x[0-9A-Fa-f]+))");
  for (std::sregex_iterator it(out.begin(), out.end(), line), end; it != end; ++it)
    v[std::stoi((*it)[1])] = std::stoll((*it)[2], nullptr, 0);
  return v;
}

}  // namespace

TEST(Interop, MbpollReadsTheStatusRegistersDuringATransfer) {
  const std::string mbpoll = test::find_on_path("mbpoll");
  if (mbpoll.empty()) GTEST_SKIP() << "mbpoll is not installed (Debian package mbpoll, listed in .ci/packages)";
  test::TempDir dir;
  test::SimProcess sim(dir, {"--buffer", "256", "--exec-delay-ms", "2"});
  const std::string port = std::to_string(sim.port());
  auto poll = [&](const std::vector<std::string>& args, const std::string& write_value = "") {
    std::vector<std::string> argv{mbpoll, "-m", "tcp", "-a", "1", "-0", "-1", "-o", "2", "-p", port};
    argv.insert(argv.end(), args.begin(), args.end());
    argv.push_back("127.0.0.1");
    if (!write_value.empty()) argv.push_back(write_value);
    return test::run_command(argv, dir);
  };

  // Idle: identification through holding and input registers.
  auto r = poll({"-r", "0", "-c", "8", "-t", "4"});
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  auto v = values(r.out);
  EXPECT_EQ(v[0], 0x425A);
  EXPECT_EQ(v[1], kProtocolVersion);
  EXPECT_EQ(v[2], 256);
  EXPECT_EQ(v[3], kMaxChunkBytes);
  EXPECT_EQ(v[6], static_cast<int>(State::idle));
  r = poll({"-r", "0", "-c", "2", "-t", "3"});
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(values(r.out)[0], 0x425A);

  // During a transfer: the state, the session (a 32-bit value, high word
  // first: mbpoll -B) and the acknowledged bytes move as documented.
  std::promise<std::string> opened;
  bool signalled = false;
  StreamOptions opt;
  opt.on_event = [&](const std::string& e) {
    if (!signalled && e.rfind("transfer opened: session ", 0) == 0) {
      signalled = true;
      opened.set_value(e.substr(25, 8));
    }
  };
  const std::string program = test::zigzag_program(300);
  auto sender = std::async(std::launch::async, [&] { return stream_program(program, {"127.0.0.1", sim.port()}, opt); });
  const std::string session_hex = opened.get_future().get();
  r = poll({"-r", "4", "-c", "1", "-t", "4:int", "-B"});
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(static_cast<unsigned long>(values(r.out)[4]) & 0xFFFFFFFFul, std::stoul(session_hex, nullptr, 16)) << r.out;
  r = poll({"-r", "6", "-c", "1", "-t", "3"});
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(values(r.out)[6], static_cast<int>(State::receiving));
  // A write to the status registers: a standard "illegal data address".
  r = poll({"-r", "6", "-t", "4"}, "3");
  EXPECT_NE(r.status, 0);
  EXPECT_NE((r.out + r.err).find("Illegal data address"), std::string::npos) << r.out << r.err;

  const StreamResult res = sender.get();
  r = poll({"-r", "6", "-c", "1", "-t", "4"});
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(values(r.out)[6], static_cast<int>(State::done));
  r = poll({"-r", "16", "-c", "1", "-t", "4:int", "-B"});
  EXPECT_EQ(values(r.out)[16], static_cast<long long>(res.lines_executed));
  r = poll({"-r", "20", "-c", "1", "-t", "4:int", "-B"});
  EXPECT_EQ(static_cast<unsigned long>(values(r.out)[20]) & 0xFFFFFFFFul, res.crc);
  EXPECT_EQ(sim.stop(), 0);
}
