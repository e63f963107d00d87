// Where the CLI finds machine profiles, and which one a command uses.
#include <filesystem>
#include <iostream>
#include <system_error>

#include "bezcam/cam/machine_profile.hpp"
#include "bezcam/error.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/job_json.hpp"
#include "command.hpp"

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
    MachineProfile m = load_machine_profile(machine, profile_dirs());
    print_warnings(m.warnings);
    return m;
  } catch (const InputError& e) {
    if (e.id() != errc::machine_unknown) throw;
    throw InputError(e.id(), Place::at_option("--machine"), e.message());
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
      throw InputError(e.id(), job.source + ": machine",
                       e.message() + "; fix the file's \"machine\" or override it with --machine");
    }
  }
  return load_profile_option("generic");
}

}  // namespace bezcam::cli

namespace bezcam::cli {

void print_warnings(const std::vector<std::string>& warnings) {
  for (const auto& w : warnings) std::cerr << "bezcam: warning: " << w << "\n";
}

Job read_job(const std::string& path, bool strict) {
  std::vector<std::string> warnings;
  JobReadOptions ro;
  ro.strict = strict;
  ro.warnings = &warnings;
  try {
    return load_job(path, ro);
  } catch (const Error&) {
    print_warnings(warnings);
    throw;
  }
}

}  // namespace bezcam::cli
