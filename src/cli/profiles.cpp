#include <charconv>
#include <cstdlib>
// Where the CLI finds machine profiles, and which one a command uses.
#include <filesystem>
#include <iostream>
#include <system_error>

#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/error.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/job/settings.hpp"
#include "bezcam/import/read_drawing.hpp"
#include "command.hpp"
#include "options.hpp"

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
      throw InputError(errc::usage_option, Place::at_option("--tool-diameter"),
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

Job read_job(const std::string& path) {
  std::vector<std::string> warnings;
  JobReadOptions ro;
  ro.warnings = &warnings;
  try {
    return load_job(path, ro);
  } catch (const Error&) {
    print_warnings(warnings);
    throw;
  }
}

namespace {
// KEY=VALUE of --set.
std::pair<std::string, std::string> split_setting(const std::string& kv) {
  const size_t eq = kv.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(errc::import_setting, Place::at_option("--set"),
                     "expected KEY=VALUE (for example --set feed=600), found \"" + kv + "\"");
  return {kv.substr(0, eq), kv.substr(eq + 1)};
}
}  // namespace

import::ImportOptions import_options(const ConversionOptions& o) {
  import::ImportOptions io;
  for (const auto& kv : o.sets) io.settings.push_back(split_setting(kv));
  // Keys and values checked before the drawing is read: an unknown key is
  // a mistake on the command line, whatever the drawing holds.
  (void)settings_json(io.settings);
  io.layers = o.layers;
  return io;
}

Job read_job(const std::string& path, const ConversionOptions& o, import::Drawing* drawing) {
  if (!import::is_drawing(path)) {
    if (!o.sets.empty() || !o.layers.empty())
      throw InputError(errc::import_setting, Place::at_option(o.sets.empty() ? "--layer" : "--set"),
                       path + " is a job file, which states its own settings and has no layers; --set and --layer "
                              "apply to drawings (.svg, .dxf)");
    return read_job(path);
  }
  const import::ImportOptions io = import_options(o);
  import::Drawing d = import::read_drawing(path);
  if (drawing) *drawing = d;
  std::vector<std::string> warnings;
  try {
    Job job = import::to_job(d, io, &warnings);
    return job;
  } catch (const Error&) {
    print_warnings(warnings);
    throw;
  }
}

}  // namespace bezcam::cli
