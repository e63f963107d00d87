// Machine profiles are validated like jobs (issue "Safe on the shop floor",
// bug 7): a misspelt key is refused naming the key it resembles, an unknown
// placeholder is refused rather than printed literally, and the name is the
// file's name. Every shipped profile passes.
#include "bezcam/machine/machine_profile.hpp"

#include <filesystem>
#include <gtest/gtest.h>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_json.hpp"
#include "support/files.hpp"

namespace {

using bezcam::InputError;
using bezcam::MachineProfile;
using bezcam::parse_machine_profile;

InputError refusal(const std::string& text) {
  try {
    parse_machine_profile(text, "p.json");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted " << text;
  return InputError(bezcam::ErrorId(""), bezcam::Place{}, "");
}

}  // namespace

TEST(MachineProfile, EveryShippedProfileIsValid) {
  for (const auto& e : std::filesystem::directory_iterator(std::string(BEZCAM_SOURCE_DIR) + "/machines")) {
    if (e.path().extension() != ".json") continue;
    const MachineProfile m = bezcam::load_machine_profile(e.path().string(), {});
    EXPECT_EQ(m.name, e.path().stem().string());
  }
}

TEST(MachineProfile, AMisspeltKeyIsRefusedNamingTheKeyItResembles) {
  auto e = refusal(R"({"name": "p", "feed_decimal": 0})");
  EXPECT_EQ(e.id(), "machine.key-typo");
  EXPECT_EQ(e.where(), "p.json: feed_decimal");
  EXPECT_NE(std::string(e.what()).find("did you mean \"feed_decimals\""), std::string::npos) << e.what();
  e = refusal(R"({"name": "p", "nurbs": {"dialect": "fanuc", "max_rnak": 3}})");
  EXPECT_EQ(e.where(), "p.json: nurbs.max_rnak");
  EXPECT_NE(std::string(e.what()).find("\"max_rank\""), std::string::npos) << e.what();
  e = refusal(R"({"name": "p", "defaults": {"saf_z": 5}})");
  EXPECT_EQ(e.where(), "p.json: defaults.saf_z");
}

TEST(MachineProfile, AnotherUnknownKeyIsRefusedAndKeysOfTheUsersOwnAreKept) {
  const auto e = refusal(R"({"name": "p", "vendor": "acme"})");
  EXPECT_EQ(e.id(), "machine.unknown-key");
  EXPECT_EQ(e.where(), "p.json: vendor");
  EXPECT_NE(std::string(e.what()).find("keys of your own start with \"x-\""), std::string::npos) << e.what();
  EXPECT_EQ(parse_machine_profile(R"({"name": "p", "x-vendor": "acme", "words": {"x-note": 1}})", "p.json").name, "p");
}

TEST(MachineProfile, AnUnknownPlaceholderIsRefused) {
  auto e = refusal(R"({"name": "p", "spindle_on": "S{rmp} M03"})");
  EXPECT_EQ(e.id(), "machine.placeholder");
  EXPECT_EQ(e.where(), "p.json: spindle_on");
  EXPECT_NE(std::string(e.what()).find("did you mean {rpm}?"), std::string::npos) << e.what();
  e = refusal(R"({"name": "p", "footer": ["M05", "G00 Z{safe_z}", "T{tool}"]})");
  EXPECT_EQ(e.where(), "p.json: footer[2]");
  e = refusal(R"({"name": "p", "tool_change": "T{tool M06"})");
  EXPECT_EQ(e.where(), "p.json: tool_change");
  EXPECT_NO_THROW(
      parse_machine_profile(R"({"name": "p", "tool_change": "T{tool} M06", "spindle_on": "S{rpm} M03"})", "p.json"));
}

TEST(MachineProfile, TheNameIsTheFilesName) {
  bezcam::test::TempDir d;
  bezcam::test::write_file(d / "mill.json", R"({"name": "mill-2"})");
  try {
    bezcam::load_machine_profile((d / "mill.json").string(), {});
    ADD_FAILURE() << "accepted a profile named mill-2 in mill.json";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "machine.name");
    EXPECT_NE(std::string(e.what()).find("expected \"mill\""), std::string::npos) << e.what();
  }
  bezcam::test::write_file(d / "mill.json", R"({"name": "mill"})");
  EXPECT_EQ(bezcam::load_machine_profile((d / "mill.json").string(), {}).name, "mill");
}

namespace {
bezcam::ConvertResult convert_text(const std::string& job, const char* machine) {
  return bezcam::convert(bezcam::parse_job(job, "t.json"), bezcam::load_machine_profile(machine), {});
}
}  // namespace

TEST(MachineProfile, DecimalsComeFromTheTolerance) {
  // 0.0005 mm: generic's 3 decimals would spend 0.00087 in rounding alone;
  // 4 keep it under half the tolerance, and generic accepts up to 6.
  const auto r = convert_text(
      R"({"bezcam": 1, "tolerance": 0.0005, "entities": [{"type": "bezier", "points": [[0,0],[10,20],[20,0]]}]})",
      "generic");
  EXPECT_EQ(r.program.decimals, 4);
  EXPECT_NE(
      r.gcode.find("(coordinates with 4 decimals for tolerance 0.0005 mm [machine generic: 3 by default, at most 6])"),
      std::string::npos)
      << r.gcode.substr(0, 400);
  EXPECT_NE(r.gcode.find("X0.2202 Y0.4364"), std::string::npos);  // the first vertex after the start, to 4 decimals
  EXPECT_LE(r.program.max_bound, 0.0005);
  // A tolerance the default decimals hold keeps them (no golden changes).
  const auto d = convert_text(
      R"({"bezcam": 1, "tolerance": 0.01, "entities": [{"type": "bezier", "points": [[0,0],[10,20],[20,0]]}]})",
      "generic");
  EXPECT_EQ(d.program.decimals, 3);
}

TEST(MachineProfile, MaxDecimalsBelowTheDecimalsIsRefused) {
  auto e = refusal(R"({"name": "p", "decimals": {"mm": 4}, "max_decimals": {"mm": 3}})");
  EXPECT_EQ(e.where(), "p.json: max_decimals");
}

TEST(MachineProfile, GenericIsNotAMachineAndHasNoTravel) {
  // A part 100 m from the origin is a valid job for generic.
  const auto r = convert_text(
      R"({"bezcam": 1, "entities": [{"type": "bezier", "points": [[100000,0],[100010,20],[100020,0]]}]})", "generic");
  EXPECT_NE(r.gcode.find("X100020."), std::string::npos);
  // ... and refused by a machine.
  EXPECT_THROW(
      convert_text(R"({"bezcam": 1, "entities": [{"type": "bezier", "points": [[100000,0],[100010,20],[100020,0]]}]})",
                   "fanuc"),
      InputError);
}
