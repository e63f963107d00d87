// The measurements overlap the rest of the conversion: build_program()'s
// while_measuring sees the final moves while the pool still measures, the
// pool reports its earliest-added failure, and convert_program() plans the
// program it returns.
#include <atomic>
#include <chrono>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>
#include <thread>

#include "bezcam/bezcam.hpp"
#include "bezcam/cam/program_motion.hpp"
#include "cam/cut_emitters.hpp"

namespace bezcam {
namespace {

// Three curves (one per entity), with feeds and heights set.
Job three_curves() {
  return parse_job(R"({"bezcam":1,"tolerance":0.01,"job":{"feed":600,"plunge_feed":100,"safe_z":5,"cut_z":-1},
    "entities":[
      {"type":"bezier","points":[[0,0],[10,20],[30,-10],[40,10]]},
      {"type":"bezier","points":[[50,0],[55,30],[70,30],[80,0]]},
      {"type":"bezier","points":[[0,40],[20,60],[40,20],[60,45]]}]})",
                   "overlap.json");
}

std::vector<Vec3> motion_ends(const Program& p) {
  std::vector<Vec3> out;
  for (const Move& mv : p.moves)
    if (const Motion* m = motion_of(mv)) out.push_back(m->to);
  return out;
}

TEST(MeasureOverlap, WhileMeasuringSeesTheFinalMovesAndTheResultHasTheReadings) {
  const Job job = three_curves();
  const MachineProfile m = load_machine_profile("generic");
  ConvertOptions opt;
  opt.offset = {12.5, -3, 0};
  opt.return_to = Vec3{0, 0, 20};
  std::vector<Vec3> seen;
  std::vector<std::string> notes;
  int calls = 0;
  const Program p = build_program(job, m, opt, [&](const Program& q) {
    ++calls;
    seen = motion_ends(q);
    notes = q.notes;
  });
  EXPECT_EQ(calls, 1);
  // The moves it saw are the program's: the part moved, the return added.
  EXPECT_EQ(seen, motion_ends(p));
  EXPECT_EQ(notes, p.notes);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back(), (Vec3{0, 0, 20}));
  // The readings are in once it returns, as build_program() without it.
  const Program plain = build_program(job, m, opt);
  EXPECT_EQ(motion_ends(plain), motion_ends(p));
  ASSERT_EQ(p.entities.size(), 3u);
  EXPECT_GT(p.max_measured, 0);
  EXPECT_EQ(p.max_measured, plain.max_measured);
  for (size_t i = 0; i < p.entities.size(); ++i) {
    EXPECT_GT(p.entities[i].measured, 0) << i;
    EXPECT_EQ(p.entities[i].measured, plain.entities[i].measured) << i;
  }
}

TEST(MeasureOverlap, ItsFailureIsThrownAsItIsAfterTheMeasurements) {
  // Not reworded as a tolerance refusal of the build (the build wraps its
  // own flatten_tolerance errors with the machine's decimals).
  const Job job = three_curves();
  const MachineProfile m = load_machine_profile("generic");
  try {
    build_program(job, m, {}, [](const Program&) {
      throw InputError(errc::flatten_tolerance, Place::at_setting("tolerance"), "from the caller");
    });
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), errc::flatten_tolerance);
    EXPECT_EQ(e.message(), "from the caller");
  }
}

TEST(MeasureOverlap, ConvertProgramPlansTheProgramItReturns) {
  const Job job = three_curves();
  const MachineProfile m = load_machine_profile("generic");
  ConvertOptions opt;
  opt.offset = {5, 5, 0};
  const ConvertResult r = convert_program(job, m, opt);
  ASSERT_TRUE(r.plan.has_value());
  const MotionPlan again = plan_motion(program_timeline(r.program), *m.motion, PlanDetail::summary);
  EXPECT_EQ(r.plan->cycle_time_s, again.cycle_time_s);
  EXPECT_EQ(r.plan->cutting_time_s, again.cutting_time_s);
  EXPECT_EQ(r.plan->mean_feed_ratio, again.mean_feed_ratio);
  EXPECT_GT(r.program.max_measured, 0);
}

TEST(MeasureOverlap, ThePoolThrowsTheEarliestAddedFailure) {
  // A later task fails first in time; the one added earlier is reported.
  for (int run = 0; run < 5; ++run) {
    std::atomic<bool> late_failed{false};
    detail::Measurements pool;
    for (size_t i = 0; i < 12; ++i) {
      pool.add(i, [i, &late_failed]() -> double {
        if (i == 3) {
          for (int k = 0; k < 200 && !late_failed; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(1));
          throw std::logic_error("task 3");
        }
        if (i == 8) {
          late_failed = true;
          throw std::logic_error("task 8");
        }
        return static_cast<double>(i);
      });
      pool.release();
    }
    try {
      pool.finish();
      FAIL() << "no exception";
    } catch (const std::logic_error& e) {
      EXPECT_STREQ(e.what(), "task 3");
    }
  }
}

TEST(MeasureOverlap, ThePoolReturnsEveryReadingInTheOrderAdded) {
  detail::Measurements pool;
  for (size_t i = 0; i < 40; ++i) {
    pool.add(i % 7, [i] { return 0.5 * static_cast<double>(i); });
    if (i % 5 == 0) pool.release();
  }
  const auto& tasks = pool.finish();
  ASSERT_EQ(tasks.size(), 40u);
  for (size_t i = 0; i < tasks.size(); ++i) {
    EXPECT_EQ(tasks[i]->report, i % 7);
    EXPECT_EQ(tasks[i]->reading, 0.5 * static_cast<double>(i));
  }
}

}  // namespace
}  // namespace bezcam
