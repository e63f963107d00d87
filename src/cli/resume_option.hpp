#pragma once
// --from-line N [--safe-z MM] [--plunge-feed MM/MIN] for `simulate --program`
// and `stream`: resume a program part-way (bezcam/gcode/resume.hpp,
// docs/resume.md). The options as given (ResumeArgs) and, once a command
// applies them, the plan (Resume), which maps the resumed program's lines
// back to the file's.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/gcode/resume.hpp"

namespace bezcam::cli {

/// --from-line, --safe-z and --plunge-feed as given.
struct ResumeArgs {
  int from_line = 0;  ///< 0: no resume
  std::optional<double> safe_z, plunge_feed;
};

/// Adds --from-line, --safe-z and --plunge-feed to `cmd`, bound to `r`.
void add_resume_options(CLI::App* cmd, ResumeArgs& r);

/// A command's resume: the options, and the plan once applied.
class Resume {
 public:
  explicit Resume(const ResumeArgs& args) : args_(args) {}
  bool active() const { return args_.from_line > 0; }
  /// With --from-line: plans the resume of `program` (read from `file`),
  /// says on stderr where it starts and why (unless `quiet`) and returns
  /// the resumed program; without it, `program` unchanged. Refusals name
  /// the file and the line (exit 2).
  std::string apply(std::string program, const std::string& file, const MachineProfile* profile, bool quiet,
                    const std::string& who);
  /// The place of line `line` of the program that ran, in the file's own
  /// numbering (a preamble line is named as such).
  Place place_of(long line) const;
  /// The file a place of place_of() names for a line of the preamble.
  static constexpr const char* kPreamble = "the resume preamble";
  const std::optional<ResumePlan>& plan() const { return plan_; }

 private:
  ResumeArgs args_;
  std::string file_;
  std::optional<ResumePlan> plan_;
};

}  // namespace bezcam::cli
