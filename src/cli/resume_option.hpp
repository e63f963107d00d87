#pragma once
// --from-line N [--safe-z MM] [--plunge-feed MM/MIN] for `simulate --program`
// and `stream`: resume a program part-way (bezcam/gcode/resume.hpp,
// docs/resume.md). One object per command holds the options and, once
// applied, the plan, which maps the resumed program's lines back to the
// file's.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/gcode/resume.hpp"

namespace bezcam::cli {

class ResumeOption {
 public:
  /// Adds --from-line, --safe-z and --plunge-feed to `cmd`.
  void add(CLI::App* cmd);
  bool active() const { return from_line_ > 0; }
  /// With --from-line: plans the resume of `program` (read from `file`),
  /// says on stderr where it starts and why (unless `quiet`) and returns
  /// the resumed program; without it, `program` unchanged. Refusals name
  /// the file and the line (exit 2).
  std::string apply(std::string program, const std::string& file, const MachineProfile* profile, bool quiet,
                    const std::string& who);
  /// The place of line `line` of the program that ran, in the file's own
  /// numbering (a preamble line is named as such).
  Place place_of(long line) const;
  const std::optional<ResumePlan>& plan() const { return plan_; }

 private:
  int from_line_ = 0;
  std::optional<double> safe_z_, plunge_feed_;
  std::string file_;
  std::optional<ResumePlan> plan_;
};

}  // namespace bezcam::cli
