// Finding a font: a file, or a family through fontconfig. Fontconfig
// always answers with some font (its substitutes, its default); a family
// is taken only when the face it answers with has that family name.
#include <algorithm>
#include <cctype>
#include <fontconfig/fontconfig.h>
#include <memory>
#include <mutex>
#include <set>

#include "bezcam/error.hpp"
#include "bezcam/job/keys.hpp"
#include "bezcam/text/font_text.hpp"

namespace bezcam::text {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Family names compared as fontconfig compares them: case and blanks aside.
std::string folded(const std::string& s) {
  std::string o;
  for (const char c : s)
    if (c != ' ') o += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return o;
}

// fontconfig's configuration, loaded once; fontconfig is not thread-safe
// for one configuration's lookups, so they hold this lock.
FcConfig* config() {
  static FcConfig* const cfg = FcInitLoadConfigAndFonts();
  return cfg;
}
std::mutex& fc_lock() {
  static std::mutex m;
  return m;
}

struct PatternDeleter {
  void operator()(FcPattern* p) const { FcPatternDestroy(p); }
};
using Pattern = std::unique_ptr<FcPattern, PatternDeleter>;

std::vector<std::string> strings_of(FcPattern* p, const char* object) {
  std::vector<std::string> out;
  FcChar8* s = nullptr;
  for (int i = 0; FcPatternGetString(p, object, i, &s) == FcResultMatch; ++i)
    out.emplace_back(reinterpret_cast<const char*>(s));
  return out;
}

// Every family fontconfig has an outline font of.
std::set<std::string> installed_families() {
  std::set<std::string> out;
  Pattern all(FcPatternCreate());
  FcObjectSet* os = FcObjectSetBuild(FC_FAMILY, FC_OUTLINE, nullptr);
  FcFontSet* fs = FcFontList(config(), all.get(), os);
  FcObjectSetDestroy(os);
  if (!fs) return out;
  for (int i = 0; i < fs->nfont; ++i) {
    FcBool outline = FcFalse;
    if (FcPatternGetBool(fs->fonts[i], FC_OUTLINE, 0, &outline) == FcResultMatch && !outline) continue;
    for (const std::string& f : strings_of(fs->fonts[i], FC_FAMILY)) out.insert(f);
  }
  FcFontSetDestroy(fs);
  return out;
}

// The installed families nearest to `family` by their spelling: those
// sharing a word with it first, then by edits; three at most.
std::vector<std::string> nearest_families(const std::string& family) {
  const std::string want = folded(family);
  std::vector<std::pair<int, std::string>> ranked;
  for (const std::string& f : installed_families()) {
    int d = edit_distance(want, folded(f));
    if (folded(f).find(want) != std::string::npos || want.find(folded(f)) != std::string::npos) d = 0;
    ranked.emplace_back(d, f);
  }
  std::sort(ranked.begin(), ranked.end());
  std::vector<std::string> out;
  for (size_t i = 0; i < ranked.size() && i < 3; ++i) out.push_back(ranked[i].second);
  return out;
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string o;
  for (size_t i = 0; i < names.size(); ++i)
    o += std::string(i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + "\"" + names[i] + "\"";
  return o;
}

FontFace font_file(const std::string& font, const std::filesystem::path& folder) {
  const std::filesystem::path given(font);
  const std::filesystem::path file = given.is_absolute() || folder.empty() ? given : folder / given;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw InputError(
        errc::text_font_file, Place::at_json("font"),
        "expected a font file, found no file " + file.string() +
            (given.is_absolute() ? std::string() : " (a relative path is taken from the job file's folder)") +
            "; give an existing .ttf or .otf file, or a family name");
  return {file, 0, {}};
}

FontFace font_family(const std::string& font) {
  const std::lock_guard<std::mutex> lock(fc_lock());
  if (!config())
    throw InputError(errc::text_font, Place::at_json("font"),
                     "fontconfig's configuration cannot be loaded, so no family can be found; give a font file");
  Pattern pat(FcNameParse(reinterpret_cast<const FcChar8*>(font.c_str())));
  if (!pat)
    throw InputError(errc::text_font, Place::at_json("font"),
                     "expected a font family such as \"DejaVu Sans\" (or \"DejaVu Sans:bold\"), found \"" + font +
                         "\", which fontconfig does not read");
  const std::vector<std::string> asked = strings_of(pat.get(), FC_FAMILY);
  if (asked.empty())
    throw InputError(errc::text_font, Place::at_json("font"),
                     "expected a font family such as \"DejaVu Sans\", found \"" + font + "\", which names none");
  FcConfigSubstitute(config(), pat.get(), FcMatchPattern);
  FcDefaultSubstitute(pat.get());
  FcResult result = FcResultNoMatch;
  Pattern match(FcFontMatch(config(), pat.get(), &result));
  const std::vector<std::string> got = match ? strings_of(match.get(), FC_FAMILY) : std::vector<std::string>{};
  const bool same = std::any_of(got.begin(), got.end(), [&](const std::string& g) {
    return std::any_of(asked.begin(), asked.end(), [&](const std::string& a) { return folded(a) == folded(g); });
  });
  FcChar8* file = nullptr;
  if (!same || FcPatternGetString(match.get(), FC_FILE, 0, &file) != FcResultMatch) {
    const std::vector<std::string> near = nearest_families(asked.front());
    throw InputError(errc::text_font, Place::at_json("font"),
                     "the font family \"" + asked.front() + "\" is not installed" +
                         (got.empty() ? std::string() : " (fontconfig would substitute \"" + got.front() + "\")") +
                         (near.empty() ? std::string("; no font families are installed: give a font file")
                                       : "; the nearest installed families are " + quoted_list(near) +
                                             ": name one of them, install the font, or give its file"));
  }
  FontFace face;
  face.file = reinterpret_cast<const char*>(file);
  int index = 0;
  if (FcPatternGetInteger(match.get(), FC_INDEX, 0, &index) == FcResultMatch) face.index = index;
  face.family = got.front();
  return face;
}

}  // namespace

bool names_a_file(const std::string& font) {
  if (font.find('/') != std::string::npos) return true;
  const std::string l = lower(font);
  for (const char* ext : {".ttf", ".otf", ".ttc", ".otc", ".pfb", ".pfa", ".t1", ".woff", ".woff2"})
    if (l.ends_with(ext)) return true;
  return false;
}

FontFace find_font(const std::string& font, const std::filesystem::path& folder) {
  return names_a_file(font) ? font_file(font, folder) : font_family(font);
}

std::optional<FontFace> installed_font(const std::string& name) {
  if (name.empty()) return std::nullopt;
  if (!names_a_file(name)) {
    try {
      return font_family(name);
    } catch (const InputError&) {
      return std::nullopt;
    }
  }
  // A file's name: the installed font files of that name, the first in
  // fontconfig's list order by path (the same answer on every run).
  const std::string want = lower(std::filesystem::path(name).filename().string());
  const std::lock_guard<std::mutex> lock(fc_lock());
  if (!config()) return std::nullopt;
  Pattern all(FcPatternCreate());
  FcObjectSet* os = FcObjectSetBuild(FC_FILE, FC_INDEX, FC_FAMILY, FC_OUTLINE, nullptr);
  FcFontSet* fs = FcFontList(config(), all.get(), os);
  FcObjectSetDestroy(os);
  if (!fs) return std::nullopt;
  std::optional<FontFace> best;
  for (int i = 0; i < fs->nfont; ++i) {
    FcChar8* file = nullptr;
    if (FcPatternGetString(fs->fonts[i], FC_FILE, 0, &file) != FcResultMatch) continue;
    const std::filesystem::path path(reinterpret_cast<const char*>(file));
    if (lower(path.filename().string()) != want) continue;
    int index = 0;
    (void)FcPatternGetInteger(fs->fonts[i], FC_INDEX, 0, &index);
    if (index != 0) continue;
    if (best && best->file.string() <= path.string()) continue;
    const std::vector<std::string> families = strings_of(fs->fonts[i], FC_FAMILY);
    best = FontFace{path, 0, families.empty() ? std::string() : families.front()};
  }
  FcFontSetDestroy(fs);
  return best;
}

FontFace default_font() {
  const std::lock_guard<std::mutex> lock(fc_lock());
  Pattern pat(FcNameParse(reinterpret_cast<const FcChar8*>("sans-serif")));
  FcChar8* file = nullptr;
  if (config() && pat) {
    FcConfigSubstitute(config(), pat.get(), FcMatchPattern);
    FcDefaultSubstitute(pat.get());
    FcResult result = FcResultNoMatch;
    Pattern match(FcFontMatch(config(), pat.get(), &result));
    if (match && FcPatternGetString(match.get(), FC_FILE, 0, &file) == FcResultMatch) {
      FontFace face;
      face.file = reinterpret_cast<const char*>(file);
      int index = 0;
      if (FcPatternGetInteger(match.get(), FC_INDEX, 0, &index) == FcResultMatch) face.index = index;
      const std::vector<std::string> families = strings_of(match.get(), FC_FAMILY);
      if (!families.empty()) face.family = families.front();
      return face;
    }
  }
  throw InputError(errc::text_font, Place::at_json("font"),
                   "fontconfig gives no font for \"sans-serif\", so a font that is not installed has no stand-in; "
                   "install a font (fonts-dejavu-core) or name one");
}

}  // namespace bezcam::text
