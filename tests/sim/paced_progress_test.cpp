// At machine pace the simulated controller reads ahead of the machine (a
// look-ahead window of blocks), but everything it reports follows the
// planned motion, what the machine has done: lines and blocks executed,
// position, spindle, the line an alarm names, the trace, DONE. Over real
// sockets with the controller as a child process (`bezcam simulate --listen
// 127.0.0.1:0 --time-scale K`, readiness read from its stdout, stopped by
// its PID), compared with the whole program's plan (machine/planner.hpp).
//
// The time checks are one-sided so that a busy machine cannot fail them:
// the controller's machine clock starts after the test's own clock, so at
// any moment the machine has run at most (the test's elapsed time) x K
// seconds of the plan; a slow machine only makes that bound looser.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <climits>
#include <cmath>
#include <gtest/gtest.h>
#include <regex>
#include <sstream>
#include <thread>

#include "bezcam/gcode/resume.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/sim/sim_controller.hpp"
#include "bezcam/sim/trace.hpp"
#include "bezcam/verify/machined_program.hpp"
#include "support/link_test_util.hpp"

using namespace bezcam;
using namespace bezcam::link;
namespace test = bezcam::test;
using Clock = std::chrono::steady_clock;

namespace {

// Semicircles along X (10 mm apart, 15.7 mm of path at F600: 1.57 s each on
// the generic profile), one per line, after a 6-line header; `bad_at`
// (a line number, 0 for none) is replaced by a move above the profile's
// maximum feed.
std::string arcs_program(int arcs, int bad_at = 0) {
  std::vector<std::string> l = {"%", "G21 G90 G17", "G0 Z5", "G0 X0 Y0", "S10000 M3", "G1 Z-1 F300"};
  for (int i = 0; i < arcs; ++i)
    l.push_back(std::string(i % 2 ? "G2" : "G3") + " X" + std::to_string(10 * (i + 1)) + " Y0 I5 J0 F600");
  l.insert(l.end(), {"G0 Z5", "M5", "M30", "%"});
  if (bad_at > 0) l[static_cast<size_t>(bad_at - 1)] = "G1 Z-1 F30000";
  std::string p;
  for (const auto& s : l) p += s + "\n";
  return p;
}

// The whole program's plan, per program line: when its work (and all
// before it) is finished. A block spanning lines finishes them all at its end.
class PlannedLines {
 public:
  PlannedLines(const std::string& program, const MachineProfile& m) {
    const MotionPlan plan = plan_motion(read_timeline(program, &m), *m.motion);
    auto item = [&](long line, double end) {
      double& e = end_[line];
      e = std::max(e, end);
    };
    for (const PlanSegment& s : plan.segments) {
      const MotionBlock& b = plan.motion[static_cast<size_t>(s.block)];
      item(b.first_line > 0 ? b.first_line : b.line, s.t_start + s.time());
    }
    for (size_t k = 0; k < plan.pauses.size(); ++k)
      item(plan.pauses[k].line, plan.pause_start_s[k] + plan.pauses[k].seconds);
    blocks_ = plan.motion;
    cycle_ = plan.cycle_time_s;
  }
  /// Machine time at which every line up to `line` is finished.
  double done_by(long line) const {
    double t = 0;
    for (const auto& [l, e] : end_)
      if (l <= line) t = std::max(t, e);
    return t;
  }
  double cycle() const { return cycle_; }
  /// Distance from `p` to the path of the blocks of `line`.
  double distance_to_line(long line, const Vec3& p) const {
    double best = INFINITY;
    for (const MotionBlock& b : blocks_) {
      if (b.line != line) continue;
      for (int i = 0; i <= 4000; ++i) {
        const Vec3 q = evaluate_block(b, i / 4000.0);
        best = std::min(best, std::hypot(q.x - p.x, q.y - p.y, q.z - p.z));
      }
    }
    return best;
  }

 private:
  std::map<long, double> end_;
  std::vector<MotionBlock> blocks_;
  double cycle_ = 0;
};

// The trace the controller writes for `program` as fast as the CPU allows,
// in process (the same executor, no pacing).
std::string immediate_trace(const std::string& program, const MachineProfile& m) {
  std::string trace;
  sim::ControllerConfig cfg;
  cfg.profile = m;
  cfg.trace = [&](std::string_view t, bool restart) {
    if (restart) trace.clear();
    trace += t;
  };
  sim::SimController ctl(std::move(cfg));
  ctl.run_program(program);
  return trace;
}

// One record of a trace and the program lines it names (0: header, done).
struct Record {
  long first = 0, last = 0;
  std::string text;  // without its label
};

std::vector<Record> records(const std::string& trace) {
  std::vector<Record> out;
  std::istringstream in(trace);
  for (std::string l; std::getline(in, l);) {
    if (l.rfind("  ", 0) == 0 && !out.empty()) {
      out.back().text += "\n" + l;
      continue;
    }
    Record r;
    r.text = l;
    if (l.rfind("lines ", 0) == 0) {
      r.first = std::stol(l.substr(6));
      r.last = std::stol(l.substr(l.find('-') + 1));
      r.text = l.substr(l.find(' ', 6));
    } else if (l.rfind("line ", 0) == 0) {
      r.first = r.last = std::stol(l.substr(5));
      r.text = l.substr(l.find(' ', 5));
    }
    out.push_back(r);
  }
  return out;
}

std::string join(const std::vector<Record>& rs, long offset) {
  std::string s;
  for (const auto& r : rs)
    s += (r.first == 0        ? std::string()
          : r.first == r.last ? "line " + std::to_string(r.first + offset)
                              : "lines " + std::to_string(r.first + offset) + "-" + std::to_string(r.last + offset)) +
         r.text + "\n";
  return s;
}

// The records of the lines first..last (0: from the header on).
std::string lines_of(const std::string& trace, long first, long last, long offset = 0) {
  std::vector<Record> keep;
  for (const Record& r : records(trace))
    if (r.first >= first && r.last <= last && (r.first > 0 || first == 0) && r.text.rfind("done", 0) != 0 &&
        r.text.rfind("alarm", 0) != 0)
      keep.push_back(r);
  return join(keep, offset);
}

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

Vec3 position_of(const Status& s) { return {s.pos[0] / 1000.0, s.pos[1] / 1000.0, s.pos[2] / 1000.0}; }

// Windowed planning agrees with the whole program's plan within a few per
// cent (MachinePace tests); the lines' bound allows that and one block.
constexpr double kPlanAgreement = 1.05;
constexpr double kOneArc = 1.6;  // s of machine time

}  // namespace

// The issue's case: streamed at K x real time, the status must never show a
// line done that the planned motion could not have finished by then, and an
// abort mid-program names the line in motion, with the position on it and
// the trace up to the line before.
TEST(PacedProgress, AnAbortMidProgramReportsTheLineThePlannedMotionHadReached) {
  const MachineProfile m = load_machine_profile("generic");
  const std::string prog = arcs_program(100);  // 110 lines, 2 min 41 s of motion
  const PlannedLines plan(prog, m);
  const double scale = 50;  // 3.2 s of wall time
  test::TempDir dir;
  const auto trace_file = dir / "trace.txt";
  test::SimProcess sim(dir, {"--machine", "generic", "--time-scale", "50", "--trace", trace_file.string(), "-q"});
  const Endpoint to{"127.0.0.1", sim.port()};

  std::atomic<bool> cancel{false};
  StreamOptions opt;
  opt.cancel = &cancel;
  std::string stream_error;
  const auto t0 = Clock::now();
  std::thread sender([&] {
    try {
      stream_program(prog, to, opt);
      stream_error = "the stream was not interrupted";
    } catch (const Error& e) {
      stream_error = e.id() == errc::link_cancelled ? std::string() : e.what();
    }
  });
  // Poll until the machine has done half the program, then stop it.
  const long half = 56;
  long seen = 0;
  int polls = 0;
  std::string wrong;  // what a poll found wrong (the sender is stopped first)
  while (wrong.empty()) {
    const ControllerReport r = controller_status(to, std::chrono::milliseconds(5000));
    const double machine_at_most = seconds_since(t0) * scale;
    ++polls;
    seen = r.status.lines_executed;
    if (plan.done_by(seen) > machine_at_most * kPlanAgreement + kOneArc)
      wrong = std::to_string(seen) + " lines executed after at most " + std::to_string(machine_at_most) +
              " s of machine time, but the plan finishes line " + std::to_string(seen) + " at " +
              std::to_string(plan.done_by(seen)) + " s";
    else if (r.status.state == State::alarm || r.status.state == State::done)
      wrong = std::string("the program ended before it was stopped: ") + to_string(r.status.state);
    if (seen >= half) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  cancel = true;
  sender.join();
  ASSERT_EQ(wrong, "");
  const double machine_at_most = seconds_since(t0) * scale;
  EXPECT_EQ(stream_error, "");
  EXPECT_GT(polls, 3);

  const ControllerReport after = controller_status(to, std::chrono::milliseconds(5000));
  const long executed = after.status.lines_executed;
  ASSERT_EQ(after.status.state, State::alarm);
  EXPECT_EQ(after.status.alarm, Alarm::aborted);
  // Not behind what the status showed, not ahead of the planned motion.
  EXPECT_GE(executed, seen);
  EXPECT_LE(plan.done_by(executed), machine_at_most * kPlanAgreement + kOneArc) << executed;
  EXPECT_LT(executed, 108) << "the machine cannot have got near the end";
  // The line in motion when it stopped, and the machine on its path.
  EXPECT_EQ(after.status.alarm_line, static_cast<std::uint32_t>(executed + 1));
  EXPECT_LT(plan.distance_to_line(executed + 1, position_of(after.status)), 0.02)
      << "position " << position_of(after.status).x << " " << position_of(after.status).y;
  EXPECT_EQ(after.status.flags & flag::spindle_on, 0) << "an alarm stops the spindle";
  EXPECT_EQ(sim.stop(), 0);
  // The trace: the lines done, exactly as a run from the start writes
  // them, then the alarm at the line in motion.
  const std::string trace = test::slurp(trace_file);
  EXPECT_EQ(lines_of(trace, 0, executed), lines_of(immediate_trace(prog, m), 0, executed));
  const auto recs = records(trace);
  ASSERT_FALSE(recs.empty());
  EXPECT_EQ(recs.back().text.rfind("alarm line " + std::to_string(executed + 1) + " aborted link.aborted", 0), 0u)
      << recs.back().text;
  for (const Record& r : recs) EXPECT_LE(r.last, executed + 1) << r.text;
}

// A line the controller refuses, read far ahead of the machine: the alarm
// comes when the machine has run everything before it (not when the line
// was read), names that line, and the trace is the one a run from the
// start writes.
TEST(PacedProgress, ARefusedLineStopsTheMachineWhenItGetsThere) {
  const MachineProfile m = load_machine_profile("generic");
  const int bad = 36;  // 29 arcs before it: 47 s of machine time
  const std::string prog = arcs_program(60, bad);
  const PlannedLines plan(arcs_program(bad - 7), m);  // lines 1 to bad - 1 as in `prog`
  const double scale = 50;
  test::TempDir dir;
  const auto trace_file = dir / "trace.txt";
  test::SimProcess sim(dir, {"--machine", "generic", "--time-scale", "50", "--trace", trace_file.string(), "-q"});
  const Endpoint to{"127.0.0.1", sim.port()};

  const auto t0 = Clock::now();
  std::string where;
  try {
    stream_program(prog, to);
    FAIL() << "the program was accepted";
  } catch (const ControllerError& e) {
    EXPECT_EQ(e.id(), errc::controller_alarm) << e.what();
    where = e.where();
  }
  const double wall = seconds_since(t0);
  // The machine ran lines 1-35 first: the plan's time for them at K x.
  EXPECT_GE(wall * scale, plan.done_by(bad - 1) / kPlanAgreement - kOneArc)
      << "the alarm came after " << wall << " s, before the machine could have run lines 1-" << bad - 1;
  EXPECT_EQ(where, "line " + std::to_string(bad));
  const ControllerReport r = controller_status(to, std::chrono::milliseconds(5000));
  EXPECT_EQ(r.status.alarm, Alarm::feed_limit);
  EXPECT_EQ(r.status.alarm_line, static_cast<std::uint32_t>(bad));
  EXPECT_EQ(r.status.lines_executed, static_cast<std::uint32_t>(bad - 1));
  EXPECT_EQ(sim.stop(), 0);
  EXPECT_EQ(test::slurp(trace_file), immediate_trace(prog, m));
}

// The traces' meaning does not change with the pace: programs with arcs,
// NURBS blocks spanning lines (G06.2, G5.2), G5 chains, tool changes,
// inches and cutter compensation (which holds a move until the next line)
// give the same trace, lines and blocks at machine pace as as fast as
// possible.
TEST(PacedProgress, TheTraceAtMachinePaceIsTheTraceAsFastAsPossible) {
  test::TempDir dir;
  struct Prog {
    std::string file, machine;
    std::vector<std::string> extra;
  };
  const std::string data = std::string(BEZCAM_SOURCE_DIR) + "/tests/gcode/data/resume/";
  std::vector<Prog> progs = {{data + "two-tools-fanuc.nc", "fanuc", {}},
                             {data + "keyhole-linuxcnc.nc", "linuxcnc", {}},
                             {data + "g5-chain-linuxcnc.nc", "linuxcnc", {}},
                             {data + "two-tools-arcs.nc", "generic", {}},
                             {data + "semicircle-inch.nc", "generic", {}}};
  // Cutter compensation: the controller-compensated sample, as arcs.
  const auto flange = dir / "flange.nc";
  const auto conv =
      test::run_bezcam({"convert", std::string(BEZCAM_SOURCE_DIR) + "/samples/controller-comp/flange-g41.json",
                        "--machine", "linuxcnc", "--output", "arcs", "-o", flange.string()},
                       dir);
  ASSERT_EQ(conv.status, 0) << conv.err;
  progs.push_back({flange.string(), "linuxcnc", {"--tool-diameter", "1=6", "--tool-diameter", "2=3"}});

  for (const Prog& p : progs) {
    SCOPED_TRACE(p.file);
    const std::string prog = test::slurp(p.file);
    MachineProfile m = load_machine_profile(p.machine);
    if (!p.extra.empty()) m.tool_diameters_mm = {{1, 6.0}, {2, 3.0}};
    ASSERT_NE(prog.find('\n'), std::string::npos);
    // About half a second of wall time each.
    const double cycle = plan_motion(read_timeline(prog, &m), *m.motion).cycle_time_s;
    char scale[32];
    std::snprintf(scale, sizeof scale, "%.3f", std::clamp(cycle / 0.5, 0.01, 100000.0));
    const auto trace_file = dir / "paced.trace";
    std::vector<std::string> args = {"--machine",         p.machine, "--time-scale", scale, "--trace",
                                     trace_file.string(), "-q"};
    args.insert(args.end(), p.extra.begin(), p.extra.end());
    test::SimProcess sim(dir, args);
    const StreamResult r = stream_program(prog, Endpoint{"127.0.0.1", sim.port()});
    EXPECT_EQ(sim.stop(), 0);
    const std::string want = immediate_trace(prog, m);
    EXPECT_EQ(test::slurp(trace_file), want);
    const auto done = records(want).back().text;  // "done lines L blocks B at ..."
    EXPECT_EQ(done.rfind("done lines " + std::to_string(r.lines_executed) + " blocks " +
                             std::to_string(r.blocks_executed) + " at",
                         0),
              0u)
        << done;
  }
}

// `bezcam stream` stopped with Ctrl-C says where the machine stopped and
// the --from-line that goes on from there. Resumed with the line it
// prints, on the same controller (which keeps its stock from program to
// program), nothing of the program is skipped or run twice: the stopped
// run executed the lines before it, the resumed run's trace holds the
// lines from it on as the whole program's does, and the stock both runs
// cut is the stock the whole program cuts without a stop.
TEST(PacedProgress, CtrlCPrintsTheFromLineThatGoesOnWhereTheMachineStopped) {
  const MachineProfile m = load_machine_profile("generic");
  test::TempDir dir;
  const auto file = dir / "arcs.nc";
  std::string prog = arcs_program(100);
  prog.insert(prog.find("S10000 M3"), "T1 M6\n");  // the stock is cut with T1, a 3 mm flat end mill
  test::write_file(file, prog);
  const auto trace_file = dir / "trace.txt";
  const StockBox box{-5, -10, -3, 1005, 10, 0};
  test::SimProcess sim(dir, {"--machine", "generic", "--time-scale", "50", "--trace", trace_file.string(), "--stock",
                             "-5,-10,-3,1005,10,0", "--cell", "0.25", "--tool-diameter", "1=3", "-q"});
  const std::string to = "127.0.0.1:" + std::to_string(sim.port());
  test::Child stream({BEZCAM_EXE, "stream", file.string(), "--to", to, "--progress", "off"}, dir / "stream-err.txt");
  for (;;) {
    const ControllerReport r = controller_status(Endpoint{"127.0.0.1", sim.port()}, std::chrono::milliseconds(5000));
    ASSERT_NE(r.status.state, State::done);
    if (r.status.lines_executed >= 40) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  stream.signal(SIGINT);
  EXPECT_EQ(stream.wait(), 130);
  const std::string err = stream.stderr_text();
  const ControllerReport after = controller_status(Endpoint{"127.0.0.1", sim.port()}, std::chrono::milliseconds(5000));
  const long executed = after.status.lines_executed;
  ASSERT_GE(executed, 40);
  ASSERT_LT(executed, 109);
  // The line to go on from, as printed.
  std::smatch said;
  ASSERT_TRUE(std::regex_search(
      err, said, std::regex(R"(; resume with --from-line (\d+) \(bezcam stream (\S+) --to (\S+) --from-line (\d+)\))")))
      << err;
  const long next = std::stol(said[1]);
  EXPECT_EQ(said[2], file.string());
  EXPECT_EQ(said[3], to);
  EXPECT_EQ(said[4], said[1]);
  EXPECT_NE(err.find("the machine stopped after line " + std::to_string(executed) + " of " + file.string()),
            std::string::npos)
      << err;
  // The controller ran every line before it and none after.
  EXPECT_EQ(next, executed + 1);

  // Resumed from the printed line on the same controller, as fast as the
  // link goes (its trace file restarts with the resumed program).
  const auto r =
      test::run_bezcam({"stream", file.string(), "--to", to, "--progress", "off", "--from-line", said[1]}, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string resumed = test::slurp(trace_file);
  EXPECT_EQ(sim.stop(), 0);
  const ResumePlan plan = plan_resume(prog, &m, static_cast<int>(next));
  ASSERT_EQ(plan.start_line, next);
  const std::string full = immediate_trace(prog, m);
  // Every line from it on exactly once, as the whole program runs it.
  EXPECT_EQ(lines_of(resumed, plan.preamble_lines + 1, LONG_MAX, plan.line_offset()), lines_of(full, next, LONG_MAX));
  // The stock: what the program cuts in one run, as verify cuts it.
  StockCutter whole(box, 0.25, {{1, ToolShape::flat(3)}});
  cut_timeline(whole, read_timeline(prog, &m));
  const std::string last = resumed.substr(resumed.rfind('\n', resumed.size() - 2) + 1);
  EXPECT_EQ(last.rfind("stock hash " + whole.grid().hash_hex() + " ", 0), 0u) << last;
}
