#pragma once
/// Typed errors that say where.
///
/// Every refusal carries a stable id (for tests and scripts), the place it
/// concerns (a JSON path such as `entities[3].knots[7]`, a G-code line such
/// as `line 12`, or a Modbus register) and a sentence saying what was
/// expected and what was found. The CLI maps the family to an exit status:
/// InputError -> 2, IoError -> 3, ControllerError -> 4.
#include <stdexcept>
#include <string>

namespace bezcam {

enum class ErrorFamily { input, io, controller };

class Error : public std::runtime_error {
public:
  /// `id`: stable dotted identifier (`job.knots-order`); `where`: the place
  /// (may be empty); `what`: the sentence.
  Error(ErrorFamily family, std::string id, std::string where, std::string what);

  ErrorFamily family() const noexcept { return family_; }
  const std::string& id() const noexcept { return id_; }
  const std::string& where() const noexcept { return where_; }
  const std::string& message() const noexcept { return message_; }
  /// Exit status of the CLI for this family (2, 3 or 4).
  int exit_code() const noexcept;

private:
  ErrorFamily family_;
  std::string id_, where_, message_;
};

/// Invalid input or usage: bad job file, bad G-code, bad profile. Exit 2.
class InputError : public Error {
public:
  InputError(std::string id, std::string where, std::string what)
      : Error(ErrorFamily::input, std::move(id), std::move(where), std::move(what)) {}
};

/// File or connection failure. Exit 3.
class IoError : public Error {
public:
  IoError(std::string id, std::string where, std::string what)
      : Error(ErrorFamily::io, std::move(id), std::move(where), std::move(what)) {}
};

/// The controller refused or lost the program. Exit 4.
class ControllerError : public Error {
public:
  ControllerError(std::string id, std::string where, std::string what)
      : Error(ErrorFamily::controller, std::move(id), std::move(where), std::move(what)) {}
};

/// Formats a number for messages: shortest text that reads back exactly.
std::string fmt_num(double v);

}  // namespace bezcam
