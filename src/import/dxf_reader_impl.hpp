#pragma once
// The DXF reader's groups, entities and reader state (private to
// bezcam::import): dxf_reader.cpp reads curves, dxf_text.cpp texts and
// their styles.
#include <charconv>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "bezcam/error.hpp"
#include "bezcam/import/conic.hpp"
#include "bezcam/import/drawing.hpp"

namespace bezcam::import::dxf {

constexpr double kTwoPi = 2 * std::numbers::pi, kDegree = std::numbers::pi / 180;

struct Group {
  int code = 0;
  std::string value;
  size_t line = 0;  // 1-based line of the group code
};

struct Entity {
  std::string type;
  std::vector<Group> groups;
  std::vector<Entity> vertices;  // POLYLINE: its VERTEX entities
  size_t line = 0;
  std::string handle() const {
    for (const Group& g : groups)
      if (g.code == 5) return g.value;
    return {};
  }
  std::string layer() const {
    for (const Group& g : groups)
      if (g.code == 8) return g.value;
    return "0";
  }
};

struct Block {
  std::string name;
  Vec3 base;
  std::vector<Entity> entities;
};

class Reader {
 public:
  Reader(std::string_view text, std::string source) : source_(std::move(source)) { split(text); }

  [[noreturn]] void fail(ErrorId id, size_t line, const std::string& what) const {
    Place where = Place::at_file(source_);
    where.line = static_cast<long long>(line);
    throw InputError(id, std::move(where), what);
  }
  [[noreturn]] void fail(ErrorId id, const Entity& e, const Group* g, const std::string& what) const {
    const std::string h = e.handle();
    std::string where = e.type + (h.empty() ? "" : " (handle " + h + ")");
    if (g)
      where += ", group code " + std::to_string(g->code) + " on line " + std::to_string(g->line);
    else
      where += " on line " + std::to_string(e.line);
    throw InputError(id, Place::at_file(source_), where + ": " + what);
  }

  double number(const Entity& e, const Group& g) const {
    double v = 0;
    const char* b = g.value.data();
    const char* end = b + g.value.size();
    const auto r = std::from_chars(b, end, v);
    if (r.ec != std::errc() || r.ptr != end) {
      if (g.value == "nan" || g.value == "NaN" || g.value == "inf" || g.value == "-inf")
        fail(errc::import_not_finite, e, &g, "expected a finite number, found " + g.value);
      fail(errc::import_dxf_syntax, e, &g, "expected a number, found \"" + g.value + "\"");
    }
    if (!std::isfinite(v)) fail(errc::import_not_finite, e, &g, "expected a finite number, found " + g.value);
    return v;
  }
  // The first value of `code`, or `dflt`.
  double num(const Entity& e, int code, double dflt = 0) const {
    for (const Group& g : e.groups)
      if (g.code == code) return number(e, g);
    return dflt;
  }
  Vec3 vec(const Entity& e, int code, Vec3 dflt = {}) const {
    return {num(e, code, dflt.x), num(e, code + 10, dflt.y), num(e, code + 20, dflt.z)};
  }
  // An integer group (flags, degree): a whole number in [lo, hi].
  int integer(const Entity& e, int code, int dflt, int lo = 0, int hi = 1 << 30) const {
    for (const Group& g : e.groups)
      if (g.code == code) {
        const double v = number(e, g);
        if (v != std::floor(v) || v < lo || v > hi)
          fail(errc::import_dxf_syntax, e, &g,
               "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", found " +
                   g.value);
        return static_cast<int>(v);
      }
    return dflt;
  }
  bool has(const Entity& e, int code) const {
    for (const Group& g : e.groups)
      if (g.code == code) return true;
    return false;
  }
  // Every value of `code` in order (knots, weights), or the points of
  // `code` (x), code + 10 (y), code + 20 (z).
  std::vector<double> all(const Entity& e, int code) const {
    std::vector<double> v;
    for (const Group& g : e.groups)
      if (g.code == code) v.push_back(number(e, g));
    return v;
  }
  std::vector<Vec3> points(const Entity& e, int code) const {
    std::vector<Vec3> v;
    for (const Group& g : e.groups) {
      if (g.code == code)
        v.push_back({number(e, g), 0, 0});
      else if (g.code == code + 10 && !v.empty())
        v.back().y = number(e, g);
      else if (g.code == code + 20 && !v.empty())
        v.back().z = number(e, g);
    }
    return v;
  }

  Drawing read();

 private:
  std::string source_;
  std::vector<Group> groups_;
  size_t at_ = 0;
  double unit_ = 1;  // mm per drawing unit
  std::map<std::string, Block> blocks_;
  std::vector<Entity> entities_;
  Drawing d_;
  std::vector<std::string> inserting_;  // the blocks being inserted (recursion)
  // The text styles (TABLES, STYLE), by name in upper case.
  struct Style {
    std::string file, family;
  };
  std::map<std::string, Style> styles_;

  void split(std::string_view text);
  bool at(int code, std::string_view value) const {
    return at_ < groups_.size() && groups_[at_].code == code && groups_[at_].value == value;
  }
  Entity entity();
  void header();
  void blocks();
  // One entity as contours of `layer` (placed by `m`; `id_prefix`: the
  // INSERTs it is drawn through), or counted as skipped; one function per
  // kind of entity.
  void emit(const Entity& e, const Affine& m, const std::string& layer, const std::string& id_prefix);
  void emit_line(const Entity& e, Contour c, const Affine& m);
  void emit_arc(const Entity& e, Contour c, const Affine& m, const Vec3& ext);
  void emit_ellipse(const Entity& e, Contour c, const Affine& m, const Vec3& ext);
  void emit_polyline(const Entity& e, Contour c, const Affine& m, const Vec3& ext);
  void emit_spline(const Entity& e, Contour c, const Affine& m);
  Piece spline_piece(const Entity& e, int degree, std::vector<Vec3> cps, std::vector<double> knots,
                     std::vector<double> weights) const;
  void emit_insert(const Entity& e, const Affine& m, const Vec3& ext, const std::string& layer,
                   const std::string& prefix);
  void add(Contour c, const Affine& m, const std::string& kind);
  // Texts and their styles (dxf_text.cpp).
  void tables();
  void emit_text(const Entity& e, const Affine& m, const std::string& layer, const std::string& prefix,
                 const Vec3& ext);
  [[noreturn]] void fail_text(const Entity& e, const std::string& layer, const Vec3& at, const std::string& what) const;
};

/// The arbitrary axis algorithm: the OCS of extrusion direction `n` as the
/// xy part of an affine map (elevation along `n` included).
Affine ocs(const Vec3& n, double elevation);

/// An MTEXT's string with its formatting codes resolved (dxf_text.cpp):
/// font, height, colour and other changes dropped, `\P` a line break,
/// `\~` a space, `\U+XXXX` the character, stacked fractions as `a/b`.
std::string mtext_plain(const std::string& s);
/// A TEXT's (and MTEXT's) `%%` codes: `%%c` the diameter sign, `%%d` the
/// degree sign, `%%p` plus-minus, `%%%` a percent sign, `%%nnn` the
/// character nnn; `%%u`, `%%o`, `%%k` (underline, overline, strike) left
/// out.
std::string percent_codes(const std::string& s);

}  // namespace bezcam::import::dxf
