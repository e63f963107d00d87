// The progress reporter with a fake clock: silent for the first second,
// then a bar redrawn in place on a terminal or plain lines elsewhere, with
// counts, percentage, rate and time left; finished with one last line.
#include "cli/progress.hpp"

#include <algorithm>
#include <cstdlib>
#include <gtest/gtest.h>
#include <sstream>

namespace bezcam::cli {
namespace {

struct Clocked {
  double t = 100;  // any origin: only differences count
  std::ostringstream out;
  ProgressConfig cfg(ProgressStyle style) {
    ProgressConfig c;
    c.style = style;
    c.out = &out;
    c.clock = [this] { return t; };
    c.width = 80;
    return c;
  }
};

TEST(Progress, ShortRunsPrintNothing) {
  for (auto style : {ProgressStyle::bar, ProgressStyle::lines}) {
    Clocked k;
    {
      Progress p("convert", "entities", 10, k.cfg(style));
      for (int i = 0; i <= 10; ++i) {
        k.t += 0.09;  // 0.99 s in all
        p.set(i, "e" + std::to_string(i));
      }
      EXPECT_FALSE(p.shown());
    }  // the destructor finishes: still nothing, nothing was shown
    EXPECT_EQ(k.out.str(), "");
  }
}

TEST(Progress, PlainLinesAfterTheFirstSecondAtMostEveryFiveSeconds) {
  Clocked k;
  Progress p("convert", "entities", 40, k.cfg(ProgressStyle::lines));
  k.t += 1.5;
  p.set(12, "seed-ex-4");
  EXPECT_EQ(k.out.str(), "bezcam: convert: 12/40 entities (30%), 8.0 entities/s, about 3.5 s left, now seed-ex-4\n");
  k.t += 1;  // too soon for another line
  p.set(20);
  const std::string one = k.out.str();
  EXPECT_EQ(std::count(one.begin(), one.end(), '\n'), 1);
  k.t += 5;
  p.set(30);
  const std::string s = k.out.str();
  EXPECT_NE(s.find("bezcam: convert: 30/40 entities (75%), 4.0 entities/s, about 2.5 s left\n"), std::string::npos)
      << s;
  p.set(40);
  p.finish();
  EXPECT_NE(k.out.str().find("bezcam: convert: done, 40/40 entities in 7.5 s\n"), std::string::npos) << k.out.str();
  p.finish();  // idempotent
  const std::string all = k.out.str();
  EXPECT_EQ(all.find("done"), all.rfind("done"));
}

TEST(Progress, BarIsRedrawnInPlaceWithinTheWidth) {
  Clocked k;
  Progress p("convert", "entities", 40, k.cfg(ProgressStyle::bar));
  k.t += 2;
  p.set(10, "a-rather-long-entity-identifier-that-does-not-fit-in-the-line-at-all");
  const std::string first = k.out.str();
  ASSERT_EQ(first.front(), '\r');
  EXPECT_EQ(first.find('\n'), std::string::npos);  // no newline while running
  EXPECT_LE(first.size() - 1, 79u);                // never the last column
  EXPECT_NE(first.find("convert ["), std::string::npos);
  EXPECT_NE(first.find("10/40 entities  25%  5.0 entities/s  0:06 left"), std::string::npos) << first;
  // A quarter of the bar is filled (rounded down).
  const size_t open = first.find('['), close = first.find(']');
  const std::string bar = first.substr(open + 1, close - open - 1);
  EXPECT_GE(bar.size(), 10u);
  EXPECT_EQ(std::count(bar.begin(), bar.end(), '#'), static_cast<long>(bar.size() / 4));
  EXPECT_EQ(std::count(bar.begin(), bar.end(), '.'), static_cast<long>(bar.size() - bar.size() / 4));
  k.t += 0.05;  // too soon to redraw
  p.set(11);
  EXPECT_EQ(k.out.str(), first);
  k.t += 0.25;
  p.set(20);
  EXPECT_GT(k.out.str().size(), first.size());
  p.clear();  // erased for a message: blanks over the line, cursor back
  const std::string cleared = k.out.str();
  EXPECT_EQ(cleared.back(), '\r');
  p.set(40);
  p.finish();
  const std::string all = k.out.str();
  EXPECT_EQ(all.back(), '\n');
  EXPECT_NE(all.rfind("40/40 entities  100%"), std::string::npos);
  EXPECT_NE(all.rfind("in 2.3 s"), std::string::npos) << all;
}

TEST(Progress, BytesUseBinaryPrefixes) {
  Clocked k;
  Progress p("stream", "bytes", 3u << 20, k.cfg(ProgressStyle::lines));
  k.t += 2;
  p.set(1u << 20);
  EXPECT_EQ(k.out.str(), "bezcam: stream: 1.0 MiB/3.0 MiB (33%), 512 KiB/s, about 4.0 s left\n");
}

TEST(Progress, UnknownTotalAndOff) {
  Clocked k;
  Progress p("read", "blocks", 0, k.cfg(ProgressStyle::lines));
  k.t += 2;
  p.add(500);
  EXPECT_EQ(k.out.str(), "bezcam: read: 500 blocks, 250 blocks/s\n");
  Clocked q;
  Progress off("read", "blocks", 10, q.cfg(ProgressStyle::off));
  q.t += 10;
  off.set(5);
  off.finish();
  EXPECT_EQ(q.out.str(), "");
}

TEST(Progress, Formats) {
  EXPECT_EQ(format_bytes(512), "512 B");
  EXPECT_EQ(format_bytes(1536), "1.5 KiB");
  EXPECT_EQ(format_bytes(20.0 * 1024 * 1024), "20 MiB");
  EXPECT_EQ(format_clock(9), "0:09");
  EXPECT_EQ(format_clock(725), "12:05");
  EXPECT_EQ(format_clock(3723), "1:02:03");
  EXPECT_EQ(format_duration(3.26), "3.3 s");
  EXPECT_EQ(format_duration(125), "2 min 5 s");
  EXPECT_EQ(format_duration(3720), "1 h 2 min");
}

TEST(Progress, ConfigFollowsQuietAndTheEnvironment) {
  ::setenv("BEZCAM_PROGRESS", "bar", 1);
  ::setenv("BEZCAM_PROGRESS_DELAY", "0", 1);
  ::setenv("COLUMNS", "120", 1);
  ProgressConfig c = progress_config(false);
  EXPECT_EQ(c.style, ProgressStyle::bar);
  EXPECT_EQ(c.delay_s, 0);
  EXPECT_EQ(c.width, 120);
  EXPECT_EQ(progress_config(true).style, ProgressStyle::off);  // --quiet wins
  ::setenv("BEZCAM_PROGRESS", "lines", 1);
  EXPECT_EQ(progress_config(false).style, ProgressStyle::lines);
  ::unsetenv("BEZCAM_PROGRESS");
  ::unsetenv("BEZCAM_PROGRESS_DELAY");
  ::unsetenv("COLUMNS");
  EXPECT_EQ(progress_config(false).delay_s, 1.0);
}

}  // namespace
}  // namespace bezcam::cli
