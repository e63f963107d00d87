// The program options: their definitions, and what they change in the
// profile and the conversion.
#include "post_options.hpp"

#include <cmath>
#include <cstdlib>
#include <span>
#include <string_view>
#include <vector>

#include "bezcam/error.hpp"
#include "bezcam/job/keys.hpp"
#include "bezcam/kernel/surface.hpp"

namespace bezcam::cli {

void add_post_options(CLI::App* s, PostOptions& o) {
  const char* g = "Program";
  s->add_option("--preamble", o.preamble,
                "lines after the units line, replacing the profile's preamble (\"G17 G90\\nG54\": \\n separates lines)")
      ->group(g);
  s->add_option("--postamble", o.postamble,
                "lines at the end, replacing the profile's footer (a closing % is kept); {safe_z} and {program} "
                "are replaced")
      ->group(g);
  s->add_option("--precision", o.precision,
                "coordinate decimals, replacing the profile's (the proven bound "
                "includes their rounding)")
      ->check(CLI::Range(0, 9))
      ->default_str("")
      ->group(g);
  s->add_flag("--no-comments", o.no_comments, "no comments in the program (an M00's message to the operator stays)")
      ->group(g);
  s->add_flag("--modal", o.modal,
              "no repeated words in NURBS blocks (a G06.2 point omits Z and R equal to the "
              "previous point's or 1)")
      ->group(g);
  s->add_option("--return-to", o.return_to, "X,Y,Z where the tool goes at the end (across at safe Z, then down)")
      ->group(g);
  s->add_option("--origin", o.origin,
                "the drawing's point that becomes program zero: X,Y, lower-left or center "
                "(of the job's extent)")
      ->group(g);
  s->add_option("--offset", o.offset, "X,Y added to every coordinate (moves the part)")->group(g);
  s->add_option("--program-number", o.program_number,
                "program number (Fanuc O word; a comment elsewhere), "
                "replacing the job's")
      ->check(CLI::Range(1L, 99999999L))
      ->default_str("")
      ->group(g);
  s->get_option("--origin")->excludes(s->get_option("--offset"));
}

namespace {

std::vector<double> numbers_option(const std::string& text, size_t count, const char* option, const char* form) {
  std::vector<double> v;
  size_t at = 0;
  while (at <= text.size()) {
    const size_t comma = text.find(',', at);
    const std::string part = text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    char* end = nullptr;
    const double d = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(d))
      throw InputError(errc::usage_option, Place::at_option(option),
                       "expected " + std::string(form) + " (numbers separated by commas), found \"" + text + "\"");
    v.push_back(d);
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  if (v.size() != count)
    throw InputError(errc::usage_option, Place::at_option(option),
                     "expected " + std::string(form) + ", found \"" + text + "\" (" + std::to_string(v.size()) +
                         " number" + (v.size() == 1 ? "" : "s") + ")");
  return v;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' || (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == 'n')) {
      out.push_back(cur);
      cur.clear();
      if (text[i] == '\\') ++i;
    } else {
      cur += text[i];
    }
  }
  if (!cur.empty() || out.empty()) out.push_back(cur);
  return out;
}

}  // namespace

void apply_post_options(const PostOptions& o, const Job& job, MachineProfile& m, ConvertOptions& opt) {
  auto lines = [&](const std::string& text, const char* option, std::span<const std::string_view> known) {
    std::vector<std::string> out = split_lines(text);
    for (const auto& l : out)
      if (auto why = template_problem(l, known)) throw InputError(errc::usage_option, Place::at_option(option), *why);
    return out;
  };
  if (!o.preamble.empty()) m.preamble = lines(o.preamble, "--preamble", {});
  if (!o.postamble.empty()) {
    static constexpr std::string_view known[] = {"safe_z", "program"};
    std::vector<std::string> f = lines(o.postamble, "--postamble", known);
    if (!m.footer.empty() && m.footer.back() == "%" && (f.empty() || f.back() != "%")) f.push_back("%");
    m.footer = f;
  }
  if (o.precision >= 0) {
    m.decimals_mm = m.decimals_inch = o.precision;
    m.max_decimals_mm = m.max_decimals_inch = o.precision;
  }
  if (o.no_comments) m.comments = false;
  if (o.modal) m.modal = true;
  if (o.program_number > 0) opt.program_number = o.program_number;
  if (!o.return_to.empty()) {
    const auto v = numbers_option(o.return_to, 3, "--return-to", "X,Y,Z");
    opt.return_to = Vec3{v[0], v[1], v[2]};
  }
  if (!o.offset.empty()) {
    const auto v = numbers_option(o.offset, 2, "--offset", "X,Y");
    opt.offset = {v[0], v[1], 0};
  }
  if (!o.origin.empty()) {
    if (o.origin == "lower-left" || o.origin == "center") {
      Box3 b;
      for (const Entity& e : job.entities) {
        if (e.surface)
          b.add(bounds(*e.surface));
        else if (!e.curve.pieces.empty())
          b.add(e.curve.bounds());
      }
      if (b.lo.x > b.hi.x)
        throw InputError(errc::usage_option, Place::at_option("--origin"),
                         "the job has no entity to measure; give the origin as X,Y");
      const Vec3 at = o.origin == "center" ? (b.lo + b.hi) * 0.5 : b.lo;
      opt.offset = {-at.x, -at.y, 0};
    } else {
      const auto v = numbers_option(o.origin, 2, "--origin", "X,Y, lower-left or center");
      opt.offset = {-v[0], -v[1], 0};
    }
  }
}

}  // namespace bezcam::cli
