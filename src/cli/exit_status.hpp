#pragma once
// The exit statuses of the bezcam program (docs/cli.md): what scripts test.
// The library says what kind of failure an error is (ErrorFamily); the
// program turns that into a status.
#include "bezcam/error.hpp"

namespace bezcam::cli {

namespace exit_status {
inline constexpr int ok = 0;
/// Invalid input or usage: a bad file or option, lint's findings, an alarm of `simulate --program`.
inline constexpr int invalid = 2;
/// A file or a connection failed.
inline constexpr int io = 3;
/// The controller refused or lost the program.
inline constexpr int controller = 4;
/// verify: the machined part is gouged beyond the design's tolerance.
inline constexpr int gouge = 5;
/// An internal error: a bug, to be reported with the input.
inline constexpr int internal = 70;
/// Stopped by signal N: 128 + N, as a shell reports it (130 for Ctrl-C).
constexpr int signalled(int signal) { return 128 + signal; }
}  // namespace exit_status

/// The status of a refusal of the error's family.
constexpr int exit_status_of(ErrorFamily family) {
  switch (family) {
    case ErrorFamily::input: return exit_status::invalid;
    case ErrorFamily::io: return exit_status::io;
    case ErrorFamily::controller: return exit_status::controller;
  }
  return exit_status::invalid;
}

}  // namespace bezcam::cli
