#include "progress.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <unistd.h>

#include "bezcam/format.hpp"

namespace bezcam::cli {

namespace {

double steady_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

// Shortens `s` to at most `n` characters, keeping its end (ids differ at
// the end more often than at the start).
std::string fit(std::string_view s, size_t n) {
  if (s.size() <= n) return std::string(s);
  if (n <= 3) return std::string(s.substr(s.size() - n));
  return "..." + std::string(s.substr(s.size() - (n - 3)));
}

}  // namespace

std::string format_bytes(double bytes) {
  static const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  int u = 0;
  while (bytes >= 1024 && u < 4) bytes /= 1024, ++u;
  if (u == 0) return format_fixed(bytes, 0) + " B";
  return format_fixed(bytes, bytes < 10 ? 1 : 0) + " " + units[u];
}

std::string format_clock(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

std::string format_duration(double seconds) {
  seconds = std::max(0.0, seconds);
  if (seconds < 10) return format_fixed(seconds, 1) + " s";
  const long s = std::lround(seconds);
  if (s < 60) return std::to_string(s) + " s";
  if (s < 3600) return std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s";
  return std::to_string(s / 3600) + " h " + std::to_string((s / 60) % 60) + " min";
}

bool stderr_is_tty() { return ::isatty(STDERR_FILENO) == 1; }

ProgressConfig progress_config(bool quiet) {
  ProgressConfig c;
  c.style = quiet ? ProgressStyle::off : (stderr_is_tty() ? ProgressStyle::bar : ProgressStyle::lines);
  if (const char* s = std::getenv("BEZCAM_PROGRESS"); s && !quiet) {
    const std::string v = s;
    if (v == "bar")
      c.style = ProgressStyle::bar;
    else if (v == "lines")
      c.style = ProgressStyle::lines;
    else if (v == "off")
      c.style = ProgressStyle::off;
  }
  if (const char* s = std::getenv("BEZCAM_PROGRESS_DELAY"); s && *s) {
    char* end = nullptr;
    const double d = std::strtod(s, &end);
    if (end && *end == '\0' && d >= 0) c.delay_s = d;
  }
  if (const char* s = std::getenv("COLUMNS"); s && *s) {
    const int w = std::atoi(s);
    if (w >= 20 && w <= 1000) c.width = w;
  }
  return c;
}

Progress::Progress(std::string task, std::string unit, std::uint64_t total, ProgressConfig cfg)
    : task_(std::move(task)), unit_(std::move(unit)), total_(total), cfg_(std::move(cfg)) {
  start_ = now();
}

Progress::~Progress() {
  // A destructor must not throw; a failed write to stderr is not worth it.
  try {
    finish();
  } catch (...) {
  }
}

double Progress::now() const { return cfg_.clock ? cfg_.clock() : steady_seconds(); }

std::ostream& Progress::out() const { return cfg_.out ? *cfg_.out : std::cerr; }

void Progress::set(std::uint64_t done, std::string_view item) {
  std::lock_guard lock(mu_);
  done_ = done;
  item_ = item;
  update(false);
}

void Progress::add(std::uint64_t n, std::string_view item) {
  std::lock_guard lock(mu_);
  done_ += n;
  if (!item.empty()) item_ = item;
  update(false);
}

void Progress::set_total(std::uint64_t total) {
  std::lock_guard lock(mu_);
  total_ = total;
}

double Progress::elapsed() const { return now() - start_; }

bool Progress::shown() const {
  std::lock_guard lock(mu_);
  return shown_;
}

void Progress::clear() {
  std::lock_guard lock(mu_);
  if (cfg_.style != ProgressStyle::bar || !on_screen_) return;
  out() << "\r" << std::string(drawn_width_, ' ') << "\r" << std::flush;
  on_screen_ = false;
  last_draw_ = -1e300;  // redraw at the next update
}

void Progress::finish() {
  std::lock_guard lock(mu_);
  if (finished_) return;
  finished_ = true;
  if (!shown_ || cfg_.style == ProgressStyle::off) return;
  const std::string s = render(true);
  if (cfg_.style == ProgressStyle::bar) {
    const std::string pad(drawn_width_ > s.size() ? drawn_width_ - s.size() : 0, ' ');
    out() << "\r" << s << pad << "\n" << std::flush;
  } else {
    out() << s << "\n" << std::flush;
  }
  on_screen_ = false;
}

void Progress::update(bool force) {
  if (cfg_.style == ProgressStyle::off || finished_) return;
  const double t = now();
  if (t - start_ < cfg_.delay_s) return;  // short runs stay silent
  const double interval = cfg_.style == ProgressStyle::bar ? cfg_.bar_interval_s : cfg_.line_interval_s;
  if (!force && t - last_draw_ < interval) return;
  last_draw_ = t;
  const std::string s = render(false);
  if (cfg_.style == ProgressStyle::bar) {
    // Pad with blanks over the rest of a longer previous line.
    const std::string pad(drawn_width_ > s.size() ? drawn_width_ - s.size() : 0, ' ');
    out() << "\r" << s << pad << std::flush;
    drawn_width_ = s.size();
    on_screen_ = true;
  } else {
    out() << s << "\n" << std::flush;
  }
  shown_ = true;
}

std::string Progress::render(bool final_line) const {
  const double elapsed = std::max(0.0, now() - start_);
  const bool bytes = unit_ == "bytes";
  auto amount = [&](double v) { return bytes ? format_bytes(v) : std::to_string(static_cast<std::uint64_t>(v)); };
  std::string counts = amount(double(done_));
  if (total_ > 0) counts += "/" + amount(double(total_));
  if (!bytes) counts += " " + unit_;
  std::string pct;
  if (total_ > 0) pct = std::to_string(std::min<std::uint64_t>(100, done_ * 100 / total_)) + "%";
  // The average rate since the start: steadier than an instantaneous one.
  const double rate = elapsed > 0 ? double(done_) / elapsed : 0;
  std::string rate_s;
  if (rate > 0) rate_s = bytes ? format_bytes(rate) + "/s" : format_fixed(rate, rate < 10 ? 1 : 0) + " " + unit_ + "/s";
  const bool eta_known = total_ > 0 && rate > 0 && done_ < total_;
  const double eta = eta_known ? double(total_ - done_) / rate : 0;

  if (cfg_.style != ProgressStyle::bar) {
    std::string s = "bezcam: " + task_ + ": ";
    if (final_line) return s + "done, " + counts + " in " + format_duration(elapsed);
    s += counts;
    if (!pct.empty()) s += " (" + pct + ")";
    if (!rate_s.empty()) s += ", " + rate_s;
    if (eta_known) s += ", about " + format_duration(eta) + " left";
    if (!item_.empty()) s += ", now " + item_;
    return s;
  }
  // Terminal line: task [bar] counts pct rate time item, cut to the width.
  std::string tail = "  " + counts;
  if (!pct.empty()) tail += "  " + pct;
  if (!rate_s.empty()) tail += "  " + rate_s;
  if (final_line)
    tail += "  in " + format_duration(elapsed);
  else if (eta_known)
    tail += "  " + format_clock(eta) + " left";
  const size_t width = static_cast<size_t>(std::max(20, cfg_.width)) - 1;  // never touch the last column
  std::string s = task_;
  if (total_ > 0) {
    const size_t room = width > s.size() + tail.size() + 3 ? width - s.size() - tail.size() - 3 : 0;
    const size_t bar = std::clamp<size_t>(room, 10, 30);
    const double frac = std::min(1.0, double(done_) / double(total_));
    const size_t full = static_cast<size_t>(std::floor(frac * double(bar)));
    s += " [" + std::string(full, '#') + std::string(bar - full, '.') + "]";
  }
  s += tail;
  if (!final_line && !item_.empty() && s.size() + 4 < width) s += "  " + fit(item_, width - s.size() - 2);
  if (s.size() > width) s.resize(width);
  return s;
}

}  // namespace bezcam::cli
