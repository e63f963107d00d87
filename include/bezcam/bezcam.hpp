#pragma once
/// bezcam as a library: this header re-exports the public API, folder by
/// folder, in the order data walks through it (docs/architecture.md). Link
/// `bezcam::bezcam` for all of it, or one part (`bezcam::kernel`,
/// `bezcam::flatten`, ...) and include that part's headers directly.
#include "bezcam/error.hpp"
#include "bezcam/limits.hpp"
#include "bezcam/version.hpp"

// kernel/: exact geometry
#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/bezier_patch.hpp"
#include "bezcam/kernel/coons_patch.hpp"
#include "bezcam/kernel/curve.hpp"
#include "bezcam/kernel/knot_vector.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"
#include "bezcam/kernel/spline_interp.hpp"
#include "bezcam/kernel/surface.hpp"
#include "bezcam/kernel/units.hpp"
#include "bezcam/kernel/vec.hpp"

// flatten/: proven approximations
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/degree_reduce.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/exact_blocks.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tip_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"

// job/: the job model, its JSON reader, the in-memory builder, tool tables
#include "bezcam/job/job.hpp"
#include "bezcam/job/job_builder.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/job/text.hpp"
#include "bezcam/job/tool_table.hpp"

// import/: SVG and DXF drawings read exactly, as jobs
#include "bezcam/import/conic.hpp"
#include "bezcam/import/drawing.hpp"
#include "bezcam/import/dxf_reader.hpp"
#include "bezcam/import/read_drawing.hpp"
#include "bezcam/import/svg_reader.hpp"

// text/: text from fonts, the glyphs' own Béziers
#include "bezcam/text/font_text.hpp"

// machine/: the controller's model: profiles, motion blocks, cutter
// compensation, the planner
#include "bezcam/machine/cutter_comp.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/machine/motion.hpp"
#include "bezcam/machine/planner.hpp"

// cam/: the canonical program, passes, validation
#include "bezcam/cam/gouge.hpp"
#include "bezcam/cam/pass_plan.hpp"
#include "bezcam/cam/pocket_check.hpp"
#include "bezcam/cam/program.hpp"
#include "bezcam/cam/program_limits.hpp"
#include "bezcam/cam/program_motion.hpp"
#include "bezcam/cam/validate.hpp"

// gcode/: text in the profile's dialect, and back
#include "bezcam/gcode/best_output.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/lint.hpp"
#include "bezcam/gcode/number_format.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/gcode/writer.hpp"

// report/: what a program does, and how it looks
#include "bezcam/report/preview_svg.hpp"
#include "bezcam/report/report.hpp"

#if defined(BEZCAM_HAS_MODBUS)
// link/: Modbus TCP transport and sender; sim/: the simulated controller
#include "bezcam/link/crc32.hpp"
#include "bezcam/link/register_map.hpp"
#include "bezcam/link/streamer.hpp"
#include "bezcam/link/transport.hpp"
#include "bezcam/sim/sim_controller.hpp"
#include "bezcam/sim/sim_server.hpp"
#include "bezcam/sim/trace.hpp"
#endif
