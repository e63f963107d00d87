// The simulated controller's stated limits (docs/limits.md): a program line
// is at most its buffer and at most what the shared G-code reader takes; a
// line over either raises an alarm naming it, never a hang. "Quickly" is
// checked by ctest's TIMEOUT for *Limits* tests (CMakeLists.txt).
#include "bezcam/limits.hpp"

#include <gtest/gtest.h>

#include "bezcam/sim/sim_controller.hpp"

using namespace bezcam;
using namespace bezcam::link;
using namespace bezcam::sim;

TEST(Limits, TheControllerRefusesALineOverTheReadersLimitEvenWithABiggerBuffer) {
  ControllerConfig cfg;
  cfg.profile = load_machine_profile("generic");
  cfg.buffer_bytes = kMaxBuffer;  // 65535: the buffer would hold the line
  SimController ctl(cfg);
  const std::string program = "G21 G90\n(" + std::string(kMaxLineBytes, 'x') + ")\nG00 X1.\nM30\n";
  const Status s = ctl.run_program(program);
  EXPECT_EQ(s.state, State::alarm);
  EXPECT_EQ(s.alarm, Alarm::gcode);
  EXPECT_EQ(s.alarm_line, 2u);
  EXPECT_NE(ctl.alarm_text().find("more than the 4096"), std::string::npos) << ctl.alarm_text();
  // A line at the limit runs.
  const std::string at_limit = "G21 G90\n(" + std::string(kMaxLineBytes - 2, 'x') + ")\nG00 X1.\nM30\n";
  EXPECT_EQ(ctl.run_program(at_limit).state, State::done);
}
