#pragma once
/// The machined stock compared with the part a job describes: per entity,
/// the largest gouge (material removed inside the part) and the largest
/// excess (material left where the design says it goes and the tool could
/// reach), their places and volumes (docs/verify.md, "Against the design").
///
/// The design is 2.5D, read from the job as bezcam cuts it: each curve
/// entity cut on a side (`side` inside, outside, left, right) is a wall
/// along the exact curve from `top_z` down to `cut_z`, `stock_to_leave` on
/// the waste side of it; the waste side may be cut anywhere down to `cut_z`,
/// and the band the tool sweeps along the wall (as far as a tool of its
/// radius reaches, corners sharper than the tool excepted) must be cleared
/// down to `cut_z`. A curve cut on its line (`side` on) is a groove: the
/// tool's own shape swept along the curve at `cut_z`. Entities this model
/// does not describe (surfaces, curves that are not flat) are listed as not
/// compared, with the reason. Lengths are millimetres.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "bezcam/job/job.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/stock/stock_image.hpp"
#include "bezcam/verify/stock_cutter.hpp"

namespace bezcam {

/// A place in the stock: a column's centre and the floor there (mm).
struct StockPlace {
  double x = 0, y = 0, z = 0;
};

/// What the machined stock is against one entity of the design.
struct EntityCheck {
  std::string label;      ///< the entity's id, or `entities[N]`
  std::string json_path;  ///< `entities[N]`
  bool compared = true;
  std::string not_compared;  ///< why, when not compared
  /// The largest gouge measured at a column centre (mm, >= 0), normal to
  /// the design's surface: sideways into a wall, downward into a floor.
  double gouge = 0;
  StockPlace gouge_at;
  /// True when the gouge is deeper into the part than the band examined
  /// around the walls: `gouge` is then a lower bound.
  bool gouge_at_least = false;
  std::size_t gouge_columns = 0;  ///< columns gouged beyond the tolerance
  double gouge_volume = 0;        ///< mm^3, those columns' material removed inside the part
  double excess = 0;              ///< the largest excess, measured like the gouge
  StockPlace excess_at;
  std::size_t excess_columns = 0;  ///< columns with excess beyond the tolerance
  double excess_volume = 0;        ///< mm^3, those columns' material above the design
};

struct DesignCheck {
  double tolerance = 0;     ///< the job's tolerance (mm): gouges and excess beyond it count
  double design_bound = 0;  ///< the design's walls are polylines within this of the exact curves (mm)
  std::vector<EntityCheck> entities;
  /// Gouges away from every wall (a move through the part's middle).
  EntityCheck elsewhere;
  /// One class per column (DexelGrid::floors() order), for the picture.
  std::vector<ColumnClass> classes;
  double max_gouge() const;
  /// Whether a gouge exceeds the tolerance.
  bool gouged() const { return max_gouge() > tolerance; }
};

/// Compares `grid` with `job` (its units converted to mm). `tools` gives
/// each entity's tool shape by its tool number; an entity whose number it
/// lacks is taken as a flat end mill of its `tool_diameter`.
DesignCheck check_design(const DexelGrid& grid, const Job& job, const MachineProfile& m, const StockTools& tools);

/// The tools a job cuts with, by number (mm): its `tools` table, and for a
/// number the table lacks the first entity's `tool_diameter` (a flat end
/// mill) or, for a surface cut with `tool_radius`, its ball end.
StockTools design_stock_tools(const Job& job, const MachineProfile& m);

/// The stock a job is cut from when none is given (mm): its curve
/// entities' bounds grown by the largest tool's diameter, from the highest
/// `top_z` down to 1 mm below the deepest `cut_z`; nothing when the job has
/// no curve entity (a surface's stock is the program's).
std::optional<StockBox> design_stock_box(const Job& job, const MachineProfile& m, const StockTools& tools);

}  // namespace bezcam
