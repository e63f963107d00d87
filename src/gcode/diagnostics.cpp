#include "diagnostics.hpp"

#include "bezcam/error.hpp"

namespace bezcam::gcode {

void Diagnostics::fail(const std::string& id, const std::string& msg) const {
  throw InputError("gcode." + id, "line " + std::to_string(line), msg);
}

void Diagnostics::soft(const std::string& id, const std::string& msg, int at) const {
  if (!findings) fail(id, msg);
  findings->push_back({at ? at : line, "gcode." + id, msg});
}

void Diagnostics::note(const std::string& id, const std::string& msg, int at) const {
  if (findings) findings->push_back({at ? at : line, "gcode." + id, msg});
}

}  // namespace bezcam::gcode
