// bezcam simulate --listen HOST:PORT [--machine NAME|FILE] [--trace FILE] [limits, faults]
// bezcam simulate --program FILE.nc [--machine NAME|FILE] [--trace FILE]
// either with [--stock BOX [--cell C] [--memory-limit SIZE]]: the stock cut
//
// The simulated controller's front end: the same SimController either
// behind a Modbus TCP server or fed a file directly. SIGINT and SIGTERM stop
// it cleanly: the executor finishes the line in progress (at machine pace
// the machine stops where it is) and the trace is flushed before the
// process exits.
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <pthread.h>
#include <signal.h>
#include <sstream>

#include "bezcam/error.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/job/tool_table.hpp"
#include "bezcam/limits.hpp"
#include "bezcam/link/transport.hpp"
#include "bezcam/report/motion_report.hpp"
#include "bezcam/sim/sim_controller.hpp"
#include "bezcam/sim/sim_server.hpp"
#include "bezcam/sim/trace.hpp"
#include "commands.hpp"
#include "exit_status.hpp"
#include "output_file.hpp"
#include "profiles.hpp"
#include "stock_options.hpp"
#include "validators.hpp"

namespace bezcam::cli {
namespace {

// The id of a run that the simulated controller stopped: `sim.` and the alarm's name.
ErrorId alarm_error_id(link::Alarm a) {
  switch (a) {
    case link::Alarm::travel_limit: return errc::sim_travel_limit;
    case link::Alarm::feed_limit: return errc::sim_feed_limit;
    case link::Alarm::line_too_long: return errc::sim_line_too_long;
    case link::Alarm::crc_mismatch: return errc::sim_crc_mismatch;
    case link::Alarm::length_mismatch: return errc::sim_length_mismatch;
    case link::Alarm::incomplete: return errc::sim_incomplete;
    case link::Alarm::sender_lost: return errc::sim_sender_lost;
    case link::Alarm::aborted: return errc::sim_aborted;
    case link::Alarm::none:
    case link::Alarm::gcode: break;
  }
  return errc::sim_gcode;
}

}  // namespace

using namespace bezcam::link;
using namespace bezcam::sim;

CLI::App* setup_simulate(CLI::App& app, SimulateArgs& o) {
  auto* s = app.add_subcommand("simulate",
                               "Run the simulated controller: a Modbus TCP server that accepts programs "
                               "(--listen) or a program file executed directly (--program).");
  auto* l = s->add_option("--listen", o.listen, "HOST:PORT to listen on (port 0: a free port, printed on stdout)");
  auto* p = s->add_option("--program", o.program, "G-code file to execute directly, no network");
  l->excludes(p);
  p->excludes(l);
  add_resume_options(s, o.resume);
  l->excludes("--from-line");
  s->add_option("--machine", o.machine,
                "machine profile: travel limits, maximum feed and motion model (default generic)");
  add_tool_diameter_option(s, o.tool_diameters);
  auto* rep = s->add_option("--report", o.report,
                            "with --program: plan the motion on the machine's motion model and write its report "
                            "(cycle time, achieved feed, starved blocks, path deviation, per block) as JSON");
  auto* mot = s->add_option("--motion", o.motion,
                            "with --program: write the planned motion, one row per period: t x y z feed (TSV)");
  rep->needs(p);
  mot->needs(p);
  auto* stock = s->add_option("--stock", o.stock,
                              "cut a stock box x0,y0,z0,x1,y1,z1 in mm as the programs execute (kept from program "
                              "to program); each program's trace ends with its hash, removed volume and deepest "
                              "floor. Tool Tn is a flat end mill of register Dn's diameter");
  s->add_option("--cell", o.cell, "with --stock: cell size in mm (default: 0.01, at most 4 million columns)")
      ->check(positive_number())
      ->needs(stock);
  s->add_option("--memory-limit", o.memory_limit, "with --stock: largest grid, e.g. 512MiB (default 1GiB)")
      ->needs(stock);
  s->add_option("--tools", o.tools,
                "with --stock: tools table (JSON, lengths in mm) giving each T number's shape, over the "
                "flat end mills of the D registers")
      ->needs(stock);
  s->add_option("--trace", o.trace, "write the trace here (\"-\" for stdout); restarted for each program");
  s->add_option("--buffer", o.buffer, "receive buffer in bytes")->check(CLI::Range(kMinBuffer, kMaxBuffer));
  s->add_option("--max-connections", o.max_connections, "simultaneous Modbus connections")->check(CLI::Range(2, 64));
  s->add_option("--idle-timeout", o.idle_timeout, "close a connection silent this many seconds")
      ->check(positive_number());
  s->add_option("--session-timeout", o.session_timeout,
                "stop a transfer whose sender is silent this many seconds (alarm sender-lost)")
      ->check(positive_number());
  s->add_option("--time-scale", o.time_scale,
                "with --listen: execute at machine pace on the profile's motion model, at this multiple of real time "
                "(0.01 to 100000; default 1, real time), or 'max': as fast as the CPU allows")
      ->needs(l);
  s->add_option("--exec-delay-ms", o.exec_delay_ms, "time spent per program line: a slow controller")
      ->check(CLI::NonNegativeNumber);
  s->add_option("--fault", o.faults,
                "fault injection for tests: drop-before:N or drop-after:N drops the connection at the N-th chunk "
                "write, before or after applying it; corrupt:N alters a digit of the N-th chunk once it is "
                "accepted (repeatable)");
  s->add_option("--session-base", o.session_base, "first session id (tests and documentation; default random)");
  s->add_flag("-q,--quiet", o.quiet,
              "print nothing but the listening line and errors (no log of connections, programs and alarms)");
  return s;
}

namespace {

// Writes the trace to a file as it is produced; each piece is flushed so the
// file is complete whenever the controller reports DONE.
class FileSink {
 public:
  explicit FileSink(std::string path) : path_(std::move(path)) {}
  ~FileSink() {
    if (f_ && f_ != stdout) std::fclose(f_);
  }
  void operator()(std::string_view text, bool restart) {
    if (restart && path_ != "-") {
      if (f_) std::fclose(f_);
      f_ = std::fopen(path_.c_str(), "w");
      if (!f_) std::cerr << "bezcam: error: " << path_ << ": cannot write the trace\n";
    } else if (!f_ && path_ == "-") {
      f_ = stdout;
    }
    if (!f_) return;
    std::fwrite(text.data(), 1, text.size(), f_);
    std::fflush(f_);
  }

 private:
  std::string path_;
  std::FILE* f_ = nullptr;
};

std::vector<std::uint64_t> parse_faults(const std::vector<std::string>& faults, const std::string& kind) {
  std::vector<std::uint64_t> out;
  for (const auto& f : faults) {
    const auto colon = f.find(':');
    const std::string k = f.substr(0, colon);
    // The place is the --fault value as given: which of them is wrong.
    if (k != "drop-before" && k != "drop-after" && k != "corrupt")
      throw InputError(errc::sim_fault, Place::at_option(f), "expected drop-before:N, drop-after:N or corrupt:N");
    std::uint64_t n = 0;
    try {
      n = std::stoull(colon == std::string::npos ? "" : f.substr(colon + 1));
    } catch (const std::exception&) {
      throw InputError(errc::sim_fault, Place::at_option(f),
                       "expected a chunk count after the colon, such as drop-after:5");
    }
    if (k == kind) out.push_back(n);
  }
  return out;
}

// SIGINT and SIGTERM are blocked in every thread and taken by one waiting
// thread, so that stopping happens in ordinary code, not in a handler.
class SignalWaiter {
 public:
  SignalWaiter() {
    sigemptyset(&set_);
    sigaddset(&set_, SIGINT);
    sigaddset(&set_, SIGTERM);
    sigaddset(&set_, SIGUSR1);  // internal: "stop waiting"
    pthread_sigmask(SIG_BLOCK, &set_, nullptr);
  }
  template <class F>
  void start(F on_signal) {
    th_ = std::thread([this, on_signal] {
      int sig = 0;
      sigwait(&set_, &sig);
      if (sig != SIGUSR1) {
        signal_ = sig;
        on_signal();
      }
    });
  }
  ~SignalWaiter() { finish(); }
  /// Ends the waiting thread (whether or not a signal came) and waits for
  /// it, so that nothing it calls outlives the objects it calls.
  void finish() {
    if (th_.joinable()) {
      if (signal_ == 0) pthread_kill(th_.native_handle(), SIGUSR1);
      th_.join();
    }
  }
  int signal() const { return signal_; }

 private:
  sigset_t set_;
  std::thread th_;
  std::atomic<int> signal_{0};
};

// The planned motion of a program the controller executed (so the program
// is known to be valid): its report and samples.
void plan_and_write(const SimulateArgs& o, const MachineProfile& profile, const std::string& program) {
  const MotionPlan plan = plan_motion(read_timeline(program, &profile), *profile.motion);
  if (!o.report.empty()) write_output(o.report, motion_report_json(plan, o.program, profile.name));
  if (!o.motion.empty()) write_output(o.motion, motion_samples_tsv(plan));
  if (!o.quiet) std::cerr << motion_summary_text(plan, o.program + " on " + profile.name);
}

// --stock, --cell, --memory-limit: refused here, before any work, naming
// the option, as verify refuses them.
std::optional<StockConfig> stock_config(const SimulateArgs& o, const MachineProfile& m) {
  if (o.stock.empty()) return std::nullopt;
  StockConfig s;
  s.options.memory_limit = parse_memory_limit(o.memory_limit);
  s.box = parse_stock_box(o.stock);
  try {
    (void)stock_grid_size(s.box, 1);
  } catch (const Error& e) {
    throw stock_option_error(e);
  }
  s.cell = o.cell > 0 ? o.cell : default_stock_cell(s.box, kDefaultToleranceMm);
  s.tools = profile_stock_tools(m);
  if (!o.tools.empty())
    for (auto& [n, t] : stock_tools(read_tool_table_file(o.tools))) s.tools.insert_or_assign(n, t);
  return s;
}

}  // namespace

int run_simulate(const SimulateArgs& o) {
  if (o.listen.empty() && o.program.empty())
    throw InputError(errc::sim_usage, Place::at_option("simulate"), "give --listen HOST:PORT or --program FILE.nc");
  ControllerConfig cfg;
  cfg.profile = load_profile_option(o.machine);
  apply_tool_diameters(cfg.profile, o.tool_diameters);
  cfg.stock = stock_config(o, cfg.profile);
  cfg.buffer_bytes = o.buffer;
  cfg.session_timeout = std::chrono::milliseconds(static_cast<long long>(o.session_timeout * 1000));
  cfg.exec_delay = std::chrono::microseconds(static_cast<long long>(o.exec_delay_ms * 1000));
  if (!o.listen.empty()) {
    if (o.time_scale != "max") {
      double k = 0;
      try {
        std::size_t used = 0;
        k = std::stod(o.time_scale, &used);
        if (used != o.time_scale.size()) k = -1;
      } catch (const std::exception&) {
        k = -1;
      }
      if (!(k >= 0.01 && k <= 100000))
        throw InputError(
            errc::usage_option, Place::at_option("--time-scale"),
            "expected a multiple of real time from 0.01 to 100000, or max; found \"" + o.time_scale + "\"");
      if (!cfg.profile.motion)
        throw InputError(errc::sim_no_motion_model, Place::at_option("--machine"),
                         "machine \"" + cfg.profile.name +
                             "\" has no motion model (key \"motion\", docs/machines.md) to "
                             "execute at machine pace; add one, or give --time-scale max");
      cfg.time_scale = k;
    }
  }
  cfg.first_session = o.session_base;
  cfg.drop_before_chunk = parse_faults(o.faults, "drop-before");
  cfg.drop_after_chunk = parse_faults(o.faults, "drop-after");
  cfg.corrupt_chunk = parse_faults(o.faults, "corrupt");
  std::shared_ptr<FileSink> sink;
  if (!o.trace.empty()) {
    sink = std::make_shared<FileSink>(o.trace);
    cfg.trace = [sink](std::string_view t, bool restart) { (*sink)(t, restart); };
  }
  if (!o.listen.empty() && !o.quiet) {
    // The operator's log: what happens to the controller, with the time.
    cfg.on_event = [](const std::string& event) {
      const std::time_t now = std::time(nullptr);
      char t[16];
      std::strftime(t, sizeof t, "%H:%M:%S", std::localtime(&now));
      std::cerr << "bezcam simulate: " << t << " " << event << std::endl;
    };
  }
  const MachineProfile profile = cfg.profile;
  if ((!o.report.empty() || !o.motion.empty()) && !profile.motion)
    throw InputError(errc::sim_no_motion_model, Place::at_option("--machine"),
                     "machine \"" + profile.name +
                         "\" has no motion model (key \"motion\", docs/machines.md): "
                         "add one to plan its motion");
  if (!o.report.empty() && o.report == o.motion)
    throw InputError(errc::usage_report, Place::at_option("--report"),
                     "the report and the motion samples cannot go to the same file");
  Resume resume(o.resume);
  const std::string program = o.program.empty()
                                  ? std::string()
                                  : resume.apply(read_bounded(o.program, kMaxProgramBytes, "program file"), o.program,
                                                 &cfg.profile, o.quiet, "simulate");
  SignalWaiter signals;  // before any thread exists, so that all inherit the mask
  // The stock's grid is checked against the memory limit before it is
  // allocated, and before any line runs.
  const auto controller = [&] {
    try {
      return std::make_unique<SimController>(std::move(cfg));
    } catch (const Error& e) {
      if (e.id().rfind("stock.", 0) != 0) throw;
      throw stock_option_error(e);
    }
  }();
  SimController& ctl = *controller;

  if (!o.program.empty()) {
    signals.start([&ctl] { ctl.stop(); });
    Status st = ctl.run_program(program);
    signals.finish();
    if (signals.signal() != 0) {
      ctl.stop();  // the line in progress completes first
      st = ctl.status();
      std::cerr << "bezcam: simulate: stopped by signal " << signals.signal() << " after " << st.lines_executed
                << " lines; the trace is complete up to there\n";
      return exit_status::signalled(signals.signal());
    }
    if (st.state == State::alarm) {
      std::string text = ctl.alarm_text();
      const std::string prefix = "line " + std::to_string(st.alarm_line) + ": ";
      if (text.rfind(prefix, 0) == 0) text.erase(0, prefix.size());
      // A tool the stock's table lacks is refused as verify refuses it.
      const std::string id = ctl.alarm_id();
      throw InputError(id == errc::verify_tool.str() ? errc::verify_tool : alarm_error_id(st.alarm),
                       st.alarm_line ? resume.place_of(st.alarm_line) : Place::at_file(o.program),
                       text + " (alarm " + to_string(st.alarm) + " of the simulated controller)");
    }
    if (!o.quiet)
      std::cerr << "bezcam: simulate: " << o.program << ": " << st.lines_executed << " lines, " << st.blocks_executed
                << " motion blocks executed on machine " << o.machine << "\n";
    if (!o.report.empty() || !o.motion.empty()) plan_and_write(o, profile, program);
    return 0;
  }

  ServerConfig scfg;
  const Endpoint ep = parse_endpoint(o.listen, true);
  scfg.host = ep.host;
  scfg.port = ep.port;
  scfg.max_connections = o.max_connections;
  scfg.idle_timeout = std::chrono::milliseconds(static_cast<long long>(o.idle_timeout * 1000));
  ModbusServer server(ctl, scfg);
  signals.start([&server] { server.stop(); });
  // The readiness line: tests and scripts wait for it (never a sleep).
  std::cout << "bezcam simulate: listening on " << Endpoint{ep.host, server.port()}.str() << " (machine " << o.machine
            << ", buffer " << o.buffer << " bytes, at most " << o.max_connections << " connections, "
            << (o.time_scale == "max" ? std::string("as fast as possible")
                : o.time_scale == "1" ? std::string("real time")
                                      : o.time_scale + " x real time")
            << ")" << std::endl;
  server.run();
  signals.finish();
  ctl.stop();  // the trace is flushed, up to the last line the machine finished
  if (!o.quiet) {
    const Status st = ctl.status();
    std::cerr << "bezcam: simulate: stopped"
              << (signals.signal() ? " by signal " + std::to_string(signals.signal()) : "") << "; last program "
              << to_string(st.state) << ", " << st.lines_executed << " lines executed\n";
  }
  return 0;
}

}  // namespace bezcam::cli
