#include "diagnostics.hpp"

#include "bezcam/error.hpp"

namespace bezcam::gcode {

void Diagnostics::fail(ErrorId id, const std::string& msg) const { throw InputError(id, Place::at_line(line), msg); }

void Diagnostics::soft(ErrorId id, const std::string& msg, int at) const {
  if (!findings) fail(id, msg);
  findings->push_back({at ? at : line, id, msg});
}

void Diagnostics::note(ErrorId id, const std::string& msg, int at) const {
  if (findings) findings->push_back({at ? at : line, id, msg});
}

}  // namespace bezcam::gcode
