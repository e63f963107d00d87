#pragma once
/// Typed errors that say where.
///
/// Every refusal carries a stable id (a named constant of bezcam::errc in
/// <bezcam/error_ids.hpp>, for tests and scripts), the place it concerns (a
/// Place: a file, a JSON path such as `entities[3].knots[7]`, a G-code line,
/// a register or setting, an option of the calling program) and a sentence
/// saying what was expected and what was found. The family (input, io,
/// controller) says what kind of failure it was; the library does not decide
/// what a program does with it (the CLI maps families to exit statuses).
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bezcam/error_ids.hpp"
#include "bezcam/format.hpp"

namespace bezcam {

enum class ErrorFamily { input, io, controller };

/// Where an error applies. Every part is optional; to_string() composes the
/// set parts, in the order option (or setting), file, JSON path, line (and
/// column), register, as `part: part: ...` (`job.json: entities[3].knots[7]`,
/// `prog.nc: line 12`).
///
/// The library never names an option of a program: where a value came from
/// the caller rather than a file it names the setting (`output`,
/// `tolerance`, `deviation`), and a program that took the setting from an
/// option (the CLI's `--output`) shows its own option instead (see
/// with_option()).
struct Place {
  std::optional<std::string> option;     ///< an option of the calling program, e.g. `--machine` (set by programs only)
  std::optional<std::string> setting;    ///< a setting the caller passed to the library, e.g. `output`, `tolerance`
  std::optional<std::string> file;       ///< a file (or an endpoint such as `HOST:PORT`)
  std::optional<std::string> json_path;  ///< a JSON path inside the file, e.g. `entities[3].knots[7]`
  std::optional<long long> line;         ///< a 1-based line number, printed as `line N`
  std::optional<long long> column;       ///< a 1-based column of that line, printed as `line N, column C`
  std::optional<std::string> reg;        ///< a register or setting of a controller, e.g. `buffer`

  /// The place as printed in messages (empty when nothing is known).
  std::string to_string() const;
  /// True when nothing is known.
  bool empty() const { return to_string().empty(); }
  /// The JSON path (places from layers that name a path relative to their
  /// caller's entity); empty when there is none.
  std::string relative_path() const;

  static Place at_line(long long n) {
    Place p;
    p.line = n;
    return p;
  }
  static Place at_json(std::string path) {
    Place p;
    p.json_path = std::move(path);
    return p;
  }
  static Place at_option(std::string opt) {
    Place p;
    p.option = std::move(opt);
    return p;
  }
  static Place at_setting(std::string name) {
    Place p;
    p.setting = std::move(name);
    return p;
  }
  static Place at_file(std::string f) {
    Place p;
    p.file = std::move(f);
    return p;
  }
  static Place at_register(std::string r) {
    Place p;
    p.reg = std::move(r);
    return p;
  }
  /// `file` and a JSON path (`prefix.rest`, or either alone when the other is empty).
  static Place in_json(std::string file, const std::string& prefix, const std::string& rest = {});
};

class Error : public std::runtime_error {
 public:
  /// `id`: the stable identifier (errc::job_knots_order); `where`: the
  /// place (may be empty); `what`: the sentence.
  Error(ErrorFamily family, ErrorId id, Place where, std::string what);

  ErrorFamily family() const noexcept { return family_; }
  /// The dotted id, e.g. `job.knots-order`.
  const std::string& id() const noexcept { return id_; }
  /// The place as printed (Place::to_string()).
  const std::string& where() const noexcept { return where_; }
  /// The place, structured.
  const Place& place() const noexcept { return place_; }
  const std::string& message() const noexcept { return message_; }
  /// The same error with the place's setting shown as the calling program's
  /// option `opt` (e.g. setting `output` shown as `--output`).
  Error with_option(std::string opt) const;
  /// Further independent refusals of the same input (two bad entities, a
  /// misspelt key and a bad value): each is reported, not only the first.
  const std::vector<Error>& more() const noexcept { return more_; }
  void add_more(const Error& e) { more_.push_back(e); }

 private:
  ErrorFamily family_;
  std::string id_;
  Place place_;
  std::string where_, message_;
  std::vector<Error> more_;
};

/// Invalid input or usage: bad job file, bad G-code, bad profile.
class InputError : public Error {
 public:
  InputError(ErrorId id, Place where, std::string what)
      : Error(ErrorFamily::input, id, std::move(where), std::move(what)) {}
};

/// File or connection failure.
class IoError : public Error {
 public:
  IoError(ErrorId id, Place where, std::string what) : Error(ErrorFamily::io, id, std::move(where), std::move(what)) {}
};

/// The controller refused or lost the program.
class ControllerError : public Error {
 public:
  ControllerError(ErrorId id, Place where, std::string what)
      : Error(ErrorFamily::controller, id, std::move(where), std::move(what)) {}
};

}  // namespace bezcam
