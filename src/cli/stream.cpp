// bezcam stream FILE.nc --to HOST:PORT [--timeout S] [--retries N] [--retry-time S]
//                [--stall-timeout S] [--chunk BYTES] [--progress auto|bar|lines|off] [-q]
//                [--from-line N [--safe-z MM] [--plunge-feed MM/MIN]]
//
// Sends a program to a controller over Modbus TCP (streamer.hpp), with a
// progress bar on a terminal and plain progress lines otherwise. Exit
// status per docs/cli.md: 0 the controller confirmed and executed the whole
// program, 2 bad file or options, 3 connection failure, 4 the controller
// refused or lost the program.
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "bezcam/gcode/lint.hpp"
#include "bezcam/limits.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "commands.hpp"
#include "exit_status.hpp"
#include "profiles.hpp"
#include "progress.hpp"
#include "validators.hpp"

namespace bezcam::cli {

using namespace bezcam::link;

CLI::App* setup_stream(CLI::App& app, StreamArgs& o) {
  auto* s = app.add_subcommand("stream",
                               "Send a G-code program to a controller over Modbus TCP, with progress; "
                               "succeeds only when the controller confirms the CRC-32 and has executed it.");
  s->add_option("FILE", o.file, "G-code program (not with --abort)");
  s->add_option("--to", o.to, "controller address HOST:PORT")->required();
  s->add_flag("--abort", o.abort,
              "stop the transfer the controller holds, whoever sent it (the operator's stop: "
              "alarm \"aborted\", spindle off), and print its state");
  s->add_flag("--no-preflight", o.no_preflight,
              "send without first linting the program against the profile the controller enforces");
  s->add_option("--timeout", o.timeout, "seconds to wait for each reply before taking the connection as lost")
      ->check(positive_number());
  s->add_option("--retries", o.retries, "reconnection attempts after a lost connection")->check(CLI::Range(0, 1000));
  s->add_option("--retry-time", o.retry_time, "seconds spent at most reconnecting after one loss")
      ->check(positive_number());
  s->add_option("--stall-timeout", o.stall_timeout,
                "seconds the controller may take no byte and execute no line before giving up")
      ->check(positive_number());
  s->add_option("--chunk", o.chunk, "payload bytes per request (default: the controller's maximum)")
      ->check(CLI::Range(1, static_cast<int>(kMaxChunkBytes)));
  s->add_option("--progress", o.progress, "auto (a bar on a terminal, plain lines otherwise), bar, lines or off")
      ->check(CLI::IsMember({"auto", "bar", "lines", "off"}));
  s->add_flag("-q,--quiet", o.quiet, "print nothing but errors");
  add_resume_options(s, o.resume);
  s->get_option("--abort")->excludes("--from-line");
  s->footer(
      "Ctrl-C (or SIGTERM) stops the controller at once: the sender sends ABORT and says what was "
      "acknowledged and executed (exit 130).\n"
      "Before sending, the program is linted against the profile the controller enforces (its name is in "
      "the controller's registers); findings refuse it (exit 2) unless --no-preflight.\n"
      "With --from-line N the program is resumed part-way (docs/resume.md): from the nearest line at or "
      "before N where a cut may begin, after a preamble built for the profile the controller enforces.\n\n"
      "Examples:\n"
      "  bezcam stream part.nc --to 127.0.0.1:5020\n"
      "  bezcam stream part.nc --to 127.0.0.1:5020 --from-line 120\n"
      "  bezcam stream --abort --to 192.168.0.10:502");
  return s;
}

namespace {

std::string human_bytes(double b) {
  char buf[32];
  if (b < 1024)
    std::snprintf(buf, sizeof buf, "%.0f B", b);
  else if (b < 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.1f KiB", b / 1024);
  else
    std::snprintf(buf, sizeof buf, "%.1f MiB", b / (1024 * 1024));
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

std::chrono::milliseconds ms(double seconds) {
  return std::chrono::milliseconds(static_cast<long long>(seconds * 1000.0 + 0.5));
}

// Set by SIGINT / SIGTERM; the sender checks it between requests.
std::atomic<bool> g_interrupted{false};
extern "C" void on_interrupt(int) { g_interrupted.store(true); }

// One run of the command: its arguments and, with --from-line, the resume
// planned for the controller.
struct Sender {
  const StreamArgs& o;
  Resume resume;

  int run();
  std::string finding_place(long line) const;
  void preflight(const std::string& program, const Endpoint& to) const;
  std::string resume_for_controller(std::string program, const Endpoint& to);
  std::string where_to_resume(const std::string& file_text, const Endpoint& to) const;
  [[noreturn]] void throw_in_file_lines(const Error& e, const std::string& more) const;
};

// Where a finding is: FILE:LINE, the file's own line for a resumed program
// (a preamble line is named as such).
std::string Sender::finding_place(long line) const {
  const Place p = resume.place_of(line);
  return p.file == Resume::kPreamble ? p.to_string() : o.file + ":" + std::to_string(*p.line);
}

// The program against the profile the controller enforces: a program it
// would refuse mid-cut is refused before OPEN.
void Sender::preflight(const std::string& program, const Endpoint& to) const {
  const ControllerReport r = controller_status(to, ms(o.timeout));
  if (r.machine.empty()) return;
  MachineProfile m;
  try {
    m = load_profile_option(r.machine);
  } catch (const Error&) {
    if (!o.quiet)
      std::cerr << "bezcam: warning: the controller enforces profile \"" << r.machine
                << "\", which is not known here: the program was not linted before sending\n";
    return;
  }
  const auto findings = lint_gcode(program, m);
  if (findings.empty()) return;
  std::string list;
  for (size_t i = 0; i < findings.size() && i < 10; ++i)
    list += "\n  " + finding_place(findings[i].line) + ": " + findings[i].message + " [" + findings[i].id + "]";
  if (findings.size() > 10) list += "\n  ... and " + std::to_string(findings.size() - 10) + " more";
  throw InputError(
      errc::link_preflight, Place::at_file(o.file),
      std::to_string(findings.size()) + " finding" + (findings.size() == 1 ? "" : "s") + " for machine \"" + m.name +
          "\", the profile the controller at " + to.str() +
          " enforces; it would stop the program mid-cut. Nothing was sent (--no-preflight sends anyway):" + list);
}

// The profile a controller enforces, when it is known here.
std::optional<MachineProfile> controller_profile(const ControllerReport& r) {
  try {
    if (!r.machine.empty()) return load_profile_option(r.machine);
  } catch (const Error&) {
  }
  return std::nullopt;
}

// --from-line: the resume is planned for the profile the controller
// enforces (its dialect, travel and feed limits, safe Z and plunge feed).
std::string Sender::resume_for_controller(std::string program, const Endpoint& to) {
  const ControllerReport r = controller_status(to, ms(o.timeout));
  const std::optional<MachineProfile> m = controller_profile(r);
  if (!m && !o.quiet)
    std::cerr << "bezcam: warning: the controller enforces profile \"" << r.machine
              << "\", which is not known here: the resume is planned without its limits (give --safe-z and "
                 "--plunge-feed)\n";
  return resume.apply(std::move(program), o.file, m ? &*m : nullptr, o.quiet, "stream");
}

// The controller stopped the program mid-way (Ctrl-C here, an operator's
// stop, a lost sender): where the machine stopped, in the file's
// numbering, and the --from-line that goes on from there: the first line
// after the last one the machine finished that holds a block. "" when the
// controller does not say it stopped so.
std::string Sender::where_to_resume(const std::string& file_text, const Endpoint& to) const {
  ControllerReport r;
  try {
    r = controller_status(to, ms(o.timeout));
  } catch (const Error&) {
    return {};  // the controller cannot say where it stopped
  }
  if (r.status.state != State::alarm || (r.status.alarm != Alarm::aborted && r.status.alarm != Alarm::sender_lost))
    return {};
  const long executed = r.status.lines_executed;
  long next = executed + 1;  // in the file's numbering
  std::string where = "the machine stopped after line " + std::to_string(executed) + " of " + o.file;
  if (const auto& plan = resume.plan()) {
    if (executed <= plan->preamble_lines) {
      next = plan->start_line;
      where = "the machine stopped in the resume preamble, before line " + std::to_string(next) + " of " + o.file;
    } else {
      next = plan->original_line(executed) + 1;
      where = "the machine stopped after line " + std::to_string(next - 1) + " of " + o.file;
    }
  }
  const std::optional<MachineProfile> m = controller_profile(r);
  const long total = static_cast<long>(std::count(file_text.begin(), file_text.end(), '\n')) +
                     (file_text.empty() || file_text.back() == '\n' ? 0 : 1);
  const auto resume_at = [&](long n) {
    return where + "; resume with --from-line " + std::to_string(n) + " (bezcam stream " + o.file + " --to " +
           to.str() + " --from-line " + std::to_string(n) + ")";
  };
  // Lines without a block (comments, blanks) cannot begin a resume: the
  // next one that can is named, as the resume would plan it.
  for (long n = next; n <= total; ++n) {
    if (!m) return resume_at(n);
    try {
      plan_resume(file_text, &*m, static_cast<int>(n));
    } catch (const InputError& e) {
      if (e.id() == errc::resume_no_code) continue;
      if (e.id() == errc::resume_after_end) break;
      // The safe height and plunge feed are the resume's to give: the line is good.
      if (e.id() != errc::resume_setting)
        return where + "; it cannot be resumed from line " + std::to_string(n) + ": " + e.message();
    }
    return resume_at(n);
  }
  return where + "; no block of the program is left to run";
}

// A resumed program's alarm names the line of the file, not of the program
// sent; `more` is added to the message.
[[noreturn]] void Sender::throw_in_file_lines(const Error& e, const std::string& more) const {
  const std::string message = more.empty() ? e.message() : e.message() + "; " + more;
  if (const auto& line = e.place().line; resume.plan() && e.id() == errc::controller_alarm && line && *line > 0)
    throw ControllerError(e.id(), resume.place_of(static_cast<long>(*line)), message);
  if (!more.empty()) throw ControllerError(e.id(), e.place(), message);
  throw;  // called inside the handler: the error as caught
}

int Sender::run() {
  const Endpoint to = parse_endpoint(o.to);
  if (o.abort) {
    if (!o.file.empty()) throw InputError(errc::usage_stream, Place::at_option("--abort"), "takes no program file");
    const ControllerReport before = controller_status(to, ms(o.timeout));
    const ControllerReport after = abort_controller(to, ms(o.timeout));
    if (!o.quiet)
      std::cerr << "bezcam: stream: "
                << (before.status.state == State::receiving || before.status.state == State::finishing
                        ? "stopped the transfer (session " + std::to_string(before.status.session) + ")"
                        : std::string("no transfer was open: nothing to stop"))
                << "\n";
    print_controller(after, to);
    return 0;
  }
  if (o.file.empty())
    throw InputError(errc::usage_stream, Place::at_option("FILE"), "give the program to send (or --abort)");
  const std::string file_text = read_bounded(o.file, kMaxProgramBytes, "program file");
  std::string program = file_text;
  if (resume.active()) program = resume_for_controller(std::move(program), to);
  if (!o.no_preflight) preflight(program, to);
  Display::Style style = Display::Style::lines;
  if (o.quiet || o.progress == "off")
    style = Display::Style::off;
  else if (o.progress == "bar" || (o.progress == "auto" && stderr_is_tty()))
    style = Display::Style::bar;
  Display display(style);

  StreamOptions opt;
  opt.timeout = ms(o.timeout);
  opt.retries = o.retries;
  opt.retry_time = ms(o.retry_time);
  opt.stall_timeout = ms(o.stall_timeout);
  opt.chunk_bytes = static_cast<std::uint16_t>(o.chunk);
  opt.on_progress = [&](const StreamProgress& p) { display.update(p); };
  opt.on_event = [&](const std::string& e) { display.event(e); };
  opt.cancel = &g_interrupted;
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;  // no SA_RESTART: a blocked call returns
  sigemptyset(&sa.sa_mask);
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
  StreamResult r;
  try {
    r = stream_program(program, to, opt);
  } catch (const Error& e) {
    display.clear();
    if (e.id() != errc::link_cancelled)
      throw_in_file_lines(e, e.id() == errc::controller_alarm ? where_to_resume(file_text, to) : std::string());
    std::cerr << "bezcam: stream: " << e.what() << "\n";
    if (const std::string where = where_to_resume(file_text, to); !where.empty())
      std::cerr << "bezcam: stream: " << where << "\n";
    return 130;  // as a shell reports a program stopped by Ctrl-C
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
    std::cerr << "bezcam: stream: sent " << o.file
              << (resume.plan() ? " from line " + std::to_string(resume.plan()->start_line) + " with a " +
                                      std::to_string(resume.plan()->preamble_lines) + "-line preamble"
                                : std::string())
              << " (" << r.bytes << " bytes, " << r.lines << " lines, " << r.chunks << " chunks) to " << to.str()
              << " in " << rate << "; the controller confirmed CRC-32 " << crc << " and executed " << r.lines_executed
              << " lines (" << r.blocks_executed << " motion blocks)"
              << (r.reconnects ? "; " + std::to_string(r.reconnects) + " reconnections" : std::string()) << "; starved "
              << r.starved_ms << " ms"
              << (r.stalls ? " (" + std::to_string(r.stalls) + (r.stalls == 1 ? " stall)" : " stalls)") : std::string())
              << "\n";
  }
  return 0;
}

}  // namespace

int run_stream(const StreamArgs& o) {
  Sender sender{o, Resume(o.resume)};
  return sender.run();
}

}  // namespace bezcam::cli
