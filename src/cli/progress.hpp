#pragma once
// Progress of a long command: a bar on a terminal, plain lines otherwise,
// nothing at all for the first second (most runs finish before anyone could
// read it) and nothing when --quiet. Reusable by every subcommand: convert
// and preview count entities, stream counts bytes.
//
//   Progress bar("convert", "entities", job.entities.size(), progress_config(quiet));
//   for (...) { bar.set(i, label); ... }
//   bar.finish();
//
// Terminal form (redrawn in place, at most every 0.1 s):
//   convert [##########..........]  12/40 entities  30%  3.2 entities/s  0:09 left  seed-ex-4
// Plain form (one line at most every 5 s, for logs and pipes):
//   bezcam: convert: 12/40 entities (30%), 3.2 entities/s, about 9 s left
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <mutex>
#include <string>
#include <string_view>

namespace bezcam::cli {

enum class ProgressStyle {
  bar,    ///< one line redrawn with '\r' (stderr is a terminal)
  lines,  ///< plain lines (stderr is a file or a pipe)
  off,    ///< nothing (--quiet)
};

struct ProgressConfig {
  ProgressStyle style = ProgressStyle::lines;
  /// Nothing is shown until the task has run this long (seconds).
  double delay_s = 1.0;
  /// Redraw the bar at most this often (seconds).
  double bar_interval_s = 0.1;
  /// Print a plain line at most this often (seconds).
  double line_interval_s = 5.0;
  /// Width of the terminal line in characters (the bar shrinks to fit).
  int width = 80;
  /// Where to draw; std::cerr when null.
  std::ostream* out = nullptr;
  /// Monotonic clock in seconds; std::chrono::steady_clock when empty.
  std::function<double()> clock;
};

/// Whether stderr is a terminal (a bar rather than plain lines).
bool stderr_is_tty();

/// The configuration for a command run: `off` when quiet, else `bar` when
/// stderr is a terminal and `lines` when it is not. The environment can
/// override: BEZCAM_PROGRESS = bar | lines | off, BEZCAM_PROGRESS_DELAY =
/// seconds before anything is shown (0 shows progress at once; tests use it),
/// COLUMNS = terminal width.
ProgressConfig progress_config(bool quiet);

/// Progress of one task counted in `unit`s (entities, bytes, blocks).
/// "bytes" are printed with binary prefixes (KiB, MiB). Thread-safe: a
/// worker may call set() while another thread reads. The destructor calls
/// finish().
class Progress {
 public:
  /// `task`: what runs ("convert", "stream"); `total`: 0 when unknown (no
  /// percentage, bar or time left then).
  Progress(std::string task, std::string unit, std::uint64_t total, ProgressConfig cfg);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// `done` units are complete; `item` names what is being worked on now
  /// (an entity id, a file name; may be empty).
  void set(std::uint64_t done, std::string_view item = {});
  /// Adds `n` to the count.
  void add(std::uint64_t n, std::string_view item = {});
  /// Changes the total (e.g. once a size is known).
  void set_total(std::uint64_t total);
  /// Erases the bar from the terminal so that the caller can print a
  /// message; the next update draws it again. No effect in the other styles.
  void clear();
  /// Final state: the bar is drawn complete and ended with a newline, or a
  /// last plain line is printed, both only if progress was shown at all.
  /// Idempotent.
  void finish();
  /// Whether anything has been shown so far.
  bool shown() const;
  /// Seconds since construction (a following phase can pass
  /// `delay_s - elapsed()` on so that the whole command, not each phase,
  /// gets the quiet first second).
  double elapsed() const;

  /// The text of the bar line or the plain line for the current state (what
  /// update() prints), for tests.
  std::string render(bool final_line = false) const;

 private:
  double now() const;
  void update(bool force);
  std::ostream& out() const;

  std::string task_, unit_;
  std::uint64_t total_, done_ = 0;
  std::string item_;
  ProgressConfig cfg_;
  double start_, last_draw_ = -1e300;
  bool shown_ = false, on_screen_ = false, finished_ = false;
  size_t drawn_width_ = 0;
  mutable std::mutex mu_;
};

/// "1.5 KiB", "12 MiB": bytes with binary prefixes, 2 to 3 significant digits.
std::string format_bytes(double bytes);
/// "0:09", "12:05", "1:02:03": a duration in seconds as h:mm:ss or m:ss.
std::string format_clock(double seconds);
/// "9 s", "2 min 5 s", "1 h 2 min": a duration for sentences.
std::string format_duration(double seconds);

}  // namespace bezcam::cli
