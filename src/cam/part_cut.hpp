#pragma once
// Internal to cam: cutting a part (emit_part(), cut_emitters.hpp) as the
// stages of one PartCut: the side, band and passes (part_cut.cpp), the
// leads (part_leads.cpp), and the paths it measures the cut by
// (part_paths.cpp).
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bezcam/flatten/offset.hpp"
#include "bezcam/flatten/offset_measure.hpp"
#include "cut_emitters.hpp"

namespace bezcam::detail {

/// The unit tangent of `b` at `t` in XY (a chord where the derivative
/// vanishes).
Vec3 unit_tangent(const Bezier& b, double t);

/// The direction of travel where a lead joins the path at `p`: at right
/// angles to the normal from the part's nearest point to p, which points to
/// the waste when `away` is +1 (the path runs on the waste side of the part)
/// and from it when -1; the waste (+1 left, -1 right of travel) is on the
/// tool's side. Where p lies on the part (a program's path under controller
/// compensation with no offset), the path's own direction `along`.
Vec3 lead_direction(PartDistance& part, const Vec3& p, const Vec3& along, int waste, int away, double scale);

/// A quarter arc and a line on the waste side (+1 left, -1 right of
/// travel), ending at `s` along `t` (lead_in) or starting at `e` along `t`
/// (lead_out).
std::vector<Bezier> lead_in(const Vec3& s, const Vec3& t, int waste, const Lead& l);
std::vector<Bezier> lead_out(const Vec3& e, const Vec3& t, int waste, const Lead& l);

/// The printed path of moves [from, to) from `cur`, in XY, as the controller
/// draws it: lines, arcs from their printed numbers, curve blocks as their
/// Bézier pieces (Z-only moves leave nothing).
std::vector<PathPiece> printed_path(const std::vector<Move>& moves, size_t from, size_t to, Vec3 cur);

/// The tool centre's path under controller compensation (cutter_comp.hpp)
/// for the moves [from, to) of a stretch from `cur`, entered and left by the
/// leads, whose ends run along `ts` and `te`, in XY: the corners the
/// controller turns between the leads and the stretch included, the leads
/// themselves not.
std::vector<PathPiece> compensated_path(const std::vector<Move>& moves, size_t from, size_t to, Vec3 cur,
                                        const Vec3& ts, const Vec3& te, int side, double r);

/// Chords of even size along each piece, for a controller that compensates
/// the polyline (part_paths.cpp); `bound` gets their proven deviation.
std::vector<Vec3> even_chords(std::span<const Bezier> pieces, double tol, int dec, double& bound);

/// One part's cut, stage by stage. run() calls them in order; each reads
/// what the stages before it set.
struct PartCut {
  PartCut(CutContext& ctx, MotionState& motion, EntityReport& report, double safe_z, double clear_z);
  void run();

  // ---- the refusal ----
  /// Refuses, naming the key where it was set: the entity's, else the job's.
  [[noreturn]] void fail(const std::string& key, const std::string& why) const;
  /// A point for messages: `(x, y)` to 3 decimals.
  static std::string where(const Vec3& p);

  // ---- setting up (part_cut.cpp) ----
  /// A 2D curve; under controller compensation, a machine and an output
  /// that can compensate, one diameter per D register.
  void check_curve_and_controller();
  /// The tool's side of the drawn curve and the offset's radius.
  void choose_side();
  /// Climb or conventional: the part reversed where that asks.
  void choose_direction();
  /// Where the deviation may lie, the offset's fit and the band's middle.
  void choose_band();
  /// The lead used (always one under compensation) and the part sampled to
  /// check it against.
  void choose_lead();
  /// The stretches of the tool's path: the offset's chains (or the part).
  void build_chains();
  /// A closed chain with leads turned to start where a lead fits.
  std::vector<ArcSeg> start_where_lead_fits(std::vector<ArcSeg> chain);
  /// The warning and comment for material the tool cannot reach.
  void warn_material_left(const OffsetResult& o);
  /// The part's own closed edge under compensation starts mid-piece.
  void start_part_edge();
  /// The depths of the passes and the tabs' top.
  void plan_depths();

  // ---- cutting (part_cut.cpp) ----
  /// One stretch of the path as its passes cut it.
  struct Stretch {
    Vec3 s, e;                               // its ends
    Vec3 ts, te;                             // the directions its leads join it in
    std::vector<Bezier> in, out;             // its leads (none without)
    std::vector<std::vector<Bezier>> whole;  // the path as one run (passes above the tabs)
    std::vector<std::vector<Bezier>> runs;   // split at the tabs: odd runs lie on a tab
    bool tabs = false;
  };
  /// Every stretch, pass after pass.
  void cut_stretches();
  /// The lengths along a stretch `len` long from `start` where tabs start
  /// and end (none when it is too short for them, said in a warning).
  std::vector<double> tab_cuts(const Vec3& start, double len);
  /// One pass of a stretch at depths[d].
  void cut_pass(const Stretch& st, size_t d);
  /// The controller's compensation of the pass's moves from `first_move`
  /// read on its model; refused when it strays beyond the tolerance.
  void check_compensation(const Stretch& st, size_t first_move, bool last_pass);
  /// Pieces cut at z within `budget` by the output mode's emitter, as an
  /// entity of their own, from and to rest or going on from and into the
  /// tangent moves around them (`ends`); returns their proven bound.
  double cut(std::vector<Bezier> pieces, double z, double budget, CutEnds ends);
  void line_to(const Vec3& to, double feed);
  /// The proven bound and the last pass measured against the part.
  void finish();

  // ---- the leads (part_leads.cpp) ----
  /// The tool centre's lead at a path end (with the outer end of the
  /// programmed line under compensation).
  std::vector<PathPiece> lead_path(const Vec3& at, const Vec3& t, bool lead_in_end, const Lead& x) const;
  /// How much room the lead leaves (negative: it cuts into the part).
  double room(const Vec3& at, const Vec3& t, bool lead_in_end, const Lead& x);
  bool lead_fits(const Vec3& at, const Vec3& t, const Lead& x);
  /// The lead of stretch k fitted at its ends: its line made shorter, or
  /// refused, where it would cut into the part.
  Lead fit_lead(size_t k, const Stretch& st);
  /// The directions the leads of stretch k join it in, and the leads.
  void leads_of(size_t k, Stretch& st);

  CutContext& c;
  MotionState& ms;
  EntityReport& r;
  const double safe, clear;
  const Entity& ent;
  const CutParams& cp;
  const Job& job;
  Program& p;
  const int entity;

  bool controller = false;  // compensation "controller"
  double scale = 1;         // the curve's magnitude, for relative thresholds
  bool closed = false;
  double tol = 0;
  int side = 0;       // the tool relative to travel: +1 left, -1 right, 0 on
  double radius = 0;  // the offset asked: tool radius + stock to leave
  std::vector<Bezier> part;
  int dev_side = 0;       // +1: deviation only away from the part, -1: only towards it
  double fit = 0;         // the offset's fit tolerance
  double offset_by = 0;   // the band's middle
  int waste = 1;          // the waste side (+1 left, -1 right of travel)
  double tool_r = 0;      // the controller's tool radius (its D register)
  double program_by = 0;  // the program's own offset under compensation
  std::optional<Lead> lead_used;
  std::vector<std::vector<Bezier>> part_curves;
  std::optional<PartDistance> part_distance;
  double lead_budget = 0, lead_clear = 0;
  int away = 1;  // +1: the path runs on the waste side of the part
  std::vector<std::vector<Bezier>> chains;
  std::vector<bool> chain_closed;
  double fit_bound = 0;
  double out_tol = 0;  // what the offset's fit leaves of the tolerance
  std::vector<double> depths;
  double tab_top = 0;
  double tab_span = 0;  // tab width + tool diameter
  int dec = 0;
  /// Passes print the same XY numbers (only Z differs): the emitters'
  /// measurements run on the first pass and on the last (tabs split it).
  bool measure_pass = true;
  double out_bound = 0, lead_bound = 0;
  /// Under controller compensation the tool path is the controller's: its
  /// reading on bezcam's model of it (cutter_comp.hpp) joins the bound.
  double comp_reading = 0;
  /// The last pass of each stretch of the path as the tool's centre goes,
  /// and its leads.
  std::vector<PathPiece> last_path, last_leads;
};

}  // namespace bezcam::detail
