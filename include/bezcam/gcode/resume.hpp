#pragma once
/// Resume from a line: restart a program part-way, as machinists do after a
/// broken tool (docs/resume.md; /work/shared/spec/motion.md).
///
/// The program's lines before the asked line are run through the one
/// G-code reader (GcodeInterpreter), which tracks the modal state. The
/// resume starts at the nearest line at or before the asked one where a
/// cut may begin (never inside a G06.2 or G5.2 NURBS block, nor at a G5
/// that takes its tangent from the G5 before it), and the resumed program
/// is a preamble that restores the modal state in force there, retracts,
/// moves over the resume point and plunges at the plunge feed, followed by
/// the original text from that line on, byte for byte.
///
/// Line numbers: the resumed program is a G-code program of its own, and a
/// controller numbers its lines from 1. Its first `preamble_lines` lines
/// are the preamble; its line `preamble_lines + k` is the original line
/// `start_line + k - 1` (ResumePlan::original_line()). The preamble's
/// first line is a comment saying so.
#include <optional>
#include <string>
#include <string_view>

#include "bezcam/gcode/reader.hpp"
#include "bezcam/machine/machine_profile.hpp"

namespace bezcam {

/// Safe height and plunge feed of the preamble, in mm and mm/min (converted
/// for a G20 program). Unset: the profile's `safe_z`; the plunge feed the
/// program's header records for the tool (and entity) at the resume line
/// (`T2 plunge feed 200 mm/min`, as bezcam writes it), else the profile's
/// `plunge_feed`.
struct ResumeSettings {
  std::optional<double> safe_z_mm;
  std::optional<double> plunge_feed_mm_min;
};

struct ResumePlan {
  int asked_line = 0;  ///< the line asked for
  int start_line = 0;  ///< where the resumed program's tail starts (<= asked_line)
  /// Why start_line is before asked_line, a sentence ("" when they are equal).
  std::string reason;
  int total_lines = 0;     ///< lines of the original program
  MachineState state;      ///< the reader's state before start_line, in a run from the start
  double safe_z = 0;       ///< the preamble's safe height, program units
  double plunge_feed = 0;  ///< the preamble's plunge feed, program units per minute
  /// Where the plunge feed comes from: "--plunge-feed" (given), "the
  /// program's plunge feed for T2" (its header), "machine M's plunge_feed".
  std::string plunge_from;
  std::string preamble;    ///< the preamble's text, one block per line, each ended by '\n'
  int preamble_lines = 0;  ///< its line count
  std::string program;     ///< preamble + the original text from start_line on

  /// The original line of line `resumed` of `program`, 0 for a preamble line.
  long original_line(long resumed) const {
    return resumed <= preamble_lines ? 0 : resumed - preamble_lines + start_line - 1;
  }
  /// start_line - 1 - preamble_lines: add it to the resumed program's line
  /// numbers after the preamble to get the original ones.
  long line_offset() const { return static_cast<long>(start_line) - 1 - preamble_lines; }
};

/// Plans the resume of `program` at line `line` (1-based, as an editor
/// numbers the file). `profile` (may be null when `settings` gives both
/// values) is the machine's: its dialect, travel and feed limits apply to
/// the lines read and to the preamble, and its defaults give the safe
/// height and plunge feed.
///
/// Refusals (InputError):
///  - `resume.no-line` at `line N`: N is not a line of the program;
///  - `resume.no-code` at `line N`: line N holds no block (blank, comment,
///    `%` or an O-number line);
///  - `resume.state-unknown` at the earlier line the reader refuses (G93,
///    an unsupported word, ...): the modal state before N cannot be known;
///  - `resume.after-end` at `line N`: the program ended (M02/M30) before N;
///  - `resume.setting` (setting `safe_z` or `plunge_feed`): a value missing
///    from the profile and not given, not positive, or the preamble's moves
///    refused by the profile (outside its travel, above its maximum feed).
ResumePlan plan_resume(std::string_view program, const MachineProfile* profile, int line,
                       const ResumeSettings& settings = {});

}  // namespace bezcam
