// bezcam stream FILE.nc --to HOST:PORT [--timeout S] [--retries N] [--retry-time S]
//                [--stall-timeout S] [--chunk BYTES] [--progress auto|bar|lines|off] [-q]
//
// Sends a program to a controller over Modbus TCP (streamer.hpp), with a
// progress bar on a terminal and plain progress lines otherwise. Exit
// status per docs/cli.md: 0 the controller confirmed and executed the whole
// program, 2 bad file or options, 3 connection failure, 4 the controller
// refused or lost the program.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "bezcam/limits.hpp"
#include "bezcam/link/streamer.hpp"
#include "command.hpp"

namespace bezcam::cli {
namespace {

using namespace bezcam::link;

struct Options {
  std::string file, to, progress = "auto";
  double timeout = 2, retry_time = 20, stall_timeout = 60;
  int retries = 5;
  int chunk = 0;
  bool quiet = false;
} o;

CLI::App* add(CLI::App& app) {
  auto* s = app.add_subcommand("stream", "Send a G-code program to a controller over Modbus TCP, with progress; "
                                         "succeeds only when the controller confirms the CRC-32 and has executed it.");
  s->add_option("FILE", o.file, "G-code program")->required();
  s->add_option("--to", o.to, "controller address HOST:PORT")->required();
  s->add_option("--timeout", o.timeout, "seconds to wait for each reply before taking the connection as lost")
      ->check(CLI::PositiveNumber);
  s->add_option("--retries", o.retries, "reconnection attempts after a lost connection")->check(CLI::Range(0, 1000));
  s->add_option("--retry-time", o.retry_time, "seconds spent at most reconnecting after one loss")
      ->check(CLI::PositiveNumber);
  s->add_option("--stall-timeout", o.stall_timeout,
                "seconds the controller may take no byte and execute no line before giving up")
      ->check(CLI::PositiveNumber);
  s->add_option("--chunk", o.chunk, "payload bytes per request (default: the controller's maximum)")
      ->check(CLI::Range(1, static_cast<int>(kMaxChunkBytes)));
  s->add_option("--progress", o.progress, "auto (a bar on a terminal, plain lines otherwise), bar, lines or off")
      ->check(CLI::IsMember({"auto", "bar", "lines", "off"}));
  s->add_flag("-q,--quiet", o.quiet, "print nothing but errors");
  return s;
}

std::string human_bytes(double b) {
  char buf[32];
  if (b < 1024) std::snprintf(buf, sizeof buf, "%.0f B", b);
  else if (b < 1024 * 1024) std::snprintf(buf, sizeof buf, "%.1f KiB", b / 1024);
  else std::snprintf(buf, sizeof buf, "%.1f MiB", b / (1024 * 1024));
  return buf;
}

// Draws progress on stderr: a bar redrawn in place on a terminal (at most
// ten times a second), plain lines in logs and pipes (at most every 2 s).
class Display {
 public:
  enum class Style { bar, lines, off };
  explicit Display(Style s) : style_(s) {}

  void update(const StreamProgress& p, bool force = false) {
    last_ = p;
    have_ = true;
    if (style_ == Style::off) return;
    const auto now = std::chrono::steady_clock::now();
    const double since = std::chrono::duration<double>(now - drawn_).count();
    if (!force && since < (style_ == Style::bar ? 0.1 : 2.0)) return;
    drawn_ = now;
    if (style_ == Style::bar) {
      const std::string line = bar(p);
      std::cerr << "\r" << line << std::string(width_ > line.size() ? width_ - line.size() : 0, ' ') << std::flush;
      width_ = line.size();
    } else {
      std::cerr << "bezcam: stream: " << plain(p) << "\n";
    }
  }
  void event(const std::string& s) {
    if (style_ == Style::off) return;
    clear();
    std::cerr << "bezcam: stream: " << s << "\n";
  }
  void clear() {
    if (style_ == Style::bar && width_ > 0) std::cerr << "\r" << std::string(width_, ' ') << "\r" << std::flush;
    width_ = 0;
  }
  void finish() {
    if (!have_ || style_ == Style::off) return;
    update(last_, true);
    if (style_ == Style::bar) std::cerr << "\n";
    width_ = 0;
  }

 private:
  static double pct(const StreamProgress& p) {
    return p.bytes_total ? 100.0 * static_cast<double>(p.bytes_acked) / static_cast<double>(p.bytes_total) : 0;
  }
  static std::string state(const StreamProgress& p) {
    std::string s = std::string(to_string(p.state)) + ", " + std::to_string(p.lines_executed) + " executed";
    if (p.waiting) s += ", buffer full";
    if (p.reconnects) s += ", " + std::to_string(p.reconnects) + " reconnect" + (p.reconnects == 1 ? "" : "s");
    return s;
  }
  static std::string bar(const StreamProgress& p) {
    constexpr int kWidth = 20;
    const int filled = static_cast<int>(pct(p) / 100.0 * kWidth);
    char head[160];
    std::snprintf(head, sizeof head, "stream [%s%s] %3.0f%%  %s/%s  %llu/%llu lines  %s/s  ",
                  std::string(static_cast<std::size_t>(filled), '#').c_str(),
                  std::string(static_cast<std::size_t>(kWidth - filled), '.').c_str(), pct(p),
                  human_bytes(static_cast<double>(p.bytes_acked)).c_str(),
                  human_bytes(static_cast<double>(p.bytes_total)).c_str(),
                  static_cast<unsigned long long>(p.lines_acked), static_cast<unsigned long long>(p.lines_total),
                  human_bytes(p.rate).c_str());
    return head + state(p);
  }
  static std::string plain(const StreamProgress& p) {
    char head[160];
    std::snprintf(head, sizeof head, "%.0f%% (%llu/%llu bytes, %llu/%llu lines), %s/s, controller ", pct(p),
                  static_cast<unsigned long long>(p.bytes_acked), static_cast<unsigned long long>(p.bytes_total),
                  static_cast<unsigned long long>(p.lines_acked), static_cast<unsigned long long>(p.lines_total),
                  human_bytes(p.rate).c_str());
    return head + state(p);
  }

  Style style_;
  StreamProgress last_;
  bool have_ = false;
  std::size_t width_ = 0;
  std::chrono::steady_clock::time_point drawn_{};
};

// At most kMaxProgramBytes, refused before it is read (limits.hpp).
std::string read_file(const std::string& path) { return read_bounded(path, kMaxProgramBytes, "program file"); }

std::chrono::milliseconds ms(double seconds) {
  return std::chrono::milliseconds(static_cast<long long>(seconds * 1000.0 + 0.5));
}

int run() {
  const Endpoint to = parse_endpoint(o.to);
  const std::string program = read_file(o.file);
  Display::Style style = Display::Style::lines;
  if (o.quiet || o.progress == "off") style = Display::Style::off;
  else if (o.progress == "bar" || (o.progress == "auto" && stderr_is_tty())) style = Display::Style::bar;
  Display display(style);

  StreamOptions opt;
  opt.timeout = ms(o.timeout);
  opt.retries = o.retries;
  opt.retry_time = ms(o.retry_time);
  opt.stall_timeout = ms(o.stall_timeout);
  opt.chunk_bytes = static_cast<std::uint16_t>(o.chunk);
  opt.on_progress = [&](const StreamProgress& p) { display.update(p); };
  opt.on_event = [&](const std::string& e) { display.event(e); };
  StreamResult r;
  try {
    r = stream_program(program, to, opt);
  } catch (...) {
    display.clear();
    throw;
  }
  display.finish();
  if (!o.quiet) {
    char rate[64];
    std::snprintf(rate, sizeof rate, "%.2f s (%s/s)", r.seconds,
                  human_bytes(r.seconds > 0 ? static_cast<double>(r.bytes) / r.seconds : 0).c_str());
    char crc[16];
    std::snprintf(crc, sizeof crc, "%08X", r.crc);
    std::cerr << "bezcam: stream: sent " << o.file << " (" << r.bytes << " bytes, " << r.lines << " lines, "
              << r.chunks << " chunks) to " << to.str() << " in " << rate << "; the controller confirmed CRC-32 "
              << crc << " and executed " << r.lines_executed << " lines (" << r.blocks_executed << " motion blocks)"
              << (r.reconnects ? "; " + std::to_string(r.reconnects) + " reconnections" : std::string()) << "\n";
  }
  return 0;
}

Command cmd{"stream", add, run};
RegisterCommand registration(&cmd);

}  // namespace
}  // namespace bezcam::cli
