// bezcam lint FILE.nc [--machine NAME|FILE]: checks a G-code program against
// a machine profile. Each finding is printed as `FILE:LINE: message [id]`
// (the compiler format editors jump to). Exit 0 clean, 2 findings,
// 3 unreadable file.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "bezcam/error.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/limits.hpp"
#include "commands.hpp"
#include "exit_status.hpp"
#include "profiles.hpp"

namespace bezcam::cli {

CLI::App* setup_lint(CLI::App& app, LintArgs& o) {
  auto* s = app.add_subcommand("lint",
                               "Check a G-code program against a machine profile: syntax, NURBS block rules "
                               "(knot order, counts, clamping, weights), arcs valid after rounding, travel "
                               "limits, feeds. Exit 0 clean, 2 findings, 3 unreadable file.");
  s->add_option("FILE", o.file, "G-code program")->required();
  s->add_option("--machine", o.machine, "machine profile: a name in machines/ or a .json file (default: generic)");
  add_tool_diameter_option(s, o.tool_diameters);
  s->add_flag("-q,--quiet", o.quiet, "print the findings only, no summary");
  return s;
}

int run_lint(const LintArgs& o) {
  MachineProfile m = load_profile_option(o.machine);
  apply_tool_diameters(m, o.tool_diameters);
  if (std::filesystem::is_directory(o.file))
    throw IoError(errc::io_read, Place::at_file(o.file), "is a directory, not a G-code file");
  const auto findings = lint_gcode(read_bounded(o.file, kMaxProgramBytes, "G-code file"), m);
  for (const auto& f : findings) std::cout << o.file << ":" << f.line << ": " << f.message << " [" << f.id << "]\n";
  if (!o.quiet)
    std::cerr << "bezcam: " << o.file << ": "
              << (findings.empty() ? "no findings"
                                   : std::to_string(findings.size()) + " finding" + (findings.size() == 1 ? "" : "s"))
              << " for machine " << m.name << "\n";
  return findings.empty() ? exit_status::ok : exit_status::invalid;
}

}  // namespace bezcam::cli
