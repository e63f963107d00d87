// bezcam lint FILE.nc [--machine NAME|FILE]: checks a G-code program against
// a machine profile. Each finding is printed as `FILE:LINE: message [id]`
// (the compiler format editors jump to). Exit 0 clean, 2 findings,
// 3 unreadable file.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
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
  s->add_option("--machine", o.machine,
                "machine profile: a name in machines/ or a .json file (default: the machine the program's header "
                "names, as bezcam writes it, else generic)");
  add_tool_diameter_option(s, o.tool_diameters);
  s->add_flag("-q,--quiet", o.quiet, "print the findings only, no summary");
  return s;
}

namespace {

// The machine a program bezcam wrote names in its first comment line
// (`(bezcam 0.1.0: part.dxf, machine linuxcnc, output lines)`, after a
// line number on Fanuc); empty when the first lines have none.
std::string header_machine(const std::string& text) {
  static const std::regex kHeader(R"(^(?:N[0-9]+ *)?\(bezcam [^:()]*: [^()]*, machine ([A-Za-z0-9_-]+), output )");
  std::istringstream in(text);
  std::string line;
  for (int k = 0; k < 5 && std::getline(in, line); ++k) {
    std::smatch mt;
    if (std::regex_search(line, mt, kHeader)) return mt[1];
  }
  return {};
}

}  // namespace

int run_lint(const LintArgs& o) {
  if (std::filesystem::is_directory(o.file))
    throw IoError(errc::io_read, Place::at_file(o.file), "is a directory, not a G-code file");
  const std::string text = read_bounded(o.file, kMaxProgramBytes, "G-code file");
  const std::string named = o.machine.empty() ? header_machine(text) : std::string();
  MachineProfile m = load_profile_option(!o.machine.empty() ? o.machine : !named.empty() ? named : "generic");
  apply_tool_diameters(m, o.tool_diameters);
  const auto findings = lint_gcode(text, m);
  for (const auto& f : findings) std::cout << o.file << ":" << f.line << ": " << f.message << " [" << f.id << "]\n";
  if (!o.quiet)
    std::cerr << "bezcam: " << o.file << ": "
              << (findings.empty() ? "no findings"
                                   : std::to_string(findings.size()) + " finding" + (findings.size() == 1 ? "" : "s"))
              << " for machine " << m.name << (named.empty() ? "" : " (named in the program's header)") << "\n";
  return findings.empty() ? exit_status::ok : exit_status::invalid;
}

}  // namespace bezcam::cli
