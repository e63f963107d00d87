#pragma once
/// A picture of a job and its tool path, as a self-contained SVG document
/// (viewBox, no scripts, no external fonts or images: it opens in any
/// browser): the true curves sampled from their exact Bézier pieces, their
/// control polygons and points, the tool path with feeds solid and rapids
/// dashed, entity ids, start points and directions, a scale bar and the
/// units. A top view always; an isometric view as well when the job has 3D
/// entities or the tool path cuts in 3D. Surfaces are drawn as iso-parameter
/// lines (11 each way, borders heavier) with the control nets of their
/// cells; a curve on a surface as its exact composition with the surface.
/// Optionally every cutting block of a curve is coloured by its measured
/// deviation from the true geometry (surface passes are drawn, not measured).
///
/// Element classes (stable, for tests and for styling): `view` groups with
/// ids `top-view` / `iso-view`; per entity a group `entity` (data-entity =
/// index, data-id = id) holding `curve`, `control-polygon`,
/// `control-point`, `start-point`, `direction-arrow`, `entity-label`; the
/// tool path group `toolpath` holding `feed` and `rapid` paths (feeds carry
/// data-deviation in deviation mode); part cutting adds `swept` (the tool's
/// width along an entity's deepest pass), `tab` marks (where a pass rises
/// over a holding tab) and `material-left` (curve the tool cannot reach);
/// `scale-bar`; `legend`.
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "bezcam/cam/program.hpp"
#include "bezcam/flatten/offset.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/machine/motion.hpp"
#include "bezcam/machine/planner.hpp"

namespace bezcam {

/// Progress callback: (entities done, total, label of the next one).
using EntityProgress = std::function<void(size_t done, size_t total, const std::string& label)>;

struct PreviewOptions {
  bool control = true;     ///< draw control polygons and points
  bool deviation = false;  ///< colour cutting blocks by deviation (needs a job)
  double width = 1200;     ///< width of the drawing in CSS pixels (>= 400)
  /// Called before each entity's deviation is measured (the slow part)
  /// with (entities done, total, label), and with (total, total, "") at the
  /// end. May be empty.
  EntityProgress on_entity;
};

/// Part cutting, for measuring (PreviewInput::parts, block_deviations()):
/// how far from each entity's curve its path is meant to be, and which
/// blocks lead the tool in and out.
struct PartPaths {
  /// Index = entity: the tool centre's distance from the curve
  /// (EntityReport::offset); 0 or absent: cut on the curve.
  std::vector<double> offset;
  /// Index = motion block: 1 for the blocks of a lead in or out
  /// (EntityReport::lead_moves), measured when built, not here.
  std::vector<char> lead;
};

struct PreviewInput {
  /// The true geometry; null when only a program is drawn.
  const Job* job = nullptr;
  /// The tool path (a built program's motion, or a G-code file's).
  std::vector<MotionBlock> motion;
  /// The motion planned on the machine's model (preview by feed); its
  /// blocks are `motion`'s, in order. Null when not coloured by feed.
  const MotionPlan* plan = nullptr;
  std::string machine;  ///< the profile the plan is for (the legend names it)
  Units units = Units::mm;
  /// Top of the deviation colour scale (units, > 0 when deviation is on):
  /// the tolerance the program promises.
  double tolerance = 0;
  /// The program's own measured deviation (Program::max_measured) when the
  /// preview draws a program it built: the legend gives it for what the
  /// preview does not measure itself (surface passes). Negative: unknown.
  double program_measured = -1;
  /// The tool of each entity (index = entity, -1 unknown), for the labels.
  std::vector<int> entity_tool;
  /// Part cutting (index = entity; empty: none): the tool's radius, whose
  /// swept width is drawn under the entity's deepest pass, and the
  /// stretches of the curve the tool cannot reach (material left).
  std::vector<double> entity_tool_radius;
  std::vector<std::vector<MaterialLeft>> entity_left;
  PartPaths parts;                    ///< offsets and leads, for deviation colouring
  std::string title;                  ///< first header line
  std::vector<std::string> notes;     ///< further header lines
  std::vector<std::string> warnings;  ///< drawn in red under the header
};

/// The colour of a cutting block with deviation `d` under tolerance `tol`
/// (`#rrggbb`): within the tolerance a sequential scale from dark blue (0)
/// through teal to green (the tolerance), so a program using 97 % of its
/// tolerance does not look alarming; above it the alarm red `#ff0000`,
/// which the scale never approaches (such blocks are also drawn wider and
/// ringed).
std::string preview_deviation_colour(double d, double tol);

/// The colour of an achieved feed `f` on a scale up to `top` (`#rrggbb`):
/// a sequential scale from dark purple (standing still) through blue and
/// green to yellow (the top feed), legible for colour-blind readers.
std::string preview_feed_colour(double f, double top);

/// A cutting block's deviation from the true geometry: the larger of the
/// block's distance to the curve and the distance of the stretch of curve
/// it cuts to the block. `entity`: the entity measured against (the
/// block's own, or the nearest when the motion has no entity tags).
struct BlockDeviation {
  size_t block = 0;  ///< index in the motion
  int entity = -1;
  double deviation = 0;
};

/// Measures every cutting block of `motion` (feed blocks other than
/// plunges: a feed straight down after a rapid) against the curves of
/// `job`: 2D entities in the XY plane (the tool cuts them at cut_z), 3D
/// entities in space. The curve is sampled densely (flattened with a
/// certified bound of tolerance / 1000) and each block at 16 points per
/// line and finer along curved blocks, so the figures are accurate to about
/// 0.2 % of `tolerance`; the largest of them agrees with the program's
/// measured deviation (deviation.hpp) to that accuracy. Blocks of entities
/// without curves (surfaces) are left out.
///
/// A part cut beside its curve (`parts.offset` > 0 for its entity) is
/// measured against the exact offset instead: each point of a block at
/// its distance from the curve (the nearest point of the exact curve,
/// offset_measure.hpp) less the offset, which is never more than its
/// distance from the exact offset curve and equal to it wherever the tool
/// reaches the curve; its leads (`parts.lead`) are left out. Without
/// `parts` (a program read from text), such parts are left out.
std::vector<BlockDeviation> block_deviations(const Job& job, std::span<const MotionBlock> motion, double tolerance,
                                             const EntityProgress& on_entity = {}, const PartPaths& parts = {});

/// The SVG document. Throws InputError when there is nothing to draw (no
/// entities and no motion) or when deviation colouring is asked for without
/// a job or a tolerance.
std::string preview_svg(const PreviewInput& in, const PreviewOptions& opt);

/// Fills the part-cutting fields of `in` (tool widths, material left,
/// offsets, the blocks of leads) from a built program's reports;
/// `entities`: the job's entity count; `in.motion` must be the program's
/// motion (program_motion()).
void add_part_cutting(PreviewInput& in, const Program& p, size_t entities);

}  // namespace bezcam
