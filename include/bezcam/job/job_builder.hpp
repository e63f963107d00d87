#pragma once
/// Builds a Job from in-memory curves, for programs that use bezcam as a
/// library (a CAD system that has the geometry already, with no JSON file).
/// The result obeys the same invariants as a job read from a file: every
/// curve is built by the kernel's validating factories, and build() checks
/// what the JSON reader checks of the job as a whole.
///
///   Job job = JobBuilder("bracket")
///                 .tolerance(0.01)
///                 .feed(600).plunge_feed(200).safe_z(5).cut_z(-1)
///                 .bezier("outline", Bezier::make({{0, 0}, {10, 20}, {30, 0}}))
///                 .build();
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "bezcam/job/job.hpp"
#include "bezcam/job/text.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"

namespace bezcam {

class JobBuilder {
 public:
  /// `name` stands for the file name in messages and program headers.
  explicit JobBuilder(std::string name = "job");

  JobBuilder& units(Units u);
  /// Largest distance between the true geometry and the cut path (job
  /// units, > 0, finite); InputError otherwise.
  JobBuilder& tolerance(double t);
  /// The profile to use when the caller names none.
  JobBuilder& machine(std::string name);
  /// Job-wide cutting parameters (job units; feeds per minute).
  JobBuilder& feed(double v);
  JobBuilder& plunge_feed(double v);
  JobBuilder& safe_z(double v);
  JobBuilder& cut_z(double v);
  JobBuilder& spindle_rpm(double v);
  JobBuilder& tool(int t);
  JobBuilder& params(const JobParams& p);
  /// The job's tool table (job units), as a file's `tools` (ToolTable's
  /// entries in any order; build() sorts them and refuses a number given
  /// twice or an entry check_tool_entry() refuses, at `tools."N"`).
  JobBuilder& tools(ToolTable t);

  /// One Bézier curve (polynomial or rational) as an entity; `id` may be
  /// empty. `params` overrides the job's for this entity.
  JobBuilder& bezier(std::string id, Bezier curve, JobParams params = {});
  /// A B-spline or NURBS curve as an entity (decomposed exactly; the exact
  /// form is kept for NURBS output).
  JobBuilder& nurbs(std::string id, NurbsCurve curve, JobParams params = {});
  /// A path of Bézier segments end to end (each starts where the previous
  /// ends, within 1e-9 of the coordinates' magnitude; InputError naming
  /// `segments[i]` otherwise); `closed` joins the end to the start.
  JobBuilder& path(std::string id, std::vector<Bezier> segments, bool closed = false, JobParams params = {});
  /// One segment of a file's `path`: a Bézier, or a B-spline/NURBS (kept
  /// exactly for NURBS output; equal weights make it polynomial, as in a
  /// file).
  using PathSegment = std::variant<Bezier, NurbsCurve>;
  /// A path of Bézier and B-spline segments end to end, as a file's `path`
  /// is read (each segment within 1e-9 of where the previous ends;
  /// InputError naming `entities[i].segments[j]` otherwise).
  JobBuilder& path_segments(std::string id, std::vector<PathSegment> segments, bool closed = false,
                            JobParams params = {});
  /// The curve through `through` (2 points or more) as a file's
  /// `interpolate` entity with method "cubic-spline" reads it: a natural
  /// cubic spline, periodic when `closed`. InputError naming `entities[i]`
  /// when no such spline exists (two equal points in a row).
  JobBuilder& interpolate(std::string id, std::vector<Vec3> through, bool closed = false, JobParams params = {});
  /// A `text` entity as a file's is read, from its glyphs (a TextOutliner's
  /// answer): each glyph contour a closed path entity of type "text" with
  /// the id `ID/G` and the glyph's characters; with a side inside or
  /// outside (the text's own, else the job's as set so far) a hole of a
  /// glyph gets the other side. InputError naming `entities[i].text` when
  /// no glyph has ink.
  JobBuilder& text(std::string id, const std::vector<Glyph>& glyphs, JobParams params = {});
  /// Settings given as KEY=VALUE text (the CLI's `--set`, settings.hpp),
  /// read as a job file's top-level keys and `job` object are read: the
  /// units, tolerance, machine, cutting parameters, order. Throws
  /// settings_json()'s refusal of an unknown key, or an InputError whose
  /// place is the builder's name and the JSON path (`job.feed`), with the
  /// further refusals in Error::more().
  JobBuilder& settings(std::span<const std::pair<std::string, std::string>> settings);

  /// The job. Throws InputError (place: the builder's name and
  /// `entities[i]`) when an entity's values are invalid, no entity was
  /// added, or one tool number is given two diameters, or a tool the
  /// table lacks, or a diameter other than the table's (job_tools()).
  Job build() const;

 private:
  Job job_;
  size_t file_entities_ = 0;  // entities of the file the job stands for (a text is one)
  // Sets one optional value (checked by build(), like a file's).
  template <class T, class V>
  JobBuilder& set(std::optional<T>& field, V&& v) {
    field = std::forward<V>(v);
    return *this;
  }
  JobBuilder& entity(std::string id, std::string type, CurveGeometry g, JobParams params);
};

}  // namespace bezcam
