#pragma once
/// The stable ids of bezcam's errors: one named constant per id.
///
/// An id is part of the library's contract: tests and scripts match on it,
/// messages may change. Every id is listed once in docs/errors.md with its
/// family, meaning and typical place (checked by the ErrorIds test). The
/// constants' names are the dotted ids with dots and dashes as underscores.
#include <string>
#include <string_view>

namespace bezcam {

/// A stable error id: a dotted name such as `job.knots-order`.
///
/// Throw sites name a constant of bezcam::errc; an id held in a string
/// (an Error's id() re-thrown with another place) converts implicitly, and
/// the ErrorId then refers to that string, which must outlive it.
class ErrorId {
 public:
  constexpr explicit ErrorId(const char* dotted) : text_(dotted) {}
  constexpr explicit ErrorId(std::string_view dotted) : text_(dotted) {}
  /// An id carried in a string, e.g. `throw InputError(e.id(), place, what)`.
  /// The ErrorId views `dotted` and must not outlive it: pass it straight to
  /// an Error (which copies the text) or compare it, never store it.
  ErrorId(const std::string& dotted) : text_(dotted) {}  // NOLINT(google-explicit-constructor)

  /// The dotted text, e.g. `job.knots-order`.
  constexpr std::string_view str() const { return text_; }
  operator std::string() const { return std::string(text_); }  // NOLINT(google-explicit-constructor)

  friend constexpr bool operator==(ErrorId a, ErrorId b) { return a.text_ == b.text_; }

 private:
  std::string_view text_;
};

namespace errc {

/// The controller stopped the program with an alarm while running it.
inline constexpr ErrorId controller_alarm{"controller.alarm"};
/// A Coons patch boundary curve has no piece.
inline constexpr ErrorId coons_boundary_empty{"coons.boundary-empty"};
/// Internal: a Coons boundary's breaks do not run from 0 to 1.
inline constexpr ErrorId coons_boundary_partition{"coons.boundary-partition"};
/// Two Coons boundary curves do not meet at their common corner.
inline constexpr ErrorId coons_corner{"coons.corner"};
/// A Coons patch boundary is not a 3D curve.
inline constexpr ErrorId coons_dimension{"coons.dimension"};
/// A B-spline degree is below 1.
inline constexpr ErrorId curve_degree{"curve.degree"};
/// A curve's degree is above what bezcam evaluates stably.
inline constexpr ErrorId curve_degree_too_high{"curve.degree-too-high"};
/// A curve mixes 2D and 3D points.
inline constexpr ErrorId curve_dimension{"curve.dimension"};
/// The interpolation system is too ill-conditioned to solve reliably.
inline constexpr ErrorId curve_ill_conditioned{"curve.ill-conditioned"};
/// A B-spline has the wrong number of knots for its points and degree.
inline constexpr ErrorId curve_knot_count{"curve.knot-count"};
/// A B-spline's domain is empty (its inner knots span no length).
inline constexpr ErrorId curve_knot_domain{"curve.knot-domain"};
/// A knot is repeated more often than the degree allows.
inline constexpr ErrorId curve_knot_multiplicity{"curve.knot-multiplicity"};
/// The knots decrease.
inline constexpr ErrorId curve_knot_order{"curve.knot-order"};
/// A coordinate or knot is not finite.
inline constexpr ErrorId curve_not_finite{"curve.not-finite"};
/// An interpolated curve passes twice through the same point in a row.
inline constexpr ErrorId curve_repeated_point{"curve.repeated-point"};
/// A curve has fewer points than it needs.
inline constexpr ErrorId curve_too_few_points{"curve.too-few-points"};
/// A Hermite curve's tangents are not one per point.
inline constexpr ErrorId curve_tangent_count{"curve.tangent-count"};
/// A rational weight is not finite or not > 0.
inline constexpr ErrorId curve_weight{"curve.weight"};
/// The number of weights differs from the number of control points.
inline constexpr ErrorId curve_weights_count{"curve.weights-count"};
/// The tolerance is not a finite number > 0.
inline constexpr ErrorId flatten_tolerance{"flatten.tolerance"};
/// The tolerance is below what doubles resolve at the curve's magnitude.
inline constexpr ErrorId flatten_tolerance_below_precision{"flatten.tolerance-below-precision"};
/// The tolerance is below what the machine's printed decimals can honour.
inline constexpr ErrorId flatten_tolerance_below_rounding{"flatten.tolerance-below-rounding"};
/// A line follows the program end (M02/M30).
inline constexpr ErrorId gcode_after_end{"gcode.after-end"};
/// An arc (G02/G03) is malformed: centre words, radius or end point.
inline constexpr ErrorId gcode_arc{"gcode.arc"};
/// An arc's end point is not on the circle of its centre.
inline constexpr ErrorId gcode_arc_radius{"gcode.arc-radius"};
/// A G5/G5.1 Bézier move is malformed.
inline constexpr ErrorId gcode_bezier{"gcode.bezier"};
/// A canned drilling cycle (G73, G81-G83) lacks a word or has an invalid one.
inline constexpr ErrorId gcode_cycle{"gcode.cycle"};
/// The machine profile does not take this word (arcs, NURBS dialect).
inline constexpr ErrorId gcode_dialect{"gcode.dialect"};
/// A dwell G04 has no duration P >= 0.
inline constexpr ErrorId gcode_dwell{"gcode.dwell"};
/// A feed rate F is negative or above the machine's maximum.
inline constexpr ErrorId gcode_feed{"gcode.feed"};
/// A feed rate above the machine's maximum (the controller's feed-limit alarm).
inline constexpr ErrorId gcode_feed_limit{"gcode.feed-limit"};
/// G91: a travel from an axis no move has set, or G53 (absolute) in G91.
inline constexpr ErrorId gcode_incremental{"gcode.incremental"};
/// A NURBS block's first or last knots are not clamped.
inline constexpr ErrorId gcode_knot_clamped{"gcode.knot-clamped"};
/// A NURBS block has the wrong number of knots.
inline constexpr ErrorId gcode_knot_count{"gcode.knot-count"};
/// A NURBS block's first line has no knot K.
inline constexpr ErrorId gcode_knot_missing{"gcode.knot-missing"};
/// A NURBS knot repeats more often than the order allows.
inline constexpr ErrorId gcode_knot_multiplicity{"gcode.knot-multiplicity"};
/// NURBS knots decrease.
inline constexpr ErrorId gcode_knot_order{"gcode.knot-order"};
/// Lint: line numbers N do not increase.
inline constexpr ErrorId gcode_line_number_order{"gcode.line-number-order"};
/// A line is longer than bezcam reads (docs/limits.md).
inline constexpr ErrorId gcode_line_too_long{"gcode.line-too-long"};
/// Two words of the same modal group on one line.
inline constexpr ErrorId gcode_modal_group{"gcode.modal-group"};
/// Lint: the first move comes before units, plane or distance mode are set.
inline constexpr ErrorId gcode_modes_unset{"gcode.modes-unset"};
/// A cutting move has no feed rate set.
inline constexpr ErrorId gcode_no_feed{"gcode.no-feed"};
/// Axis words without an active motion mode.
inline constexpr ErrorId gcode_no_motion{"gcode.no-motion"};
/// Lint: the program has no end (M02 or M30).
inline constexpr ErrorId gcode_no_program_end{"gcode.no-program-end"};
/// A number is too large to read.
inline constexpr ErrorId gcode_number{"gcode.number"};
/// Lint: a repeated NURBS knot makes the curve jump.
inline constexpr ErrorId gcode_nurbs_jump{"gcode.nurbs-jump"};
/// A word in NURBS mode outside a block.
inline constexpr ErrorId gcode_nurbs_mode{"gcode.nurbs-mode"};
/// A NURBS block is still open (at a new block, another word or the end).
inline constexpr ErrorId gcode_nurbs_open{"gcode.nurbs-open"};
/// A NURBS control point line lacks X, Y or its weight.
inline constexpr ErrorId gcode_nurbs_point{"gcode.nurbs-point"};
/// A NURBS knot or end word outside a block.
inline constexpr ErrorId gcode_nurbs_start{"gcode.nurbs-start"};
/// A word that only the first line of a NURBS block may hold.
inline constexpr ErrorId gcode_nurbs_word{"gcode.nurbs-word"};
/// A plane other than G17 (XY) is selected.
inline constexpr ErrorId gcode_plane{"gcode.plane"};
/// A move starts from a position no earlier move has set.
inline constexpr ErrorId gcode_position_unknown{"gcode.position-unknown"};
/// The program file is larger than bezcam reads (docs/limits.md).
inline constexpr ErrorId gcode_program_too_large{"gcode.program-too-large"};
/// The program has more lines than bezcam reads (docs/limits.md).
inline constexpr ErrorId gcode_program_too_long{"gcode.program-too-long"};
/// A NURBS rank (order) P is out of range.
inline constexpr ErrorId gcode_rank{"gcode.rank"};
/// Lint: a rapid move lowers Z while moving in X/Y.
inline constexpr ErrorId gcode_rapid_plunge{"gcode.rapid-plunge"};
/// The same word appears twice on a line.
inline constexpr ErrorId gcode_repeated_word{"gcode.repeated-word"};
/// A spindle speed S is negative.
inline constexpr ErrorId gcode_spindle{"gcode.spindle"};
/// Lint: a cutting move with the spindle stopped.
inline constexpr ErrorId gcode_spindle_off{"gcode.spindle-off"};
/// The line is not well-formed G-code (comments, words, numbers).
inline constexpr ErrorId gcode_syntax{"gcode.syntax"};
/// A tool number T is not a whole number in range.
inline constexpr ErrorId gcode_tool{"gcode.tool"};
/// Lint: M06 without a T word.
inline constexpr ErrorId gcode_tool_unset{"gcode.tool-unset"};
/// A move leaves the machine's travel.
inline constexpr ErrorId gcode_travel{"gcode.travel"};
/// A word has no meaning on its line.
inline constexpr ErrorId gcode_unexpected_word{"gcode.unexpected-word"};
/// G20/G21 changes the units after the first move.
inline constexpr ErrorId gcode_units_change{"gcode.units-change"};
/// Cutter radius compensation (G41/G42/G40) cannot do what the program
/// asks: no diameter for its D, an arc or a curve where a line must be, a
/// corner or arc too tight for the tool.
inline constexpr ErrorId gcode_cutter_comp{"gcode.cutter-comp"};
/// A G/M-code, axis or feature this reader does not support.
inline constexpr ErrorId gcode_unsupported{"gcode.unsupported"};
/// A NURBS weight is missing or not > 0.
inline constexpr ErrorId gcode_weight{"gcode.weight"};
/// A DXF block inserts itself, or an SVG `use` draws itself (directly or through others).
inline constexpr ErrorId import_block_recursion{"import.block-recursion"};
/// A DXF file is in binary form, which bezcam does not read.
inline constexpr ErrorId import_dxf_binary{"import.dxf-binary"};
/// A DXF file is truncated or its group codes and values are malformed.
inline constexpr ErrorId import_dxf_syntax{"import.dxf-syntax"};
/// A drawing holds no geometry bezcam can cut (after --layer).
inline constexpr ErrorId import_empty{"import.empty"};
/// A DXF spline's knots, weights or points do not make a spline (knots decrease, counts differ).
inline constexpr ErrorId import_knots{"import.knots"};
/// --layer names a layer the drawing does not have.
inline constexpr ErrorId import_layer{"import.layer"};
/// The file is not an SVG or DXF drawing (or not well-formed XML).
inline constexpr ErrorId import_not_a_drawing{"import.not-a-drawing"};
/// A coordinate of a drawing is not a finite number.
inline constexpr ErrorId import_not_finite{"import.not-finite"};
/// A --set option is not KEY=VALUE, or the job refuses its value.
inline constexpr ErrorId import_setting{"import.setting"};
/// An SVG attribute (path data, length, transform) cannot be read.
inline constexpr ErrorId import_svg_syntax{"import.svg-syntax"};
/// A drawing's text asks for what a text entity cannot be (a width factor,
/// an oblique angle, mirrored, fitted, several lines) or has no font.
inline constexpr ErrorId import_text{"import.text"};
/// A drawing's units are unknown ($INSUNITS, SVG length units, no page size).
inline constexpr ErrorId import_units{"import.units"};
/// A file cannot be read.
inline constexpr ErrorId io_read{"io.read"};
/// A file or standard output cannot be written.
inline constexpr ErrorId io_write{"io.write"};
/// The cut rises above safe_z.
inline constexpr ErrorId job_above_safe_z{"job.above-safe-z"};
/// A Coons patch blend is not linear, cubic or quintic.
inline constexpr ErrorId job_blend{"job.blend"};
/// Part cutting: a side, tool, depth, lead, tab, direction, compensation or
/// order setting that cannot be honoured for this entity.
inline constexpr ErrorId job_cut{"job.cut"};
/// A point has a different dimension than its entity's first point.
inline constexpr ErrorId job_dimension{"job.dimension"};
/// An entity type bezcam does not know.
inline constexpr ErrorId job_entity_type{"job.entity-type"};
/// The gouge policy is not "refuse" or "skip".
inline constexpr ErrorId job_gouge{"job.gouge"};
/// An unknown key within a few edits of a known one: a likely typo, refused.
inline constexpr ErrorId job_key_typo{"job.key-typo"};
/// The coolant is not "flood", "mist" or "off".
inline constexpr ErrorId job_coolant{"job.coolant"};
/// A `before` / `after` line holds a line break or an unknown placeholder.
inline constexpr ErrorId job_template{"job.template"};
/// An interpolation method bezcam does not know, or closed with the wrong method.
inline constexpr ErrorId job_method{"job.method"};
/// A required key or parameter is missing.
inline constexpr ErrorId job_missing{"job.missing"};
/// A number is not finite (or too large for a double).
inline constexpr ErrorId job_not_finite{"job.not-finite"};
/// A number that must be > 0 is not.
inline constexpr ErrorId job_not_positive{"job.not-positive"};
/// An unknown key (not a likely typo), refused: it would otherwise be ignored.
inline constexpr ErrorId job_unknown_key{"job.unknown-key"};
/// A number is outside its range.
inline constexpr ErrorId job_range{"job.range"};
/// A path segment type bezcam does not know.
inline constexpr ErrorId job_segment_type{"job.segment-type"};
/// A curve on a surface names no surface of the job.
inline constexpr ErrorId job_surface_ref{"job.surface-ref"};
/// A surface type bezcam does not know.
inline constexpr ErrorId job_surface_type{"job.surface-type"};
/// One tool number given two diameters or shapes in one job, a tool the
/// job's tool table lacks, or a table entry and a tool_diameter (or
/// tool_radius) that differ.
inline constexpr ErrorId job_tool{"job.tool"};
/// A tool table entry bezcam cannot take: a tool number that is not a
/// whole number >= 0, an unknown shape, a value the shape does not take.
inline constexpr ErrorId job_tool_table{"job.tool-table"};
/// The job file is not valid JSON.
inline constexpr ErrorId job_syntax{"job.syntax"};
/// A surface tool path pattern or direction bezcam does not know.
inline constexpr ErrorId job_toolpath{"job.toolpath"};
/// A JSON value has the wrong type.
inline constexpr ErrorId job_type{"job.type"};
/// Units are not "mm" or "inch".
inline constexpr ErrorId job_units{"job.units"};
/// A curve on a surface leaves the patch's parameter square.
inline constexpr ErrorId job_uv_range{"job.uv-range"};
/// An operation bezcam does not know, or one the entity cannot take (a
/// point that is not drilled or bored).
inline constexpr ErrorId job_operation{"job.operation"};
/// A hole that cannot be made as asked (docs/holes.md): a drill of
/// another diameter than the circle, a hole deeper than the drill's
/// flutes, a bore smaller than the tool, a curve that is not a circle.
inline constexpr ErrorId job_hole{"job.hole"};
/// A pocket that cannot be cleared as asked: an open entity, islands
/// crossing the outline, a stepover or entry that does not fit, a region
/// where the tool fits nowhere.
inline constexpr ErrorId job_pocket{"job.pocket"};
/// The job format version is not 1.
inline constexpr ErrorId job_version{"job.version"};
/// A job has more entities than bezcam reads (docs/limits.md).
inline constexpr ErrorId limit_entities{"limit.entities"};
/// A file is larger than bezcam reads (docs/limits.md).
inline constexpr ErrorId limit_file_size{"limit.file-size"};
/// A Coons patch needs more exact cells than the limit.
inline constexpr ErrorId limit_patch_cells{"limit.patch-cells"};
/// An entity has more points than the limit.
inline constexpr ErrorId limit_points{"limit.points"};
/// The program would have more lines than the limit.
inline constexpr ErrorId limit_program_length{"limit.program-length"};
/// Flattening would need more segments than the limit.
inline constexpr ErrorId limit_segments{"limit.segments"};
/// The tolerance is below what doubles resolve at the job's coordinates.
inline constexpr ErrorId limit_tolerance_precision{"limit.tolerance-precision"};
/// Simulated controller: the sender aborted the transfer.
inline constexpr ErrorId link_aborted{"link.aborted"};
/// The sender was interrupted (Ctrl-C, SIGTERM) and aborted the transfer.
inline constexpr ErrorId link_cancelled{"link.cancelled"};
/// The program has lint findings for the profile the controller enforces: not sent.
inline constexpr ErrorId link_preflight{"link.preflight"};
/// The controller acknowledged other bytes than were sent.
inline constexpr ErrorId link_ack{"link.ack"};
/// The controller is busy with another sender's program.
inline constexpr ErrorId link_busy{"link.busy"};
/// The connection to the controller cannot be made or used.
inline constexpr ErrorId link_connection{"link.connection"};
/// Simulated controller: the program's CRC-32 differs from the sender's.
inline constexpr ErrorId link_crc_mismatch{"link.crc-mismatch"};
/// The program to send is empty.
inline constexpr ErrorId link_empty{"link.empty"};
/// An endpoint is not HOST:PORT.
inline constexpr ErrorId link_endpoint{"link.endpoint"};
/// Simulated controller: the received length differs from the sender's.
inline constexpr ErrorId link_length_mismatch{"link.length-mismatch"};
/// The connection was lost and could not be restored.
inline constexpr ErrorId link_lost{"link.lost"};
/// The program to send holds a NUL byte.
inline constexpr ErrorId link_nul_byte{"link.nul-byte"};
/// The sender's timeouts or retries are out of range.
inline constexpr ErrorId link_options{"link.options"};
/// The server does not speak the bezcam program protocol.
inline constexpr ErrorId link_protocol{"link.protocol"};
/// The controller refused a request.
inline constexpr ErrorId link_refused{"link.refused"};
/// Internal: a register request outside Modbus limits.
inline constexpr ErrorId link_request{"link.request"};
/// The controller no longer holds this transfer.
inline constexpr ErrorId link_restarted{"link.restarted"};
/// Simulated controller: the sender was silent longer than the session timeout.
inline constexpr ErrorId link_sender_lost{"link.sender-lost"};
/// The controller took no byte and executed no line for too long.
inline constexpr ErrorId link_stalled{"link.stalled"};
/// The program to send is larger than the protocol takes.
inline constexpr ErrorId link_too_large{"link.too-large"};
/// The controller speaks another protocol version.
inline constexpr ErrorId link_version{"link.version"};
/// A machine profile value is invalid.
inline constexpr ErrorId machine_invalid{"machine.invalid"};
/// An unknown key of a machine profile within a few edits of a known one: refused.
inline constexpr ErrorId machine_key_typo{"machine.key-typo"};
/// An unknown key of a machine profile (not a likely typo): refused.
inline constexpr ErrorId machine_unknown_key{"machine.unknown-key"};
/// A machine profile's name is not its file's name.
inline constexpr ErrorId machine_name{"machine.name"};
/// A template of a machine profile names a placeholder it does not have (`{rmp}`).
inline constexpr ErrorId machine_placeholder{"machine.placeholder"};
/// A machine profile is not valid JSON.
inline constexpr ErrorId machine_syntax{"machine.syntax"};
/// No machine profile of that name or file.
inline constexpr ErrorId machine_unknown{"machine.unknown"};
/// A Bézier patch's degree is above what bezcam evaluates stably.
inline constexpr ErrorId patch_degree_too_high{"patch.degree-too-high"};
/// A patch coordinate is not finite.
inline constexpr ErrorId patch_not_finite{"patch.not-finite"};
/// A patch's rows of points differ in length.
inline constexpr ErrorId patch_row_length{"patch.row-length"};
/// A patch row has fewer than 2 points.
inline constexpr ErrorId patch_too_few_points{"patch.too-few-points"};
/// A patch has fewer than 2 rows.
inline constexpr ErrorId patch_too_few_rows{"patch.too-few-rows"};
/// A patch weight is not finite or not > 0.
inline constexpr ErrorId patch_weight{"patch.weight"};
/// A patch's weights do not match its points.
inline constexpr ErrorId patch_weights_shape{"patch.weights-shape"};
/// A path segment does not start where the previous one ends.
inline constexpr ErrorId path_joint{"path.joint"};
/// A path marked closed does not end at its start.
inline constexpr ErrorId path_not_closed{"path.not-closed"};
/// The deviation view cannot be drawn for this input.
inline constexpr ErrorId preview_deviation{"preview.deviation"};
/// Nothing to draw.
inline constexpr ErrorId preview_empty{"preview.empty"};
/// The deviation view needs a tolerance > 0.
inline constexpr ErrorId preview_tolerance{"preview.tolerance"};
/// The program's units differ from the job's.
inline constexpr ErrorId preview_units{"preview.units"};
/// The program has arcs but the machine does not take them.
inline constexpr ErrorId program_arcs{"program.arcs"};
/// A feed rate exceeds the machine's maximum.
inline constexpr ErrorId program_feed{"program.feed"};
/// A rapid move would cross the part below safe Z.
inline constexpr ErrorId program_rapid_below_safe_z{"program.rapid-below-safe-z"};
/// The tool path leaves the machine's travel.
inline constexpr ErrorId program_travel{"program.travel"};
/// Resume from a line: the modal state before the line cannot be known (the reader refuses an earlier line).
inline constexpr ErrorId resume_state_unknown{"resume.state-unknown"};
/// Resume from a line: the line comes after the program's end (M02/M30).
inline constexpr ErrorId resume_after_end{"resume.after-end"};
/// Resume from a line: the line holds no block (blank, comment, % or O-number line).
inline constexpr ErrorId resume_no_code{"resume.no-code"};
/// Resume from a line: the line is not in the program (beyond its end).
inline constexpr ErrorId resume_no_line{"resume.no-line"};
/// Resume from a line: the safe height or plunge feed is missing, not valid, or refused by the profile.
inline constexpr ErrorId resume_setting{"resume.setting"};
/// Simulate: the simulated controller stopped with alarm aborted.
inline constexpr ErrorId sim_aborted{"sim.aborted"};
/// The simulated controller is receiving a streamed transfer.
inline constexpr ErrorId sim_busy{"sim.busy"};
/// A setting of the simulated controller or server is out of range.
inline constexpr ErrorId sim_config{"sim.config"};
/// Simulate: the simulated controller stopped with alarm crc-mismatch.
inline constexpr ErrorId sim_crc_mismatch{"sim.crc-mismatch"};
/// A fault injection is not well-formed.
inline constexpr ErrorId sim_fault{"sim.fault"};
/// Simulate: the simulated controller stopped with alarm feed-limit.
inline constexpr ErrorId sim_feed_limit{"sim.feed-limit"};
/// Simulate: the simulated controller stopped with alarm gcode.
inline constexpr ErrorId sim_gcode{"sim.gcode"};
/// Simulate: the simulated controller stopped with alarm incomplete.
inline constexpr ErrorId sim_incomplete{"sim.incomplete"};
/// Simulated controller: the interpreter failed unexpectedly (a bug).
inline constexpr ErrorId sim_internal{"sim.internal"};
/// Simulate: the simulated controller stopped with alarm length-mismatch.
inline constexpr ErrorId sim_length_mismatch{"sim.length-mismatch"};
/// A line is longer than the simulated controller's receive buffer.
inline constexpr ErrorId sim_line_too_long{"sim.line-too-long"};
/// The simulated controller's server cannot listen.
inline constexpr ErrorId sim_listen{"sim.listen"};
/// Simulate: the machine profile has no motion model to plan with.
inline constexpr ErrorId sim_no_motion_model{"sim.no-motion-model"};
/// The program run by the simulated controller holds a NUL byte.
inline constexpr ErrorId sim_nul_byte{"sim.nul-byte"};
/// Simulate: the simulated controller stopped with alarm sender-lost.
inline constexpr ErrorId sim_sender_lost{"sim.sender-lost"};
/// The program is larger than the simulated controller takes.
inline constexpr ErrorId sim_too_large{"sim.too-large"};
/// Simulate: the simulated controller stopped with alarm travel-limit.
inline constexpr ErrorId sim_travel_limit{"sim.travel-limit"};
/// Simulate needs a server address or a program.
inline constexpr ErrorId sim_usage{"sim.usage"};
/// A stock box is empty, inverted or not finite.
inline constexpr ErrorId stock_box{"stock.box"};
/// A stock's cell size is not a finite number > 0.
inline constexpr ErrorId stock_cell{"stock.cell"};
/// A stock grid would need more memory than the limit.
inline constexpr ErrorId stock_memory{"stock.memory"};
/// A move to sweep through the stock is malformed (not finite, an arc without radius, a polyline without points).
inline constexpr ErrorId stock_move{"stock.move"};
/// A tool's shape or dimensions are not valid (diameter, corner radius, angle).
inline constexpr ErrorId tool_shape{"tool.shape"};
/// Verify: the stock box holds no part of the program's cutting moves.
inline constexpr ErrorId verify_stock_outside{"verify.stock-outside"};
/// Verify: a block cuts with a tool the tools table lacks.
inline constexpr ErrorId verify_tool{"verify.tool"};
/// Verify: the program moves no tool at a feed (nothing to machine).
inline constexpr ErrorId verify_empty{"verify.empty"};
/// The tool would gouge the surface.
inline constexpr ErrorId surface_gouge{"surface.gouge"};
/// The surface normal vanishes (a degenerate patch).
inline constexpr ErrorId surface_normal_undefined{"surface.normal-undefined"};
/// A text entity's text is empty or only spaces.
inline constexpr ErrorId text_empty{"text.empty"};
/// A text's font family is not installed (fontconfig would substitute another).
inline constexpr ErrorId text_font{"text.font"};
/// A text's font file is missing or is not a font FreeType reads.
inline constexpr ErrorId text_font_file{"text.font-file"};
/// A text has a character its font has no glyph for.
inline constexpr ErrorId text_glyph{"text.glyph"};
/// A job with text was read without a text outliner (a library caller's).
inline constexpr ErrorId text_unavailable{"text.unavailable"};
/// A stepover is too small for the tolerance.
inline constexpr ErrorId toolpath_stepover{"toolpath.stepover"};
/// A surface needs more passes than the limit.
inline constexpr ErrorId toolpath_too_many_passes{"toolpath.too-many-passes"};
/// A program option (--return-to, --origin, --preamble, ...) that cannot be read.
inline constexpr ErrorId usage_option{"usage.option"};
/// An output mode the machine or command does not take.
inline constexpr ErrorId usage_output{"usage.output"};
/// Preview options that do not go together.
inline constexpr ErrorId usage_preview{"usage.preview"};
/// The report would overwrite the program.
inline constexpr ErrorId usage_report{"usage.report"};
/// A --set names a key the job does not have.
inline constexpr ErrorId usage_setting{"usage.setting"};
/// --strict: a warning, taken as an error.
inline constexpr ErrorId usage_strict{"usage.strict"};
/// stream: a program file with --abort, or none without it.
inline constexpr ErrorId usage_stream{"usage.stream"};

}  // namespace errc
}  // namespace bezcam
