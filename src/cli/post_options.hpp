#pragma once
// The program options of convert and check (preamble, postamble,
// precision, comments, return point, origin, program number): what a
// machinist changes in the program without writing a profile.
#include <CLI/CLI.hpp>
#include <string>

#include "bezcam/cam/program.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/machine/machine_profile.hpp"

namespace bezcam::cli {

/// What a machinist changes in the program without writing a profile, in
/// the spirit of FreeCAD's post options (convert and check).
struct PostOptions {
  std::string preamble, postamble;  ///< replace the profile's (lines split at "\n")
  int precision = -1;               ///< coordinate decimals; -1: the profile's
  bool no_comments = false, modal = false;
  std::string return_to;       ///< "X,Y,Z"
  std::string origin, offset;  ///< "X,Y" (origin also lower-left, center)
  long program_number = 0;     ///< 0: the job's or the profile's
};

/// Adds the options above to `s`, in the help group "Program".
void add_post_options(CLI::App* s, PostOptions& o);

/// Applies the post options to the profile and the conversion: refuses
/// (usage.option, exit 2) what cannot be read, naming the option.
void apply_post_options(const PostOptions& o, const Job& job, MachineProfile& m, ConvertOptions& opt);

}  // namespace bezcam::cli
