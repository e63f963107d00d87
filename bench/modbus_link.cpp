// Benchmark of the Modbus program link, printing its own table:
//  1. round-trip time of a status read and of a full-size chunk request on
//     loopback, and the transfer rate they allow: one request in flight,
//     228 payload bytes per request, so at most 228 B / RTT;
//  2. the sustained rate of streaming a large program to the simulated
//     controller (drip feed, executing while receiving) and its ratio to
//     that bound;
//  3. simulated execution speed in blocks per second (lines and arcs, with
//     and without the trace being formatted).
//
//   build/modbus_link [program-MiB]      (default 4)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <vector>

#include "bezcam/link/crc32.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/link/transport.hpp"
#include "bezcam/sim/sim_server.hpp"

using namespace bezcam;
using namespace bezcam::link;
using namespace bezcam::sim;
using Clock = std::chrono::steady_clock;

namespace {

double secs(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

std::string lines_program(std::size_t bytes) {
  std::string p = "%\nG21 G90 G17\nT1 M06\nS10000 M03\nG00 Z5.\nX0. Y0.\nG01 Z-1. F300.\n";
  char b[96];
  for (int i = 1; p.size() < bytes; ++i) {
    std::snprintf(b, sizeof b, "X%d.%03d Y%d.%03d F1000.\n", i % 97, (i * 37) % 1000, (i * 7) % 53, (i * 11) % 1000);
    p += b;
  }
  return p + "M05\nG00 Z5.\nM30\n%\n";
}

// Lines that cost the executor almost nothing per byte (a comment of 200
// characters each): the transfer, not the execution, sets the pace.
std::string comment_program(std::size_t bytes) {
  std::string p = "%\nG21 G90 G17\n";
  const std::string line = "(" + std::string(200, 'c') + ")\n";
  while (p.size() < bytes) p += line;
  return p + "M30\n%\n";
}

std::string arcs_program(int n) {
  // Full circles of radius 10 around (50, 50), as pairs of half arcs.
  std::string p = "%\nG21 G90 G17\nG00 Z5.\nX40. Y50.\nG01 Z-1. F300.\n";
  for (int i = 0; i < n / 2; ++i) p += "G02 X60. Y50. I10. J0. F800.\nG02 X40. Y50. I-10. J0.\n";
  return p + "G00 Z5.\nM30\n%\n";
}

struct Stats {
  double median, mean, p99;
};
Stats stats(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  double sum = 0;
  for (double x : v) sum += x;
  return {v[v.size() / 2], sum / static_cast<double>(v.size()), v[v.size() * 99 / 100]};
}

double exec_rate(const std::string& program, bool trace, long* blocks) {
  ControllerConfig cfg;
  cfg.profile = load_machine_profile("generic");
  cfg.buffer_bytes = kMaxBuffer;
  std::size_t traced = 0;
  if (trace) cfg.trace = [&traced](std::string_view t, bool) { traced += t.size(); };  // formatted, then dropped
  SimController ctl(cfg);
  const auto t0 = Clock::now();
  const Status s = ctl.run_program(program);
  const auto t1 = Clock::now();
  if (s.state != State::done) {
    std::fprintf(stderr, "execution failed: %s\n", ctl.alarm_text().c_str());
    std::exit(1);
  }
  *blocks = s.blocks_executed;
  return s.blocks_executed / secs(t0, t1);
}

}  // namespace

int main(int argc, char** argv) {
  const double mib = argc > 1 ? std::atof(argv[1]) : 4.0;
  const std::string program = lines_program(static_cast<std::size_t>(mib * 1024 * 1024));

  std::printf("bezcam Modbus link benchmark (loopback 127.0.0.1, server and client in one process)\n\n");

  // 1. Round trips.
  double rtt_full = 0, rtt_full_mean = 0;
  {
    ControllerConfig cfg;
    cfg.profile = load_machine_profile("generic");
    SimController ctl(cfg);
    ModbusServer server(ctl, ServerConfig{});
    server.start();
    ModbusClient c({"127.0.0.1", server.port()}, std::chrono::milliseconds(2000));
    std::array<std::uint16_t, reg::status_count> st{};
    std::vector<double> small, full;
    for (int i = 0; i < 200; ++i) c.read_holding(0, st);  // warm-up
    for (int i = 0; i < 3000; ++i) {
      const auto t0 = Clock::now();
      c.read_holding(0, st);
      small.push_back(secs(t0, Clock::now()));
    }
    // A full-size chunk request: an FC 23 writing 121 registers (228 payload
    // bytes) and reading the 48-register status back, as the sender does.
    // After the first, each is a retransmission: acknowledged, not applied,
    // so the controller's work per request is the protocol's alone.
    c.write_registers(reg::command, encode_command(Command::open, std::array<std::uint32_t, 2>{1, 0}));
    c.read_holding(0, st);
    const std::uint32_t session = get_u32(&st[reg::session]);
    const std::string payload(kMaxChunkBytes - 1, ' ');
    const auto regs = encode_chunk({session, 1, payload + "\n"});
    for (int i = 0; i < 200; ++i) c.write_and_read(reg::chunk, regs, 0, st);
    for (int i = 0; i < 3000; ++i) {
      const auto t0 = Clock::now();
      c.write_and_read(reg::chunk, regs, 0, st);
      full.push_back(secs(t0, Clock::now()));
    }
    server.stop();
    const Stats s = stats(small), f = stats(full);
    rtt_full = f.median;
    rtt_full_mean = f.mean;
    std::printf("Round trip (3000 requests each)            median     mean      p99\n");
    std::printf("  FC 03, 48 registers (12 + 105 bytes)   %7.1f us %7.1f us %7.1f us\n", s.median * 1e6, s.mean * 1e6,
                s.p99 * 1e6);
    std::printf("  FC 23, chunk of 228 B (259 + 105 bytes) %6.1f us %7.1f us %7.1f us\n\n", f.median * 1e6,
                f.mean * 1e6, f.p99 * 1e6);
  }
  // One chunk in flight at a time: at most 228 payload bytes per round trip.
  const double bound = kMaxChunkBytes / rtt_full, bound_mean = kMaxChunkBytes / rtt_full_mean;
  std::printf(
      "Bound on the transfer rate, 228 B per round trip: %.0f KiB/s at the median RTT, %.0f KiB/s at the mean\n\n",
      bound / 1024, bound_mean / 1024);

  // 2. Sustained transfer, executing while receiving.
  std::printf("Sustained transfer of %.1f MiB programs, executing while receiving (drip feed)\n", mib);
  std::printf(
      "  program                      buffer    time       rate    ratio to bound (median, mean RTT)  chunks  "
      "lines/s\n");
  const std::string comments = comment_program(program.size());
  for (const auto* prog : {&program, &comments})
    for (std::size_t buffer : {std::size_t{4096}, std::size_t{kMaxBuffer}}) {
      ControllerConfig cfg;
      cfg.profile = load_machine_profile("generic");
      cfg.buffer_bytes = buffer;
      SimController ctl(cfg);
      ModbusServer server(ctl, ServerConfig{});
      server.start();
      const auto t0 = Clock::now();
      const StreamResult r = stream_program(*prog, {"127.0.0.1", server.port()});
      const double t = secs(t0, Clock::now());
      server.stop();
      if (r.crc != crc32(*prog)) return 1;
      const double rate = static_cast<double>(r.bytes) / t;
      std::printf("  %-27s %6zu  %6.2f s  %6.0f KiB/s      %5.2f   %5.2f                   %6llu  %7.0f\n",
                  prog == &program ? "G01 lines (~24 B/line)" : "comment lines (203 B/line)", buffer, t, rate / 1024,
                  rate / bound, rate / bound_mean, static_cast<unsigned long long>(r.chunks), r.lines_executed / t);
    }

  // 2b. The link alone: a program that fits in an empty 64 KiB buffer, so
  // the buffer never holds the sender back; timed from the start to the
  // acknowledgement of the last byte (COMMIT and execution excluded). Once
  // with the executor running alongside (it competes for the CPU), once
  // with it paused on the first line (the protocol and sockets only).
  struct Acked {};  // thrown from the progress callback to stop at the last ack
  for (const bool paused : {false, true}) {
    const std::string small = lines_program(60000);
    std::vector<double> rates;
    std::uint64_t chunks = 0;
    for (int rep = 0; rep < 15; ++rep) {
      ControllerConfig cfg;
      cfg.profile = load_machine_profile("generic");
      cfg.buffer_bytes = kMaxBuffer;
      if (paused) cfg.exec_delay = std::chrono::milliseconds(100);
      SimController ctl(cfg);
      ModbusServer server(ctl, ServerConfig{});
      server.start();
      Clock::time_point t0 = Clock::now(), t_acked{};
      StreamOptions opt;
      opt.on_progress = [&](const StreamProgress& p) {
        chunks = p.bytes_acked == 0 ? 0 : chunks + 1;
        if (p.bytes_acked == p.bytes_total) {
          t_acked = Clock::now();
          throw Acked{};
        }
      };
      t0 = Clock::now();
      try {
        stream_program(small, {"127.0.0.1", server.port()}, opt);
      } catch (const Acked&) {
      }
      server.stop();
      rates.push_back(static_cast<double>(small.size()) / secs(t0, t_acked));
    }
    const Stats s = stats(rates);
    std::printf(
        "  %-27s %6zu  burst   %6.0f KiB/s      %5.2f   %5.2f                   %6llu   (%zu B, median of 15 runs, to "
        "the last ack)\n",
        paused ? "G01 lines, executor paused" : "G01 lines into empty buffer", std::size_t{kMaxBuffer}, s.median / 1024,
        s.median / bound, s.median / bound_mean, static_cast<unsigned long long>(chunks), small.size());
  }

  // 2c. At machine pace: short G01 blocks at the generic
  // profile's top feed and block rate (0.333 mm at 20000 mm/min: 1000 blocks
  // per second of machine time), streamed to a controller executing at K x
  // real time; the largest K with no stall, and the rate the sender kept up.
  {
    std::printf("\nAt machine pace: 0.333 mm G01 blocks at 20000 mm/min (1000 blocks/s, generic), 64 KiB buffer\n");
    std::printf("  time scale   lines   machine s   wall s   starved ms  stalls   rate KiB/s  ratio to bound\n");
    double best = 0;
    for (double k : {1.0, 10.0, 50.0, 100.0, 200.0, 400.0, 800.0}) {
      const int n = k <= 1 ? 1000 : static_cast<int>(std::min(200000.0, 2000 * k));
      std::string p = "G21 G90 G17\nG0 X0 Y0 Z0\nS10000 M3\nG1 F20000\n";
      double x = 0, y = 0;
      char b[64];
      for (int i = 0; i < n; ++i) {
        const double a = (i % 400) / 400.0 * 6.283185307179586;
        x += 0.3333 * std::cos(a);
        y += 0.3333 * std::sin(a);
        std::snprintf(b, sizeof b, "X%.4f Y%.4f\n", x, y);
        p += b;
      }
      p += "M30\n";
      ControllerConfig cfg;
      cfg.profile = load_machine_profile("generic");
      cfg.buffer_bytes = kMaxBuffer;
      cfg.time_scale = k;
      SimController ctl(cfg);
      ModbusServer server(ctl, ServerConfig{});
      server.start();
      const auto t0 = Clock::now();
      const StreamResult r = stream_program(p, {"127.0.0.1", server.port()});
      const double t = secs(t0, Clock::now());
      server.stop();
      const double rate = static_cast<double>(r.bytes) / t;
      std::printf("  %9.0f x %7d   %9.2f   %6.2f   %10u  %6u   %10.0f   %5.2f\n", k, n, t * k, t, r.starved_ms,
                  r.stalls, rate / 1024, rate / bound);
      if (r.starved_ms == 0)
        best = k;
      else
        break;
    }
    std::printf("  largest time scale with no stall: %.0f x real time\n", best);
  }

  // 3. Execution speed.
  std::printf("\nSimulated execution (run_program, no network)\n");
  std::printf("  program                         blocks      blocks/s\n");
  long blocks = 0;
  const std::string lines = lines_program(8 * 1024 * 1024);
  double r = exec_rate(lines, false, &blocks);
  std::printf("  G01 lines, no trace          %9ld   %11.0f\n", blocks, r);
  r = exec_rate(lines, true, &blocks);
  std::printf("  G01 lines, trace formatted   %9ld   %11.0f\n", blocks, r);
  const std::string arcs = arcs_program(40000);
  r = exec_rate(arcs, false, &blocks);
  std::printf("  G02 arcs, no trace           %9ld   %11.0f\n", blocks, r);
  r = exec_rate(arcs, true, &blocks);
  std::printf("  G02 arcs, trace (31 samples) %9ld   %11.0f\n", blocks, r);
  return 0;
}
