#include "bezcam/post/convert.hpp"

#include "bezcam/error.hpp"

namespace bezcam {

MachineProfile resolve_profile(const Job& job, const std::string& cli_machine) {
  if (!cli_machine.empty()) return load_machine_profile(cli_machine);
  if (job.machine) {
    try {
      return load_machine_profile(*job.machine);
    } catch (const InputError& e) {
      // The name came from the file, not from the command line.
      if (e.where() != "--machine") throw;
      throw InputError(e.id(), job.source + ": machine",
                       e.message() + "; fix the file's \"machine\" or override it with --machine");
    }
  }
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
