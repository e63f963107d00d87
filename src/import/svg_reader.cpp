// SVG through SVG++ (header-only) over libxml2. SVG++ hands over each
// path command as written (policy::path::raw: relative, shorthands and arcs
// untouched), converts shapes to the same commands (with arcs, never cubic
// approximations), merges each element's `transform` into one matrix, and
// turns the outermost viewport (width, height, viewBox) into a transform.
// Everything else here is done in double precision on the control points.
#include "bezcam/import/svg_reader.hpp"

#include <algorithm>
#include <boost/mpl/fold.hpp>
#include <boost/mpl/insert.hpp>
#include <boost/mpl/joint_view.hpp>
#include <boost/mpl/protect.hpp>
#include <boost/mpl/set.hpp>
#include <cmath>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <svgpp/policy/xml/libxml2.hpp>
#include <svgpp/svgpp.hpp>

#include "bezcam/error.hpp"
#include "bezcam/import/conic.hpp"
#include "bezcam/limits.hpp"

namespace bezcam::import {
namespace {

namespace tag = svgpp::tag;
constexpr double kMmPerPx = 25.4 / 96;

std::string name_of(const xmlNode* n) { return n && n->name ? reinterpret_cast<const char*>(n->name) : "?"; }
std::string attr_of(const xmlNode* n, const char* a) {
  if (!n) return {};
  xmlChar* v = xmlGetProp(n, reinterpret_cast<const xmlChar*>(a));
  if (!v) return {};
  std::string s(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return s;
}
long line_of(const xmlNode* n) { return n ? xmlGetLineNo(n) : 0; }
// `<path id="logo"> (line 4)`, for messages.
std::string describe(const xmlNode* n) {
  if (!n) return "the document";
  const std::string id = attr_of(n, "id");
  return "<" + name_of(n) + (id.empty() ? "" : " id=\"" + id + "\"") + "> on line " + std::to_string(line_of(n));
}

// What the whole traversal shares: the output, the element being read (for
// messages), the page.
struct Shared {
  std::string source;
  Drawing* out = nullptr;
  const xmlNode* current = nullptr;
  double page_h_px = 0;  // the outermost viewport's height
  bool have_page = false;
  double ref_w = 0, ref_h = 0;                  // reference viewport when the root has no width/height
  std::map<std::string, int> id_uses;           // ids given out, to keep them unique
  std::map<std::string, const xmlNode*> by_id;  // every element with an id, for `use`
  std::vector<const xmlNode*> using_;           // the `use` elements being expanded, outermost first
  size_t instances = 0;                         // elements drawn through `use`
  [[noreturn]] void fail(ErrorId id, const std::string& what) const {
    throw InputError(id, Place::at_file(source), describe(current) + ": " + what);
  }
};

struct Context;
// Draws the element a `use` references as its child (after the traversal's
// type is known).
void load_used(const xmlNode* target, Context& use);

struct Context {
  // The document's context: a root without width or height takes them
  // from its viewBox (100 % of the reference viewport), not from SVG++'s
  // default viewport of 500 x 500.
  explicit Context(Shared& s) : s_(&s) {
    if (s.ref_w > 0 && s.ref_h > 0) lengths_.set_viewport_size(s.ref_w, s.ref_h);
  }
  Context(Context& parent, const xmlNode* node)
      : s_(parent.s_),
        ctm_(parent.ctm_),
        lengths_(parent.lengths_),
        node_(node),
        depth_(parent.depth_ + 1),
        id_(attr_of(node, "id")),
        prefix_(parent.prefix_),
        via_(parent.via_) {
    s_->current = node;
  }

  // ---- lengths: user units (px at 96 per inch), percentages of the viewport
  using length_factory_type = svgpp::factory::length::unitless<>;
  const length_factory_type& length_factory() const { return lengths_; }

  // ---- transforms (the element's `transform`, and the viewport's)
  void transform_matrix(const boost::array<double, 6>& m) {
    ctm_ = ctm_.after(Affine{m[0], m[1], m[2], m[3], m[4], m[5]});
  }
  void transform_translate(double tx, double ty) { ctm_ = ctm_.after(Affine{1, 0, 0, 1, tx, ty}); }
  void transform_scale(double sx, double sy) { ctm_ = ctm_.after(Affine{sx, 0, 0, sy, 0, 0}); }

  // ---- viewport (svg elements)
  void set_viewport(double, double, double w, double h) {
    lengths_.set_viewport_size(w, h);
    if (!s_->have_page) s_->page_h_px = h, s_->have_page = true;
  }
  void set_viewbox_size(double w, double h) { lengths_.set_viewport_size(w, h); }
  void get_reference_viewport_size(double& w, double& h) {
    w = s_->ref_w;
    h = s_->ref_h;
  }
  void disable_rendering() { hidden_ = true; }

  // ---- `use`: x and y (its transform comes through the transform events)
  void set(tag::attribute::x, double v) { use_x_ = v; }
  void set(tag::attribute::y, double v) { use_y_ = v; }
  void set(tag::attribute::width, double) {}  // a use's size matters only for a symbol or svg it draws
  void set(tag::attribute::height, double) {}

  // ---- path events, as written
  template <class C>
  static bool rel(C) {
    return std::is_same_v<C, tag::coordinate::relative>;
  }
  Vec3 at(double x, double y, bool relative) const { return relative ? Vec3{cur_.x + x, cur_.y + y} : Vec3{x, y}; }

  template <class C>
  void path_move_to(double x, double y, C c) {
    finish_subpath(false);
    check(x, y);
    cur_ = start_ = at(x, y, rel(c));
    open_ = true;
    last_ctrl_kind_ = 0;  // S and T reflect only after C/S and Q/T
  }
  template <class C>
  void path_line_to(double x, double y, C c) {
    check(x, y);
    add(line_piece(cur_, at(x, y, rel(c))));
    last_ctrl_kind_ = 0;  // S and T reflect only after C/S and Q/T
  }
  template <class C>
  void path_line_to_ortho(double v, bool horizontal, C c) {
    check(v, 0);
    Vec3 p = cur_;
    (horizontal ? p.x : p.y) = rel(c) ? (horizontal ? cur_.x : cur_.y) + v : v;
    add(line_piece(cur_, p));
    last_ctrl_kind_ = 0;  // S and T reflect only after C/S and Q/T
  }
  template <class C>
  void path_cubic_bezier_to(double x1, double y1, double x2, double y2, double x, double y, C c) {
    check(x1, y1), check(x2, y2), check(x, y);
    cubic(at(x1, y1, rel(c)), at(x2, y2, rel(c)), at(x, y, rel(c)));
  }
  template <class C>
  void path_cubic_bezier_to(double x2, double y2, double x, double y, C c) {  // S
    check(x2, y2), check(x, y);
    const Vec3 p1 = last_ctrl_kind_ == 'C' ? cur_ * 2 - last_ctrl_ : cur_;
    cubic(p1, at(x2, y2, rel(c)), at(x, y, rel(c)));
  }
  template <class C>
  void path_quadratic_bezier_to(double x1, double y1, double x, double y, C c) {
    check(x1, y1), check(x, y);
    quadratic(at(x1, y1, rel(c)), at(x, y, rel(c)));
  }
  template <class C>
  void path_quadratic_bezier_to(double x, double y, C c) {  // T
    check(x, y);
    const Vec3 p1 = last_ctrl_kind_ == 'Q' ? cur_ * 2 - last_ctrl_ : cur_;
    quadratic(p1, at(x, y, rel(c)));
  }
  template <class C>
  void path_elliptical_arc_to(double rx, double ry, double rot, bool large, bool sweep, double x, double y, C c) {
    check(rx, ry), check(rot, 0), check(x, y);
    const Vec3 to = at(x, y, rel(c));
    for (Piece& p : svg_arc(cur_, rx, ry, rot, large, sweep, to)) add(std::move(p));
    cur_ = to;
    last_ctrl_kind_ = 0;
  }
  void path_close_subpath() {
    if (!open_) return;
    if (cur_.x != start_.x || cur_.y != start_.y) add(line_piece(cur_, start_));
    finish_subpath(true);
    cur_ = start_;
    open_ = true;  // a command after Z starts a new subpath at the same point
    last_ctrl_kind_ = 0;
  }
  void path_exit() { finish_subpath(false); }

  // Every attribute has been read: the element's own `transform` is known
  // only now (SVG++ reads attributes in document order, so `d` may come
  // before it), and its subpaths are mapped and given out.
  void on_exit_element() {
    const std::string kind = name_of(node_);
    if (kind == "polyline" || kind == "polygon") points_of(kind == "polygon");
    finish_subpath(false);
    emit_subpaths();
    if (kind == "use") use();
  }

 private:
  Shared* s_;
  Affine ctm_;
  length_factory_type lengths_;
  const xmlNode* node_ = nullptr;
  int depth_ = 0;
  bool hidden_ = false;
  std::string id_;
  std::string prefix_;  // ids of the `use` elements this element is drawn through, each followed by '/'
  std::string via_;     // the same, for messages
  double use_x_ = 0, use_y_ = 0;
  Vec3 cur_, start_, last_ctrl_;
  char last_ctrl_kind_ = 0;
  bool open_ = false;
  std::vector<Piece> pieces_;
  // Subpaths read, in user units before the element's transform.
  struct Subpath {
    std::vector<Piece> pieces;
    bool closed = false;
  };
  std::vector<Subpath> subpaths_;

  // SVG 1.1 9.7: pairs of numbers, separated by white space and/or a comma.
  void points_of(bool closed) {
    const std::string text = attr_of(node_, "points");
    std::vector<double> v;
    const char* p = text.c_str();
    for (;;) {
      while (*p == ' ' || *p == ',' || *p == '\t' || *p == '\n' || *p == '\r') ++p;
      if (!*p) break;
      char* end = nullptr;
      const double x = std::strtod(p, &end);
      if (end == p)
        s_->fail(errc::import_svg_syntax, "points: expected a number at character " +
                                              std::to_string(p - text.c_str() + 1) + ", found \"" +
                                              std::string(p).substr(0, 12) + "\"");
      v.push_back(x);
      p = end;
    }
    // An odd count is an error in the data; SVG renders up to the last pair.
    if (v.size() < 4) return;
    path_move_to(v[0], v[1], tag::coordinate::absolute());
    for (size_t i = 2; i + 1 < v.size(); i += 2) path_line_to(v[i], v[i + 1], tag::coordinate::absolute());
    if (closed) path_close_subpath();
  }
  void check(double a, double b) const {
    if (!std::isfinite(a) || !std::isfinite(b))
      s_->fail(errc::import_not_finite, "expected finite coordinates, found " + fmt_num(a) + ", " + fmt_num(b));
  }
  void add(Piece p) {
    cur_ = p.points.back();
    // Degenerate pieces (a zero-length line, `L` to the current point) cut nothing.
    bool moves = false;
    for (const Vec3& q : p.points) moves = moves || q.x != p.points.front().x || q.y != p.points.front().y;
    if (moves) pieces_.push_back(std::move(p));
  }
  void cubic(const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    Piece p;
    p.points = {cur_, p1, p2, p3};
    add(std::move(p));
    last_ctrl_ = p2;
    last_ctrl_kind_ = 'C';
  }
  void quadratic(const Vec3& p1, const Vec3& p2) {
    Piece p;
    p.points = {cur_, p1, p2};
    add(std::move(p));
    last_ctrl_ = p1;
    last_ctrl_kind_ = 'Q';
  }
  // SVG 1.1, 5.6: the referenced element is drawn as if it were a child of
  // a `g` carrying the use's transform followed by translate(x, y).
  void use() {
    if (hidden_) return;
    const std::string href = attr_of(node_, "href");  // xlink:href, or SVG 2's href
    if (href.empty()) return;                         // references nothing: draws nothing
    if (href[0] != '#')
      s_->current = node_,
      s_->fail(errc::import_svg_syntax, "href \"" + href +
                                            "\": expected a reference to an element of this drawing (#id); "
                                            "other files are not read");
    const auto it = s_->by_id.find(href.substr(1));
    if (it == s_->by_id.end())
      s_->current = node_,
      s_->fail(errc::import_svg_syntax, "href \"" + href + "\": no element has the id \"" + href.substr(1) + "\"");
    static const std::set<std::string> usable = {"g",    "path",     "rect",    "circle", "ellipse",
                                                 "line", "polyline", "polygon", "use"};
    if (!usable.count(name_of(it->second))) {
      s_->out->layers[""].skipped["use"] += 1;  // a symbol, svg, text or image: not geometry bezcam reads through use
      return;
    }
    for (const xmlNode* n = it->second; n; n = n->parent)
      if (n == node_)
        s_->current = node_,
        s_->fail(errc::import_block_recursion, "href \"" + href + "\" references an element that contains this use");
    if (std::find(s_->using_.begin(), s_->using_.end(), it->second) != s_->using_.end() ||
        std::find(s_->using_.begin(), s_->using_.end(), node_) != s_->using_.end())
      s_->current = node_,
      s_->fail(errc::import_block_recursion, "href \"" + href + "\": the use references itself through other uses");
    if (++s_->instances > kMaxEntities)
      s_->current = node_,
      s_->fail(errc::limit_entities, "use elements draw more than " + std::to_string(kMaxEntities) +
                                         " elements (the most entities of a job)");
    ctm_ = ctm_.after(Affine{1, 0, 0, 1, use_x_, use_y_});
    prefix_ += (id_.empty() ? "use@line " + std::to_string(line_of(node_)) : id_) + "/";
    via_ += " through " + describe(node_);
    s_->using_.push_back(node_);
    load_used(it->second, *this);
    s_->using_.pop_back();
  }

  void finish_subpath(bool closed) {
    open_ = false;
    if (!pieces_.empty()) subpaths_.push_back({std::move(pieces_), closed});
    pieces_.clear();
  }
  void emit_subpaths() {
    std::vector<Subpath> subpaths = std::move(subpaths_);
    subpaths_.clear();
    if (hidden_) return;
    // User units -> millimetres, y up from the page's bottom edge.
    const Affine page{kMmPerPx, 0, 0, -kMmPerPx, 0, s_->page_h_px * kMmPerPx};
    const Affine m = page.after(ctm_);
    const std::string kind = name_of(node_);
    for (size_t k = 0; k < subpaths.size(); ++k) {
      Contour c;
      for (Piece& p : subpaths[k].pieces) {
        for (Vec3& q : p.points) {
          q = m.apply(q);
          if (!std::isfinite(q.x) || !std::isfinite(q.y))
            s_->current = node_,
            s_->fail(errc::import_not_finite, "expected finite coordinates once transformed and scaled, found " +
                                                  fmt_num(q.x) + ", " + fmt_num(q.y));
        }
        c.pieces.push_back(std::move(p));
      }
      // Joints meet exactly (the same double), and a closed contour ends where it starts.
      for (size_t i = 1; i < c.pieces.size(); ++i) c.pieces[i].points.front() = c.pieces[i - 1].points.back();
      if (subpaths[k].closed) c.pieces.back().points.back() = c.pieces.front().points.front();
      c.closed = subpaths[k].closed;
      std::string base = prefix_ + (id_.empty() ? kind + "@line " + std::to_string(line_of(node_)) : id_);
      if (k > 0) base += "." + std::to_string(k + 1);
      int& uses = s_->id_uses[base];
      c.id = ++uses == 1 ? base : base + "#" + std::to_string(uses);
      c.element = describe(node_) + via_;
      if (k == 0) s_->out->layers[""].read[kind] += 1;  // elements, not subpaths
      s_->out->contours.push_back(std::move(c));
    }
  }
};

// Children get their own Context (a copy of the parent's transform and
// viewport) that knows its XML element, for ids and messages.
template <class Child>
class ElementFactory : boost::noncopyable {
 public:
  using type = Child;
  template <class Parent>
  ElementFactory(Parent& parent, xmlNode* const& node) : ctx_(parent, node) {}
  type& get() { return ctx_; }
  void on_exit_element() { ctx_.on_exit_element(); }

 private:
  Child ctx_;
};

struct ChildContextFactories {
  template <class ParentContext, class ElementTag, class Enable = void>
  struct apply {
    using type = ElementFactory<Context>;
  };
};

using ProcessedElements = boost::mpl::set<tag::element::svg, tag::element::g, tag::element::path, tag::element::rect,
                                          tag::element::circle, tag::element::ellipse, tag::element::line,
                                          tag::element::polyline, tag::element::polygon, tag::element::use_>::type;
// What a `use` draws: geometry, groups and further uses (a referenced svg
// or symbol, which would set a viewport of its own, is counted as skipped).
using UsableElements = boost::mpl::set<tag::element::g, tag::element::path, tag::element::rect, tag::element::circle,
                                       tag::element::ellipse, tag::element::line, tag::element::polyline,
                                       tag::element::polygon, tag::element::use_>::type;

// polyline and polygon `points` are read here (points_of()): SVG++'s
// list-of-points parser does not compile with GCC 12 (it binds a const
// context to a non-const reference); the other shapes become path commands.
using ShapeAttributes = boost::mpl::set<
    boost::mpl::pair<tag::element::path, tag::attribute::d>, boost::mpl::pair<tag::element::rect, tag::attribute::x>,
    boost::mpl::pair<tag::element::rect, tag::attribute::y>,
    boost::mpl::pair<tag::element::rect, tag::attribute::width>,
    boost::mpl::pair<tag::element::rect, tag::attribute::height>,
    boost::mpl::pair<tag::element::rect, tag::attribute::rx>, boost::mpl::pair<tag::element::rect, tag::attribute::ry>,
    boost::mpl::pair<tag::element::circle, tag::attribute::cx>,
    boost::mpl::pair<tag::element::circle, tag::attribute::cy>,
    boost::mpl::pair<tag::element::circle, tag::attribute::r>,
    boost::mpl::pair<tag::element::ellipse, tag::attribute::cx>,
    boost::mpl::pair<tag::element::ellipse, tag::attribute::cy>,
    boost::mpl::pair<tag::element::ellipse, tag::attribute::rx>,
    boost::mpl::pair<tag::element::ellipse, tag::attribute::ry>,
    boost::mpl::pair<tag::element::line, tag::attribute::x1>, boost::mpl::pair<tag::element::line, tag::attribute::y1>,
    boost::mpl::pair<tag::element::line, tag::attribute::x2>, boost::mpl::pair<tag::element::line, tag::attribute::y2>,
    boost::mpl::pair<tag::element::use_, tag::attribute::x>,
    boost::mpl::pair<tag::element::use_, tag::attribute::y>>::type;

using ProcessedAttributes =
    boost::mpl::fold<boost::mpl::protect<boost::mpl::joint_view<ShapeAttributes, svgpp::traits::viewport_attributes>>,
                     boost::mpl::set<tag::attribute::transform>::type,
                     boost::mpl::insert<boost::mpl::_1, boost::mpl::_2>>::type;

struct ShapesPolicy {
  using convert_to_path =
      boost::mpl::set4<tag::element::rect, tag::element::line, tag::element::circle, tag::element::ellipse>;
  using collect_attributes = boost::mpl::set0<>;
  static const bool convert_only_rounded_rect_to_path = false;
};

// Drawings from Inkscape and browsers carry attributes and CSS properties
// SVG 1.1 does not know (aria-label, font-variation-settings, line-height):
// they say nothing about geometry and are ignored, as browsers do, and so
// are unknown elements. Every other refusal of SVG++ stands (a value that
// does not parse in an attribute bezcam reads).
template <class Ctx>
struct LenientErrors : svgpp::policy::error::raise_exception<Ctx> {
  template <class XMLElement, class ElementName>
  static bool unknown_element(const Ctx&, const XMLElement&, const ElementName&) {
    return true;  // skipped with its children; the traversal goes on
  }
  template <class XMLElement>
  static bool unexpected_element(const Ctx&, const XMLElement&) {
    return true;
  }
  template <class XMLAttribute, class AttributeName>
  static bool unknown_attribute(const Ctx&, const XMLAttribute&, const AttributeName&,
                                BOOST_SCOPED_ENUM(svgpp::detail::namespace_id), tag::source::attribute) {
    return true;
  }
  template <class XMLAttribute, class AttributeName>
  static bool unknown_attribute(const Ctx&, const XMLAttribute&, const AttributeName&, tag::source::css) {
    return true;
  }
};

}  // namespace
}  // namespace bezcam::import

// SVG++ takes at most 8 policies as parameters of document_traversal; the
// error policy is given by specialising its default for bezcam's context.
template <>
struct svgpp::policy::error::default_policy<bezcam::import::Context>
    : bezcam::import::LenientErrors<bezcam::import::Context> {};

namespace bezcam::import {
namespace {

// Elements that draw but are not geometry bezcam cuts: counted as skipped.
const std::set<std::string>& skipped_kinds() {
  static const std::set<std::string> k = {"text", "image", "foreignObject", "pattern", "marker", "textPath"};
  return k;
}
void count_skipped(const xmlNode* n, Drawing& d) {
  for (const xmlNode* c = n; c; c = c->next) {
    if (c->type != XML_ELEMENT_NODE) continue;
    const std::string name = name_of(c);
    if (skipped_kinds().count(name)) {
      d.layers[""].skipped[name] += 1;
      continue;  // a text's tspans are the text
    }
    count_skipped(c->children, d);
  }
}

void index_ids(const xmlNode* n, std::map<std::string, const xmlNode*>& by_id) {
  for (const xmlNode* c = n; c; c = c->next) {
    if (c->type != XML_ELEMENT_NODE) continue;
    const std::string id = attr_of(c, "id");
    if (!id.empty()) by_id.emplace(id, c);  // the first of equal ids, as browsers take
    index_ids(c->children, by_id);
  }
}

using Traversal = svgpp::document_traversal<
    svgpp::processed_elements<ProcessedElements>, svgpp::processed_attributes<ProcessedAttributes>,
    svgpp::viewport_policy<svgpp::policy::viewport::as_transform>, svgpp::context_factories<ChildContextFactories>,
    svgpp::path_policy<svgpp::policy::path::raw>, svgpp::basic_shapes_policy<ShapesPolicy>,
    svgpp::length_policy<svgpp::policy::length::forward_to_method<Context>>>;

void load_used(const xmlNode* target, Context& use) {
  Traversal::load_referenced_element<svgpp::referencing_element<tag::element::use_>,
                                     svgpp::expected_elements<UsableElements>,
                                     svgpp::processed_elements<UsableElements>>::load(const_cast<xmlNode*>(target),
                                                                                      use);
}

struct DocFree {
  void operator()(xmlDoc* d) const { xmlFreeDoc(d); }
};

// A number with an optional unit, for the root's width/height (the
// reference viewport when they are absent is the viewBox).
bool parse_viewbox(const std::string& s, double& w, double& h) {
  double v[4];
  const char* p = s.c_str();
  for (double& x : v) {
    while (*p == ' ' || *p == ',' || *p == '\t' || *p == '\n' || *p == '\r') ++p;
    char* end = nullptr;
    x = std::strtod(p, &end);
    if (end == p) return false;
    p = end;
  }
  w = v[2];
  h = v[3];
  return true;
}

}  // namespace

Drawing read_svg(std::string_view text, const std::string& source) {
  Drawing d;
  d.source = source;
  d.format = "svg";
  if (text.size() > static_cast<size_t>(std::numeric_limits<int>::max()))
    throw InputError(errc::import_not_a_drawing, Place::at_file(source), "the file is too large to be read as XML");
  // No network, no entity expansion beyond the document itself.
  std::unique_ptr<xmlDoc, DocFree> doc(xmlReadMemory(text.data(), static_cast<int>(text.size()), source.c_str(),
                                                     nullptr,
                                                     XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING));
  if (!doc) {
    const xmlError* e = xmlGetLastError();
    std::string why = e && e->message ? e->message : "not well-formed XML";
    while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
    Place where = Place::at_file(source);
    if (e && e->line > 0) where.line = e->line;
    throw InputError(errc::import_not_a_drawing, std::move(where),
                     "expected an SVG drawing (XML), found a file the XML parser refuses: " + why);
  }
  xmlNode* root = xmlDocGetRootElement(doc.get());
  if (!root || name_of(root) != "svg")
    throw InputError(
        errc::import_not_a_drawing, Place::at_file(source),
        "expected an SVG drawing (root element <svg>), found " +
            (root ? "<" + name_of(root) + "> on line " + std::to_string(line_of(root)) : std::string("no element")));
  Shared s;
  s.source = source;
  s.out = &d;
  // Without width and height the page is the viewBox, in user units.
  s.ref_w = s.ref_h = 0;
  if (!parse_viewbox(attr_of(root, "viewBox"), s.ref_w, s.ref_h) &&
      (attr_of(root, "width").empty() || attr_of(root, "height").empty()))
    throw InputError(errc::import_units, Place::at_file(source),
                     describe(root) + ": expected width and height or a viewBox (the page's size), found neither");
  // The page's size sets every length's scale: a unit SVG does not know
  // there is refused as unknown units, naming it.
  for (const char* a : {"width", "height"}) {
    const std::string v = attr_of(root, a);
    if (v.empty()) continue;
    char* end = nullptr;
    std::strtod(v.c_str(), &end);
    std::string unit(end);
    while (!unit.empty() && unit.back() == ' ') unit.pop_back();
    static const std::set<std::string> known = {"", "px", "in", "cm", "mm", "pt", "pc", "em", "ex", "%"};
    if (end != v.c_str() && !known.count(unit))
      throw InputError(errc::import_units, Place::at_file(source),
                       describe(root) + ": " + a +
                           ": expected a length in px, in, cm, mm, pt or pc (or none: 96 per inch), found \"" + v +
                           "\"");
  }
  // The unit the page's size says: an absolute one on width or height.
  d.mm_per_unit = kMmPerPx;
  for (const char* a : {"width", "height"}) {
    const std::string v = attr_of(root, a);
    static const std::map<std::string, double> absolute = {
        {"in", 25.4}, {"cm", 10}, {"mm", 1}, {"pt", 25.4 / 72}, {"pc", 25.4 / 6}};
    for (const auto& [unit, mm] : absolute)
      if (d.declared_units.empty() && v.size() > unit.size() && v.ends_with(unit)) {
        d.declared_units = unit + " (" + a + "=\"" + v + "\")";
        d.declared_mm = mm;
      }
  }
  index_ids(root, s.by_id);
  Context ctx(s);
  s.current = root;
  try {
    Traversal::load_document(root, ctx);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    s.fail(errc::import_svg_syntax, std::string("expected valid SVG attribute values, found: ") + e.what());
  }
  count_skipped(root, d);
  if (d.contours.empty())
    throw InputError(errc::import_empty, Place::at_file(source),
                     "expected geometry (path, rect, circle, ellipse, line, polyline or polygon), found none");
  return d;
}

}  // namespace bezcam::import
