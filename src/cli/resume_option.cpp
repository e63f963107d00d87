// --from-line for simulate and stream: the options, the plan, the messages.
#include "resume_option.hpp"

#include <iostream>

#include "bezcam/machine/machine_profile.hpp"
#include "validators.hpp"

namespace bezcam::cli {

void add_resume_options(CLI::App* cmd, ResumeArgs& r) {
  auto* from =
      cmd->add_option(
             "--from-line", r.from_line,
             "resume the program at this line (1-based): from the nearest line at or before it where a cut may "
             "begin, after a preamble that restores the modal state there, retracts, moves over and plunges")
          ->check(CLI::PositiveNumber);
  cmd->add_option("--safe-z", r.safe_z,
                  "with --from-line: the height (mm) the preamble retracts to (default: the "
                  "profile's safe_z)")
      ->needs(from);
  cmd->add_option("--plunge-feed", r.plunge_feed,
                  "with --from-line: the feed (mm/min) the preamble plunges at (default: the plunge feed the program's "
                  "header records for the tool there, else the profile's plunge_feed)")
      ->check(positive_number())
      ->needs(from);
}

std::string Resume::apply(std::string program, const std::string& file, const MachineProfile* profile, bool quiet,
                          const std::string& who) {
  if (!active()) return program;  // --safe-z and --plunge-feed need --from-line (add_resume_options())
  file_ = file;
  try {
    plan_ = plan_resume(program, profile, args_.from_line, ResumeSettings{args_.safe_z, args_.plunge_feed});
  } catch (const Error& e) {
    const Place& p = e.place();
    if (p.setting) throw e.with_option(*p.setting == "safe_z" ? "--safe-z" : "--plunge-feed");
    Place q = p;
    q.file = file;
    throw InputError(e.id(), q, e.message());
  }
  const ResumePlan& r = *plan_;
  if (!quiet) {
    std::cerr << "bezcam: " << who << ": resuming " << file << " at line " << r.start_line;
    if (!r.reason.empty()) std::cerr << ", not " << r.asked_line << " as asked: " << r.reason;
    std::cerr << "\nbezcam: " << who << ": a " << r.preamble_lines << "-line preamble restores the modal state of line "
              << r.start_line << ", retracts to Z" << fmt_num(r.safe_z)
              << ", moves over the resume point and plunges at F" << fmt_num(r.plunge_feed) << " (" << r.plunge_from
              << ")"
              << "; the controller numbers the resumed program's lines from 1: line " << r.preamble_lines + 1
              << " is line " << r.start_line << " of " << file << " (add " << r.line_offset()
              << " to the line numbers after " << r.preamble_lines << ")\n";
  }
  return r.program;
}

Place Resume::place_of(long line) const {
  if (!plan_) return Place::at_line(line);
  Place p;
  if (const long orig = plan_->original_line(line)) {
    p.file = file_;
    p.line = orig;
  } else {
    p.file = kPreamble;
    p.line = line;
  }
  return p;
}

}  // namespace bezcam::cli
