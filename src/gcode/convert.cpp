#include "bezcam/gcode/convert.hpp"


namespace bezcam {

ConvertResult convert(const Job& job, const MachineProfile& m, const ConvertOptions& opt) {
  ConvertResult r;
  r.program = build_program(job, m, opt);
  validate_program(r.program, m);  // before one character is written
  r.gcode = write_gcode(r.program, m);
  return r;
}

}  // namespace bezcam
