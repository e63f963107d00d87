#include "bezcam/post/convert.hpp"

namespace bezcam {

MachineProfile resolve_profile(const Job& job, const std::string& cli_machine) {
  if (!cli_machine.empty()) return load_machine_profile(cli_machine);
  if (job.machine) return load_machine_profile(*job.machine);
  return load_machine_profile("generic");
}

ConvertResult convert(const Job& job, const MachineProfile& m, const ConvertOptions& opt) {
  ConvertResult r;
  r.program = build_program(job, m, opt);
  validate_program(r.program, m);  // before one character is written
  r.gcode = write_gcode(r.program, m);
  return r;
}

}  // namespace bezcam
