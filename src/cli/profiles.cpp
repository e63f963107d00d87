// Where the CLI finds machine profiles, and which one a command uses.
#include "profiles.hpp"

#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "bezcam/error.hpp"
#include "bezcam/job/job.hpp"

namespace bezcam::cli {

namespace {

// BEZCAM_MACHINES first (machine_search_path), then beside the executable:
// <exe>/../machines (the build tree: build/bezcam) and
// <exe>/../share/bezcam/machines (an installed prefix).
const std::vector<std::filesystem::path>& profile_dirs() {
  static const std::vector<std::filesystem::path> dirs = [] {
    std::vector<std::filesystem::path> beside;
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
      const auto root = exe.parent_path().parent_path();
      for (auto dir : {root / "machines", root / "share" / "bezcam" / "machines"})
        if (std::filesystem::is_directory(dir, ec)) beside.push_back(dir);
    }
    return machine_search_path(beside);
  }();
  return dirs;
}

}  // namespace

MachineProfile load_profile_option(const std::string& machine) {
  try {
    return load_machine_profile(machine, profile_dirs());
  } catch (const InputError& e) {
    if (e.id() != errc::machine_unknown) throw;
    throw InputError(e.id(), Place::at_option("--machine"), e.message());
  }
}

void add_tool_diameter_option(CLI::App* s, std::vector<std::string>& values) {
  s->add_option("--tool-diameter", values,
                "a D register for cutter compensation (G41/G42 D-): D=DIAMETER_MM, e.g. 1=6, repeatable; added to the "
                "profile's tool_diameters_mm")
      ->type_name("D=MM");
}

void apply_tool_diameters(MachineProfile& m, const std::vector<std::string>& values) {
  for (const auto& v : values) {
    const auto eq = v.find('=');
    int d = -1;
    double mm = -1;
    bool ok = eq != std::string::npos;
    if (ok) {
      const auto [e1, c1] = std::from_chars(v.data(), v.data() + eq, d);
      ok = c1 == std::errc() && e1 == v.data() + eq && d >= 0 && d <= 99999;
      char* end = nullptr;
      const std::string rhs = v.substr(eq + 1);
      mm = std::strtod(rhs.c_str(), &end);
      ok = ok && !rhs.empty() && *end == '\0' && mm >= 0 && mm < 1e4;
    }
    if (!ok)
      throw InputError(
          errc::usage_option, Place::at_option("--tool-diameter"),
          "expected D=DIAMETER_MM (a register 0 to 99999 and a diameter from 0 to 10000 mm), found \"" + v + "\"");
    m.tool_diameters_mm[d] = mm;
  }
}

MachineProfile resolve_profile(const Job& job, const std::string& cli_machine) {
  if (!cli_machine.empty()) return load_profile_option(cli_machine);
  if (job.machine) {
    try {
      return load_machine_profile(*job.machine, profile_dirs());
    } catch (const InputError& e) {
      // The name came from the file, not from the command line.
      if (e.id() != errc::machine_unknown) throw;
      throw InputError(e.id(), Place::in_json(job.source, "machine"),
                       e.message() + "; fix the file's \"machine\" or override it with --machine");
    }
  }
  return load_profile_option("generic");
}

}  // namespace bezcam::cli
