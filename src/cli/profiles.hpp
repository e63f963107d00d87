#pragma once
// The machine profile a command uses: found by name (BEZCAM_MACHINES, then
// beside the executable) or as a .json file, from --machine or the job's
// "machine", with the D registers of --tool-diameter added.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "bezcam/machine/machine_profile.hpp"

namespace bezcam {
struct Job;
}  // namespace bezcam

namespace bezcam::cli {

/// Loads the profile named by `--machine` (a name or a .json file); an
/// unknown name is refused naming the option.
MachineProfile load_profile_option(const std::string& machine);
/// Picks the profile: `--machine` if given, else the job's `machine`, else
/// "generic"; an unknown name from the file is refused naming its key.
MachineProfile resolve_profile(const Job& job, const std::string& cli_machine);

/// `--tool-diameter D=MM` (repeatable): the controller's D registers for
/// cutter compensation (G41/G42 D-), added to the profile's tool table.
void add_tool_diameter_option(CLI::App* s, std::vector<std::string>& values);
void apply_tool_diameters(MachineProfile& m, const std::vector<std::string>& values);

}  // namespace bezcam::cli
