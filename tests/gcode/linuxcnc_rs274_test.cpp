// LinuxCNC's own interpreter as the judge of the `linuxcnc` profile's
// programs: `rs274` (Debian package linuxcnc-uspace, .ci/packages) runs a
// program standalone (`rs274 -g FILE`: no machine, no configuration) and
// prints the canonical machining calls it makes of it. Every sample, in
// every output mode, must be accepted (exit 0, PROGRAM_END reached) and mean
// what bezcam meant: the same end point for every move, the same centre and
// direction for every arc, the same order for every G5/G5.1/G5.2 curve.
// rs274 prints NURBS_FEED without coordinates, so a `(DEBUG,...)` comment
// with the interpreter's position parameters #5420-#5422 is added after
// each curve block; rs274 prints it as MESSAGE("POS x y z").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/gcode/best_output.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/number_format.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/kernel/arc.hpp"
#include "support/run_process.hpp"
#include "support/sample_job.hpp"

namespace bezcam {
namespace {

namespace fs = std::filesystem;

std::string find_rs274() {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/bin");
  for (std::string d; std::getline(dirs, d, ':');)
    if (!d.empty() && ::access((fs::path(d) / "rs274").c_str(), X_OK) == 0) return (fs::path(d) / "rs274").string();
  return "";
}

struct Rs274Run {
  int status = -1;
  std::string output;
};

// Runs rs274 on each program in turn, each in its own scratch directory
// (nothing of a machine is needed). Never two at once, not even from two
// test processes: concurrent rs274 processes share LinuxCNC's shared memory
// and die of SIGBUS, so every run holds an exclusive lock on a lock file.
// The tool table rs274 reads: zero lengths, and each tool's diameter in
// its D column, in inches (rs274 standalone has no INI: its machine units
// are inches), for the programs' cutter compensation (G41/G42 D-).
std::string tool_table(const std::map<int, double>& diameters_mm) {
  std::ostringstream tbl;
  tbl.precision(12);
  for (int t = 1; t <= 99; ++t) {
    const auto it = diameters_mm.find(t);
    tbl << "T" << t << " P" << t << " Z0 D" << (it == diameters_mm.end() ? 6.0 : it->second / 25.4)
        << " ;zero length\n";
  }
  return tbl.str();
}

std::vector<Rs274Run> run_rs274(const std::string& exe, const std::vector<std::string>& programs,
                                const std::vector<std::string>& tables) {
  std::vector<Rs274Run> runs(programs.size());
  const fs::path dir = fs::temp_directory_path() / ("bezcam-rs274-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const int lock = ::open((fs::temp_directory_path() / "bezcam-rs274.lock").c_str(), O_CREAT | O_RDWR, 0666);
  // Tools whose length offsets are zero: programs use G43 H- after each
  // tool change, and rs274's built-in table has lengths, which would move
  // every canonical Z; with zero offsets the canonical point is the tool
  // tip the program describes (as in bezcam's simulated controller).
  for (size_t i = 0; i < programs.size(); ++i) {
    std::ofstream(dir / "program.ngc") << programs[i];
    std::ofstream(dir / "tools.tbl") << tables[i];
    const std::string cmd = "cd '" + dir.string() + "' && '" + exe + "' -t tools.tbl -g program.ngc 2>&1";
    if (lock >= 0) ::flock(lock, LOCK_EX);
    const testproc::Result r = testproc::shell(cmd);
    runs[i].output = r.out;
    runs[i].status = r.status;
    if (lock >= 0) ::flock(lock, LOCK_UN);
  }
  if (lock >= 0) ::close(lock);
  fs::remove_all(dir);
  return runs;
}

// One canonical motion call: STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED,
// NURBS_FEED, or MESSAGE (our position probe).
struct Canon {
  std::string name;
  std::vector<double> args;
};

std::vector<Canon> parse_canon(const std::string& out) {
  std::vector<Canon> calls;
  const std::regex call(R"(^\s*\d+ N\.+ ([A-Z_]+)\((.*)\)\s*$)");
  const std::regex probe(R"xx("POS (\S+) (\S+) (\S+)")xx");
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_match(line, m, call)) continue;
    const std::string name = m[1];
    Canon c{name, {}};
    if (name == "MESSAGE") {
      std::smatch q;
      const std::string args = m[2];
      if (!std::regex_search(args, q, probe)) continue;
      for (int i = 1; i <= 3; ++i) c.args.push_back(std::stod(q[i]));
    } else if (name == "STRAIGHT_TRAVERSE" || name == "STRAIGHT_FEED" || name == "ARC_FEED" || name == "NURBS_FEED") {
      std::istringstream a(m[2].str());
      for (std::string tok; std::getline(a, tok, ',');) {
        if (tok.find("...") != std::string::npos) continue;
        c.args.push_back(std::stod(tok));
      }
    } else {
      continue;
    }
    calls.push_back(c);
  }
  return calls;
}

// The program with a position probe after every G5 / G5.1 line and every G5.3.
std::string with_probes(const std::string& gcode) {
  std::string out;
  std::istringstream in(gcode);
  for (std::string line; std::getline(in, line);) {
    out += line + "\n";
    if (line.rfind("G5 ", 0) == 0 || line.rfind("G5.1 ", 0) == 0 || line == "G5.3")
      out += "(DEBUG,POS #5420 #5421 #5422)\n";
  }
  return out;
}

// What bezcam meant: the canonical calls its moves should become, with the
// axes each one states (the first retract leaves X and Y unknown).
struct Expected {
  std::string name;
  Vec3 to, center;
  unsigned axes = 7;
  int order = 0;
  int rotation = 0;
  Plane plane = Plane::xy;  ///< arcs: ARC_FEED's ends are the plane's (G18: Z X, axis Y; G19: Y Z, axis X)
};

// Under cutter compensation the calls are the tool centre's: the program's
// motion as bezcam's model of compensation (cutter_comp.hpp) makes it.
std::vector<Expected> compensated_calls(const Program& p) {
  // The profile's G53 G0 Z0 before a tool change is in the text only: its
  // place among the blocks is the count of blocks before it (compensation
  // is off there, nothing is held).
  std::vector<size_t> tool_change_at;
  for (size_t i = 0; i < p.moves.size(); ++i)
    if (std::holds_alternative<ToolChangePosition>(p.moves[i].what)) {
      Program before = p;
      before.moves.resize(i);
      tool_change_at.push_back(program_motion(before).size());
    }
  std::vector<Expected> out;
  const auto blocks = program_motion(p);
  size_t next_change = 0;
  std::string printed[3];  // as the writer: a move that changes nothing printed is not written
  for (size_t i = 0; i < blocks.size(); ++i) {
    for (; next_change < tool_change_at.size() && tool_change_at[next_change] == i; ++next_change) {
      Expected z;
      z.name = "STRAIGHT_TRAVERSE";
      z.axes = 4;
      out.push_back(z);
      printed[2].clear();
    }
    const MotionBlock& b = blocks[i];
    Expected e;
    e.to = b.to;
    e.axes = b.from_known == 7 ? 7 : 4;
    if (b.kind == BlockKind::arc_cw || b.kind == BlockKind::arc_ccw) {
      e.name = "ARC_FEED";
      e.center = b.center;
      e.rotation = b.kind == BlockKind::arc_ccw ? 1 : -1;
      e.plane = b.plane;
    } else {
      bool changes = false;
      for (int a = 0; a < 3; ++a) changes = changes || format_number(b.to[a], p.decimals) != printed[a];
      if (!changes) continue;
      e.name = b.kind == BlockKind::rapid ? "STRAIGHT_TRAVERSE" : "STRAIGHT_FEED";
    }
    for (int a = 0; a < 3; ++a) printed[a] = format_number(b.to[a], p.decimals);
    out.push_back(e);
  }
  return out;
}

std::vector<Expected> expected_calls(const Program& p) {
  for (const Move& move : p.moves)
    if (std::holds_alternative<CompensationMove>(move.what)) return compensated_calls(p);
  std::vector<Expected> out;
  std::string printed[3];
  for (const Move& move : p.moves) {
    if (std::holds_alternative<ToolChangePosition>(move.what)) {
      // The profile's G53 G0 Z0: machine Z zero, which is program Z zero
      // here (no work offset, zero tool length); Z is printed again after.
      Expected e;
      e.name = "STRAIGHT_TRAVERSE";
      e.axes = 4;
      out.push_back(e);
      printed[2].clear();
      continue;
    }
    const Motion* mv = motion_of(move);
    if (!mv) continue;
    Expected e;
    e.to = mv->to;
    e.axes = mv->axes;
    if (const auto* arc = std::get_if<ArcMove>(&move.what)) {
      e.name = "ARC_FEED";
      e.center = arc->center;
      e.rotation = arc->ccw ? 1 : -1;
      e.plane = arc->plane;
    } else if (const auto* cv = std::get_if<CurveMove>(&move.what)) {
      e.name = "NURBS_FEED";
      e.order = cv->shape->order;
      e.axes = 3;
    } else {
      // The writer prints only what changes; a move that changes nothing
      // as printed is not written at all.
      bool changes = false;
      for (int a = 0; a < 3; ++a)
        if ((mv->axes & (1u << a)) && format_number(mv->to[a], p.decimals) != printed[a]) changes = true;
      if (!changes) continue;
      e.name = is_rapid(move) ? "STRAIGHT_TRAVERSE" : "STRAIGHT_FEED";
    }
    for (int a = 0; a < 3; ++a)
      if (e.axes & (1u << a)) printed[a] = format_number(mv->to[a], p.decimals);
    out.push_back(e);
  }
  return out;
}

// The program `convert --output MODE` writes (best: gcode/best_output.hpp);
// the modes of one job share `memo`, as --compare-outputs does.
ConvertResult convert_in(const Job& job, const MachineProfile& m, const std::string& mode,
                         const std::shared_ptr<ConversionMemo>& memo) {
  ConvertOptions opt;
  opt.measure = false;  // the meaning is checked here, the deviation elsewhere
  opt.memo = memo;
  if (mode != "best") {
    opt.output = parse_output_mode(mode);
    return convert(job, m, opt);
  }
  ConvertResult r = convert_best(job, m, opt).result;
  r.gcode = write_gcode(r.program, m, r.plan ? &*r.plan : nullptr);
  return r;
}

// What a run over the samples exercised.
struct Exercised {
  size_t programs = 0;
  int curves = 0, arcs = 0, compensated = 0;
};

// Every sample converted in each of `modes`, run by rs274 (`exe`), each
// move where bezcam put it; what was exercised in `x`.
void check_samples(const std::string& exe, const std::vector<std::string>& modes, Exercised& x) {
  const MachineProfile m = load_machine_profile("linuxcnc");
  struct Case {
    std::string name;
    ConvertResult r;
  };
  std::vector<Case> cases;
  // samples/controller-comp: jobs cut with the controller's compensation
  // (G41/G42), which some output modes refuse (below).
  std::vector<fs::path> files;
  for (const char* dir : {BEZCAM_SOURCE_DIR "/samples", BEZCAM_SOURCE_DIR "/samples/controller-comp"})
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
  int compensated = 0;
  for (const auto& path : files) {
    const fs::directory_entry entry(path);
    const Job job = test::load_sample(entry.path());
    const auto memo = make_conversion_memo();
    for (const std::string& mode : modes) {
      const std::string name = entry.path().filename().string() + ", --output " + mode;
      try {
        cases.push_back({name, convert_in(job, m, mode, memo)});
      } catch (const InputError& e) {
        // Only a tolerance the machine's decimals cannot honour may refuse,
        // and controller compensation asked of NURBS output.
        // and controller compensation where the controller cannot follow
        // the output mode (NURBS blocks; G01 moves that it joins without a
        // corner, straying beyond the tolerance).
        const std::string what = e.what();
        // Best leaves a refused mode out: it refuses what every mode does.
        const bool comp = e.id() == "job.cut" && mode != "arcs" && mode != "best" &&
                          (what.find("cannot be written as NURBS blocks") != std::string::npos ||
                           what.find("controller's compensation of these lines strays") != std::string::npos);
        if (!comp) EXPECT_EQ(e.id(), "flatten.tolerance-below-rounding") << name << ": " << e.what();
      }
    }
  }
  std::vector<std::string> programs;
  std::vector<std::string> tables;
  for (const auto& c : cases) {
    programs.push_back(with_probes(c.r.gcode));
    tables.push_back(tool_table(with_compensation_registers(m, c.r.program).tool_diameters_mm));
  }
  const auto runs = run_rs274(exe, programs, tables);

  int curves = 0, arcs = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(cases[i].name);
    const ConvertResult& r = cases[i].r;
    const Rs274Run& run = runs[i];
    ASSERT_EQ(run.status, 0) << run.output << "\n--- program ---\n" << r.gcode;
    ASSERT_NE(run.output.find("PROGRAM_END()"), std::string::npos) << run.output;
    if (run.output.find("cutter radius compensation on") != std::string::npos) ++compensated;

    const auto calls = parse_canon(run.output);
    const auto want = expected_calls(r.program);
    // rs274 prints 4 decimals; the program has 4 (mm) or 5 (inch).
    const double eps = 0.5e-4 + 1e-9;
    size_t k = 0;
    for (const auto& w : want) {
      ASSERT_LT(k, calls.size()) << "rs274 made fewer moves than the program has";
      const Canon& c = calls[k++];
      ASSERT_EQ(c.name, w.name) << "call " << k << " to (" << w.to.x << ", " << w.to.y << ", " << w.to.z << ")";
      if (w.name == "NURBS_FEED") {
        ++curves;
        ASSERT_EQ(c.args.size(), 1u);
        EXPECT_EQ(c.args[0], w.order);
        // The probe right after it: the interpreter's position, 6 decimals.
        ASSERT_LT(k, calls.size());
        const Canon& pos = calls[k++];
        ASSERT_EQ(pos.name, "MESSAGE");
        EXPECT_NEAR(pos.args[0], w.to.x, 0.5e-6 + 1e-9);
        EXPECT_NEAR(pos.args[1], w.to.y, 0.5e-6 + 1e-9);
        continue;
      }
      if (w.name == "ARC_FEED") {
        ++arcs;
        ASSERT_GE(c.args.size(), 6u);
        // In the plane's coordinates: first end, second end, first and
        // second centre, rotation, the axis end.
        const Vec3 to = to_plane(w.to, w.plane), centre = to_plane(w.center, w.plane);
        EXPECT_NEAR(c.args[0], to.x, eps);
        EXPECT_NEAR(c.args[1], to.y, eps);
        EXPECT_NEAR(c.args[2], centre.x, eps);
        EXPECT_NEAR(c.args[3], centre.y, eps);
        EXPECT_EQ(c.args[4], w.rotation);
        EXPECT_NEAR(c.args[5], to.z, eps);
        continue;
      }
      ASSERT_GE(c.args.size(), 3u);
      for (int a = 0; a < 3; ++a)
        if (w.axes & (1u << a)) EXPECT_NEAR(c.args[static_cast<size_t>(a)], w.to[a], eps) << c.name << " axis " << a;
    }
    // After the program's moves only the footer's retract follows.
    for (; k < calls.size(); ++k) EXPECT_EQ(calls[k].name, "STRAIGHT_TRAVERSE");
  }
  std::cout << "[ rs274    ] " << cases.size() << " programs accepted; " << curves << " G5/G5.1/G5.2 blocks, " << arcs
            << " arcs and every line and rapid end where bezcam put them\n";
  x = {cases.size(), curves, arcs, compensated};
}

const char* kNoRs274 =
    "rs274 (LinuxCNC's standalone interpreter, Debian package linuxcnc-uspace) is not installed; "
    "install it to check the linuxcnc profile's programs against LinuxCNC itself";

TEST(LinuxcncRs274, EverySampleInEveryModeIsAcceptedAndMeansWhatWeMeant) {
  const std::string exe = find_rs274();
  if (exe.empty()) GTEST_SKIP() << kNoRs274;
  Exercised x;
  check_samples(exe, {"lines", "arcs", "nurbs"}, x);
  EXPECT_GE(x.programs, 40u);
  EXPECT_GT(x.curves, 20);  // G5, G5.1 and G5.2 blocks were exercised
  EXPECT_GT(x.arcs, 50);
  EXPECT_GE(x.compensated, 1);  // a G41/G42 program, its tool centre where bezcam's model puts it
}

// --output best: each entity in the mode it chose, in one program.
TEST(LinuxcncRs274, EverySampleInBestOutputIsAcceptedAndMeansWhatWeMeant) {
  const std::string exe = find_rs274();
  if (exe.empty()) GTEST_SKIP() << kNoRs274;
  Exercised x;
  check_samples(exe, {"best"}, x);
  EXPECT_GE(x.programs, 40u / 3);
  EXPECT_GT(x.arcs, 50);
  EXPECT_GE(x.compensated, 1);
}

}  // namespace
}  // namespace bezcam

namespace bezcam {
namespace {

// The position after each line: the program with a probe printing the line
// number and the interpreter's position (#5420-#5422) after every line
// that leaves no block open and does not end the program.
std::string with_line_probes(const std::string& gcode, const std::vector<bool>& probe) {
  std::string out;
  std::istringstream in(gcode);
  size_t no = 0;
  for (std::string line; std::getline(in, line); ++no) {
    out += line + "\n";
    if (no < probe.size() && probe[no]) out += "(DEBUG,POS " + std::to_string(no + 1) + " #5420 #5421 #5422)\n";
  }
  return out;
}

// One motion as an interpreter executed it: its kind, where it ends, and
// for an arc its centre, direction and plane.
struct Executed {
  std::string name;  // STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED, NURBS_FEED
  Vec3 to, center;
  int rotation = 0;
  Plane plane = Plane::xy;
};

std::string describe(const Executed& e) {
  std::ostringstream s;
  s << e.name << " to (" << e.to.x << ", " << e.to.y << ", " << e.to.z << ")";
  if (e.name == "ARC_FEED") s << " centre (" << e.center.x << ", " << e.center.y << ", " << e.center.z << ")";
  return s.str();
}

// Straight moves that end where the one before ended move nothing: rs274
// prints G28's intermediate point where the tool already stands, bezcam
// leaves it out.
void keep_moving(std::vector<Executed>& out, Executed e) {
  const Vec3 before = out.empty() ? Vec3{} : out.back().to;
  if (e.name.rfind("STRAIGHT", 0) == 0 && norm(e.to - before) < 1e-9) return;
  out.push_back(std::move(e));
}

}  // namespace

// Programs as other posts write them (tests/gcode/data/posts, see
// other_posts_test.cpp): blanks inside words, G91 (lines, arcs in G17 and
// G18, G5, G5.1 and G5.2 blocks), G90.1 / G91.1, G28 and G91 G28 Z0,
// comments, N numbers, lower case. Every motion bezcam reads ends where
// LinuxCNC's interpreter ends it (arcs with the same centre and
// direction), and the position after every line is the same.
TEST(LinuxcncRs274, ProgramsFromOtherPostsMoveAsLinuxcncReadsThem) {
  const std::string exe = find_rs274();
  if (exe.empty())
    GTEST_SKIP() << "rs274 (LinuxCNC's standalone interpreter, Debian package linuxcnc-uspace) is not installed";
  const char* files[] = {"dxf2gcode-plate.ngc", "dxf2gcode-incremental.ngc", "freecad-linuxcnc.ngc", "freecad-fanuc.nc",
                         "linuxcnc-distance-modes.ngc"};
  std::vector<std::string> texts, programs, tables;
  std::vector<std::vector<Vec3>> positions;  // bezcam's, after each line
  std::vector<std::vector<bool>> probed;
  std::vector<std::vector<Executed>> ours;
  for (const char* f : files) {
    std::ifstream in(std::string(BEZCAM_SOURCE_DIR) + "/tests/gcode/data/posts/" + f, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    texts.push_back(ss.str());
    GcodeInterpreter reader;
    std::vector<Vec3> pos;
    std::vector<bool> probe;
    std::vector<Executed> moves;
    std::istringstream lines(texts.back());
    int no = 0;
    for (std::string line; std::getline(lines, line);) {
      for (const MotionBlock& b : reader.feed_line(line, ++no)) {
        Executed e;
        e.to = b.to;
        if (b.kind == BlockKind::arc_cw || b.kind == BlockKind::arc_ccw) {
          e.name = "ARC_FEED";
          e.center = b.center;
          e.rotation = b.kind == BlockKind::arc_ccw ? 1 : -1;
          e.plane = b.plane;
        } else {
          e.name = b.kind == BlockKind::rapid    ? "STRAIGHT_TRAVERSE"
                   : b.kind == BlockKind::linear ? "STRAIGHT_FEED"
                                                 : "NURBS_FEED";
        }
        keep_moving(moves, e);
      }
      pos.push_back(reader.state().pos);
      probe.push_back(!reader.state().program_end && reader.continuation().open_block == ModalMotion::none);
    }
    EXPECT_TRUE(reader.finish().empty());
    positions.push_back(pos);
    probed.push_back(probe);
    ours.push_back(moves);
    programs.push_back(with_line_probes(texts.back(), probe));
    tables.push_back(tool_table({}));
  }
  const auto runs = run_rs274(exe, programs, tables);

  const std::regex call(R"(^\s*\d+ N\S*\s+([A-Z_]+)\((.*)\)\s*$)");
  const std::regex probe(R"xx("POS (\d+) (\S+) (\S+) (\S+)")xx");
  for (size_t i = 0; i < runs.size(); ++i) {
    SCOPED_TRACE(files[i]);
    ASSERT_EQ(runs[i].status, 0) << runs[i].output;
    ASSERT_NE(runs[i].output.find("PROGRAM_END()"), std::string::npos) << runs[i].output;
    std::vector<Executed> theirs;
    Plane plane = Plane::xy;
    size_t probes = 0;
    std::istringstream out(runs[i].output);
    for (std::string line; std::getline(out, line);) {
      std::smatch m;
      if (!std::regex_match(line, m, call)) continue;
      const std::string name = m[1], args = m[2];
      if (name == "SELECT_PLANE") {
        plane = args.find("XZ") != std::string::npos   ? Plane::zx
                : args.find("YZ") != std::string::npos ? Plane::yz
                                                       : Plane::xy;
        continue;
      }
      if (name == "MESSAGE") {
        std::smatch q;
        ASSERT_TRUE(std::regex_search(args, q, probe)) << line;
        const size_t no = std::stoul(q[1]);
        ASSERT_GE(no, 1u);
        ASSERT_LE(no, positions[i].size());
        const Vec3 at{std::stod(q[2]), std::stod(q[3]), std::stod(q[4])};
        // 6 decimals printed.
        EXPECT_LT(norm(at - positions[i][no - 1]), 1e-6) << "after line " << no;
        ++probes;
        // A curve's end: the probe after the line that completes it.
        if (!theirs.empty() && theirs.back().name == "NURBS_FEED" && std::isnan(theirs.back().to.x))
          theirs.back().to = at;
        continue;
      }
      if (name != "STRAIGHT_TRAVERSE" && name != "STRAIGHT_FEED" && name != "ARC_FEED" && name != "NURBS_FEED")
        continue;
      std::vector<double> v;
      std::istringstream a(args);
      for (std::string tok; std::getline(a, tok, ',');)
        if (tok.find("...") == std::string::npos) v.push_back(std::stod(tok));
      Executed e;
      e.name = name;
      if (name == "NURBS_FEED") {
        e.to = Vec3{std::nan(""), std::nan(""), std::nan("")};
        theirs.push_back(e);  // never a move that moves nothing
        continue;
      }
      if (name == "ARC_FEED") {
        ASSERT_GE(v.size(), 6u) << line;
        // In the plane's coordinates: first end, second end, first and
        // second centre, rotation, the axis end.
        e.to = from_plane(Vec3{v[0], v[1], v[5]}, plane);
        e.rotation = static_cast<int>(v[4]);
        e.plane = plane;
        const Vec3 from = theirs.empty() ? Vec3{} : theirs.back().to;
        Vec3 c = to_plane(from, plane);
        c.x = v[2];
        c.y = v[3];
        e.center = from_plane(c, plane);
        theirs.push_back(e);
        continue;
      }
      ASSERT_GE(v.size(), 3u) << line;
      e.to = Vec3{v[0], v[1], v[2]};
      keep_moving(theirs, e);
    }
    EXPECT_EQ(probes, static_cast<size_t>(std::count(probed[i].begin(), probed[i].end(), true)));
    const auto& mine = ours[i];
    ASSERT_EQ(mine.size(), theirs.size()) << runs[i].output;
    const double eps = 0.5e-4 + 1e-9;  // rs274 prints 4 decimals
    for (size_t k = 0; k < mine.size(); ++k) {
      SCOPED_TRACE("move " + std::to_string(k + 1) + ": bezcam " + describe(mine[k]) + ", rs274 " +
                   describe(theirs[k]));
      EXPECT_EQ(mine[k].name, theirs[k].name);
      EXPECT_LT(norm(mine[k].to - theirs[k].to), eps);
      if (mine[k].name == "ARC_FEED") {
        EXPECT_EQ(mine[k].plane, theirs[k].plane);
        EXPECT_EQ(mine[k].rotation, theirs[k].rotation);
        EXPECT_LT(norm(mine[k].center - theirs[k].center), eps);
      }
    }
  }
}

}  // namespace bezcam

namespace bezcam {
namespace {

// One canonical call of a canned cycle: a straight move (to) or a dwell.
struct CycleCall {
  std::string name;  // STRAIGHT_TRAVERSE, STRAIGHT_FEED, DWELL
  Vec3 to;
  double seconds = 0;
};

std::string describe(const CycleCall& c) {
  std::ostringstream s;
  s << c.name;
  if (c.name == "DWELL")
    s << " " << c.seconds;
  else
    s << " to (" << c.to.x << ", " << c.to.y << ", " << c.to.z << ")";
  return s.str();
}

// Appends a straight move unless it ends where the tool stands (rs274
// prints such moves, bezcam leaves them out).
void add_move(std::vector<CycleCall>& out, Vec3& at, CycleCall c) {
  if (norm(c.to - at) < 1e-9) return;
  at = c.to;
  out.push_back(std::move(c));
}

}  // namespace

// Canned cycles as LinuxCNC's interpreter runs them: every move and dwell
// of G81, G82, G83 and G73, in G98 and G99, G90 and G91, with L repeats,
// pecks that do not divide the depth, starts below R, in mm and inches
// (the peck clearance is 0.010 inch), in G17, G18 and G19, and a cycle
// that keeps the initial level across a change of plane. The programs'
// numbers have at most 4 decimals, as rs274 prints them, so the ends
// agree within 1e-9.
TEST(LinuxcncRs274, CannedCyclesMoveAndDwellAsLinuxcncRunsThem) {
  const std::string exe = find_rs274();
  if (exe.empty())
    GTEST_SKIP() << "rs274 (LinuxCNC's standalone interpreter, Debian package linuxcnc-uspace) is not installed";
  const std::vector<std::string> programs = {
      // G17, mm: G99 (the default), the modal X line, G98, a start below R,
      // G91 with L, G82, exact and inexact pecks.
      "G21 G90 G17\nG0 X0 Y0 Z10\nF100\nG81 X1 Y1 Z-2 R2\nX2\nG80\nG0 Z1\n"
      "G98 G83 X5 Y5 Z-3.5 R2 Q1\nG91 G99 G73 X1 Z-2.1 R-3 Q0.7 L2\nG90 G0 Z-5\n"
      "G98 G82 X0 Z-6 R-1 P0.5\nG99 X3 Y2\nG98 Y4 P1.25\nG80\nG0 Z20\n"
      "G83 X10 Y10 Z-4 R1 Q1.25\nG91 X-2 Y1 L3\nG90 G99 G73 X0 Y0 Z0 R3 Q1 L2\nG80\nM2\n",
      // G20: the clearance of G83 and G73 is 0.010 inch.
      "G20 G90 G17\nG0 X0 Y0 Z1\nF10\nG98 G83 X0.5 Y0.5 Z-0.25 R0.1 Q0.1\nG73 X1 Z-0.2 R0.05 Q0.08\nG80\nM2\n",
      // G18 and G19; the initial level kept across the change of plane.
      "G21 G90 G18\nG0 X0 Y0 Z1\nF100\nG81 Z2 X1 Y-1 R0.5\nG19\nG91 G82 Y1 Z1 X-1 R-0.25 P0.25 L2\n"
      "G90 G80\nG0 X5\nG99 G83 Y0 Z0 X-2 R1 Q1.5\nG80\nG17\nM2\n",
  };
  std::vector<std::vector<CycleCall>> ours;
  for (const std::string& text : programs) {
    std::vector<CycleCall> calls;
    Vec3 at{0, 0, 0};  // rs274 starts at the origin
    for (const MotionBlock& b : read_gcode(text)) {
      add_move(calls, at, {b.kind == BlockKind::rapid ? "STRAIGHT_TRAVERSE" : "STRAIGHT_FEED", b.to, 0});
      if (b.dwell_s > 0) calls.push_back({"DWELL", {}, b.dwell_s});
    }
    ours.push_back(calls);
  }
  const auto runs = run_rs274(exe, programs, std::vector<std::string>(programs.size(), tool_table({})));
  const std::regex call(R"(^\s*\d+ N\S*\s+([A-Z_]+)\((.*)\)\s*$)");
  int dwells = 0;
  size_t moves = 0;
  for (size_t i = 0; i < runs.size(); ++i) {
    SCOPED_TRACE(programs[i]);
    ASSERT_EQ(runs[i].status, 0) << runs[i].output;
    ASSERT_NE(runs[i].output.find("PROGRAM_END()"), std::string::npos) << runs[i].output;
    std::vector<CycleCall> theirs;
    Vec3 at{0, 0, 0};
    std::istringstream out(runs[i].output);
    for (std::string line; std::getline(out, line);) {
      std::smatch m;
      if (!std::regex_match(line, m, call)) continue;
      const std::string name = m[1];
      if (name != "STRAIGHT_TRAVERSE" && name != "STRAIGHT_FEED" && name != "DWELL") continue;
      std::vector<double> v;
      std::istringstream a(m[2].str());
      for (std::string tok; std::getline(a, tok, ',');) v.push_back(std::stod(tok));
      if (name == "DWELL") {
        ASSERT_EQ(v.size(), 1u) << line;
        theirs.push_back({name, {}, v[0]});
        continue;
      }
      ASSERT_GE(v.size(), 3u) << line;
      add_move(theirs, at, {name, Vec3{v[0], v[1], v[2]}, 0});
    }
    const auto& mine = ours[i];
    ASSERT_EQ(mine.size(), theirs.size()) << runs[i].output;
    for (size_t k = 0; k < mine.size(); ++k) {
      SCOPED_TRACE("call " + std::to_string(k + 1) + ": bezcam " + describe(mine[k]) + ", rs274 " +
                   describe(theirs[k]));
      EXPECT_EQ(mine[k].name, theirs[k].name);
      EXPECT_LT(norm(mine[k].to - theirs[k].to), 1e-9);
      EXPECT_NEAR(mine[k].seconds, theirs[k].seconds, 1e-9);
      dwells += mine[k].name == "DWELL";
    }
    moves += mine.size();
  }
  EXPECT_GE(dwells, 5);
  EXPECT_GT(moves, 150u);
}

// bezcam's own drilled holes (docs/holes.md) in each cycle: two G81 holes
// waiting at R (G99), then G83, G73 and G82 back to the initial level
// (G98): LinuxCNC moves exactly as the program's moves say, peck by peck.
TEST(LinuxcncRs274, DrilledHolesMoveAsTheProgramSays) {
  const std::string exe = find_rs274();
  if (exe.empty())
    GTEST_SKIP() << "rs274 (LinuxCNC's standalone interpreter, Debian package linuxcnc-uspace) is not installed";
  const Job job = parse_job(R"({"bezcam":1,"units":"mm","tolerance":0.01,
   "tools":{"2":{"shape":"drill","diameter":5,"point_angle":118}},
   "job":{"feed":800,"plunge_feed":150,"safe_z":5,"top_z":0,"clearance":1,"tool":2,"cut_z":-7.3,"operation":"drill"},
   "entities":[{"type":"point","at":[10,10]},{"type":"point","at":[20,10]},
    {"type":"point","at":[30,10],"peck":2.5,"retract_z":2},
    {"type":"point","at":[40,10],"peck":1.5,"chip_break":true,"retract_z":3},
    {"type":"point","at":[50,10],"dwell":0.5,"retract_z":4}]})",
                            "holes.json");
  const MachineProfile m = load_machine_profile("linuxcnc");
  const ConvertResult r = convert(job, m, {});
  for (const char* cycle : {"G99 G81", "G98 G83", "G98 G73", "G98 G82"})
    EXPECT_NE(r.gcode.find(cycle), std::string::npos) << cycle;
  const auto runs = run_rs274(exe, {r.gcode}, {tool_table({})});
  ASSERT_EQ(runs[0].status, 0) << runs[0].output << "\n--- program ---\n" << r.gcode;
  ASSERT_NE(runs[0].output.find("PROGRAM_END()"), std::string::npos) << runs[0].output;
  const auto calls = parse_canon(runs[0].output);
  const auto want = expected_calls(r.program);
  ASSERT_LE(want.size(), calls.size());
  for (size_t k = 0; k < want.size(); ++k) {
    ASSERT_EQ(calls[k].name, want[k].name) << "call " << k;
    ASSERT_GE(calls[k].args.size(), 3u);
    for (int a = 0; a < 3; ++a)
      if (want[k].axes & (1u << a))
        EXPECT_NEAR(calls[k].args[static_cast<size_t>(a)], want[k].to[a], 0.5e-4 + 1e-9)
            << "call " << k << " axis " << a;
  }
  EXPECT_GT(want.size(), 40u);  // every peck a move of its own
  EXPECT_NE(runs[0].output.find("DWELL(0.5"), std::string::npos) << runs[0].output;
}

}  // namespace bezcam
