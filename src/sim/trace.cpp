#include "bezcam/sim/trace.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

namespace bezcam::sim {

std::string trace_number(double v) {
  // Fixed decimals make traces byte-comparable; "-0.000000" would differ
  // from "0.000000" for values that merely round to zero, so it is folded.
  if (!std::isfinite(v)) return v != v ? "nan" : (v > 0 ? "inf" : "-inf");
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", kTraceDecimals, v);
  std::string s(buf);
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

namespace {

std::string xyz(const Vec3& p) { return trace_number(p.x) + " " + trace_number(p.y) + " " + trace_number(p.z); }

const char* kind_name(BlockKind k) {
  switch (k) {
    case BlockKind::rapid: return "rapid";
    case BlockKind::linear: return "linear";
    case BlockKind::arc_cw: return "arc_cw";
    case BlockKind::arc_ccw: return "arc_ccw";
    case BlockKind::nurbs: return "nurbs";
    case BlockKind::bezier: return "bezier";
  }
  return "unknown";
}

// Non-empty knot spans inside the domain [u_{p}, u_{n}] of a NURBS block
// (The NURBS Book, 2.2: the curve is one polynomial piece per span).
int nonempty_spans(const MotionBlock& b) {
  const int n = static_cast<int>(b.ctrl.size());
  const int p = b.order - 1;
  if (b.knots.size() != static_cast<std::size_t>(n + b.order) || p < 0) return 1;
  int spans = 0;
  for (int i = p; i < n; ++i)
    if (b.knots[static_cast<std::size_t>(i + 1)] > b.knots[static_cast<std::size_t>(i)]) ++spans;
  return std::max(spans, 1);
}

std::string line_ref(const MotionBlock& b) {
  if (b.first_line > 0 && b.first_line != b.line)
    return "lines " + std::to_string(b.first_line) + "-" + std::to_string(b.line);
  return "line " + std::to_string(b.line);
}

}  // namespace

std::string trace_header(std::string_view machine) { return "bezcam-trace 1 machine " + std::string(machine) + "\n"; }

int trace_sample_count(const MotionBlock& b) {
  switch (b.kind) {
    case BlockKind::rapid:
    case BlockKind::linear: return 0;
    case BlockKind::arc_cw:
    case BlockKind::arc_ccw:
    case BlockKind::bezier: return kArcSamples - 1;
    case BlockKind::nurbs: return kSpanSamples * nonempty_spans(b) - 1;
  }
  return 0;
}

// The end point is exact (it is what the program printed); the samples show
// the shape between, at parameters k/(n+1) so that neither end repeats.
std::string trace_block(const MotionBlock& b) {
  std::string s = line_ref(b) + " " + kind_name(b.kind) + " to " + xyz(b.to);
  if (b.kind == BlockKind::arc_cw || b.kind == BlockKind::arc_ccw) {
    s += " center " + xyz(b.center);
    if (b.plane != Plane::xy) s += " plane G" + std::to_string(g_number(b.plane));
  }
  if (b.kind == BlockKind::nurbs || b.kind == BlockKind::bezier)
    s += " order " + std::to_string(b.order) + " points " + std::to_string(b.ctrl.size());
  if (b.kind != BlockKind::rapid) s += " feed " + trace_number(b.feed);
  s += '\n';
  const int n = trace_sample_count(b);
  for (int k = 1; k <= n; ++k) {
    const double t = static_cast<double>(k) / (n + 1);
    s += "  at " + trace_number(t) + " " + xyz(evaluate_block(b, t)) + "\n";
  }
  return s;
}

// Only what a machinist would check between moves: units, distance mode,
// tool, spindle, coolant, work offset, tool length compensation, dwells,
// program end. Feed is on each move record instead.
std::string trace_state(int line, const MachineState& a, const MachineState& b) {
  std::string s;
  const std::string at = "line " + std::to_string(line) + " ";
  if (a.units != b.units || a.units_set != b.units_set) s += at + "units " + to_string(b.units) + "\n";
  if (a.distance != b.distance)
    s += at + "distance " + (b.distance == DistanceMode::absolute ? "absolute" : "incremental") + "\n";
  if (a.tool != b.tool) s += at + "tool " + std::to_string(b.tool) + "\n";
  if (a.spindle_on != b.spindle_on || (b.spindle_on && a.spindle_rpm != b.spindle_rpm))
    s += at + (b.spindle_on ? "spindle on " + trace_number(b.spindle_rpm) : std::string("spindle off")) + "\n";
  if (a.coolant_mist != b.coolant_mist || a.coolant_flood != b.coolant_flood)
    s += at + "coolant " +
         (b.coolant_mist && b.coolant_flood ? "mist flood"
          : b.coolant_mist                  ? "mist"
          : b.coolant_flood                 ? "flood"
                                            : "off") +
         "\n";
  if (a.coord_system != b.coord_system)
    s += at + "work offset G" + std::to_string(static_cast<int>(b.coord_system)) + "\n";
  if (a.tool_length_comp != b.tool_length_comp || a.tool_length_h != b.tool_length_h)
    s += at +
         (b.tool_length_comp ? "tool length H" + std::to_string(b.tool_length_h) : std::string("tool length off")) +
         "\n";
  if (b.dwell_seconds != a.dwell_seconds) s += at + "dwell " + trace_number(b.dwell_seconds - a.dwell_seconds) + "\n";
  if (b.program_stops != a.program_stops) s += at + "program stop (the operator resumes)\n";
  if (a.program_end != b.program_end && b.program_end) s += at + "program end\n";
  return s;
}

std::string trace_alarm(int line, std::string_view code, std::string_view id, std::string_view message) {
  // One record per line: a message's own line breaks would split it.
  std::string m(message);
  for (char& c : m)
    if (c == '\n' || c == '\r') c = ' ';
  return "alarm line " + std::to_string(line) + " " + std::string(code) + " " + std::string(id) + ": " + m + "\n";
}

std::string trace_done(long lines, long blocks, const Vec3& pos) {
  return "done lines " + std::to_string(lines) + " blocks " + std::to_string(blocks) + " at " + xyz(pos) + "\n";
}

std::string trace_stock(const DexelGrid& g) {
  const DexelGrid::Deepest d = g.deepest();
  return "stock hash " + g.hash_hex() + " removed " + trace_number(g.removed_volume()) + " deepest " +
         trace_number(d.z) + " at " + trace_number(d.x) + " " + trace_number(d.y) + "\n";
}

namespace {

std::vector<std::string_view> split(std::string_view s, char sep, bool skip_empty) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i <= s.size()) {
    const auto j = s.find(sep, i);
    const auto piece = s.substr(i, j == std::string_view::npos ? std::string_view::npos : j - i);
    if (!(skip_empty && piece.empty())) out.push_back(piece);
    if (j == std::string_view::npos) break;
    i = j + 1;
  }
  return out;
}

// A token is a number only if it reads as one whole; "1-5" (a line range)
// or "arc_cw" stay words and must match exactly.
std::optional<double> as_number(std::string_view t) {
  double v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || end != t.data() + t.size()) return std::nullopt;
  return v;
}

}  // namespace

// Structure (lines, field counts, words) must match exactly; only numbers get
// the tolerance, so a changed move kind or line number is always caught.
std::optional<TraceMismatch> compare_traces(std::string_view expected, std::string_view actual, double tolerance) {
  const auto el = split(expected, '\n', false), al = split(actual, '\n', false);
  const std::size_t n = std::max(el.size(), al.size());
  for (std::size_t i = 0; i < n; ++i) {
    const std::string_view e = i < el.size() ? el[i] : std::string_view("<end of trace>");
    const std::string_view a = i < al.size() ? al[i] : std::string_view("<end of trace>");
    if (i >= el.size() || i >= al.size())
      return TraceMismatch{i + 1, std::string(e), std::string(a), "one trace is longer"};
    const auto et = split(e, ' ', true), at = split(a, ' ', true);
    if (et.size() != at.size())
      return TraceMismatch{i + 1, std::string(e), std::string(a), "different number of fields"};
    for (std::size_t k = 0; k < et.size(); ++k) {
      if (et[k] == at[k]) continue;
      // A hash's digits are no quantity: "0123..." must match exactly.
      const bool word = k > 0 && et[k - 1] == "hash";
      const auto x = word ? std::nullopt : as_number(et[k]), y = word ? std::nullopt : as_number(at[k]);
      if (x && y && std::abs(*x - *y) <= tolerance) continue;
      return TraceMismatch{i + 1, std::string(e), std::string(a),
                           "field " + std::to_string(k + 1) + ": " + std::string(et[k]) + " vs " + std::string(at[k]) +
                               (x && y ? " (differ by more than " + trace_number(tolerance) + ")" : "")};
    }
  }
  return std::nullopt;
}

}  // namespace bezcam::sim
