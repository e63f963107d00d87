// The job reader's stated limits (limits.hpp, docs/limits.md): each input
// just over a limit is refused with an error naming the place, and refused
// quickly (the time check is ctest's TIMEOUT for *Limits* tests, set in
// CMakeLists.txt, not an assertion); inputs at the limit are read.
#include "bezcam/limits.hpp"

#include <fcntl.h>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>

#include "bezcam/error.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/job_json.hpp"

using namespace bezcam;

namespace {

struct Refusal {
  std::string id, where, message;
};

Refusal refusal_of(const std::string& text) {
  try {
    parse_job(text, "job.json");
  } catch (const InputError& e) {
    return {e.id(), e.where(), e.message()};
  }
  return {};
}

std::string job(const std::string& entities) { return R"({"bezcam": 1, "entities": [)" + entities + "]}"; }

// A clamped uniform B-spline of `n` points of degree p zig-zagging along x.
std::string bspline(size_t n, int p) {
  std::string s = R"({"type": "bspline", "degree": )" + std::to_string(p) + R"(, "points": [)";
  s.reserve(n * 24);
  for (size_t i = 0; i < n; ++i) s += (i ? ",[" : "[") + std::to_string(i) + (i % 2 ? ",1]" : ",0]");
  s += R"(], "knots": [)";
  const size_t spans = n - static_cast<size_t>(p);
  for (size_t i = 0; i < n + static_cast<size_t>(p) + 1; ++i) {
    const size_t k = i <= static_cast<size_t>(p) ? 0 : std::min(i - static_cast<size_t>(p), spans);
    s += (i ? "," : "") + std::to_string(k);
  }
  return s + "]}";
}

std::string bezier_of_degree(int n) {
  std::string s = R"({"type": "bezier", "points": [)";
  for (int i = 0; i <= n; ++i) s += (i ? ",[" : "[") + std::to_string(i) + "," + std::to_string((i * 7) % 5) + "]";
  return s + "]}";
}

}  // namespace

TEST(Limits, AJobFileOverTheSizeLimitIsRefusedBeforeItIsRead) {
  // A sparse file: 32 MiB + 1 byte that take no room on disk and are never read.
  const auto path = std::filesystem::temp_directory_path() / ("bezcam-limits-" + std::to_string(::getpid()) + ".json");
  const int fd = ::open(path.c_str(), O_CREAT | O_TRUNC | O_WRONLY, 0600);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::ftruncate(fd, static_cast<off_t>(kMaxJobBytes + 1)), 0);
  ::close(fd);
  try {
    load_job(path);
    ADD_FAILURE() << "an oversized job file was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "limit.file-size");
    EXPECT_EQ(e.where(), path.string());
    EXPECT_NE(e.message().find("32 MiB"), std::string::npos) << e.message();
  }
  std::filesystem::remove(path);
  // The same limit for text handed over directly.
  EXPECT_EQ(refusal_of(std::string(kMaxJobBytes + 1, ' ')).id, "limit.file-size");
}

TEST(Limits, EntitiesPerJob) {
  std::string many;
  for (size_t i = 0; i < kMaxEntities; ++i)
    many += std::string(i ? "," : "") + R"({"type":"bezier","points":[[0,0],[1,1]]})";
  EXPECT_EQ(parse_job(job(many), "job.json").entities.size(), kMaxEntities);  // at the limit: read
  const Refusal r = refusal_of(job(many + R"(,{"type":"bezier","points":[[0,0],[1,1]]})"));
  EXPECT_EQ(r.id, "limit.entities");
  EXPECT_EQ(r.where, "job.json: entities");
  EXPECT_NE(r.message.find("at most 10000 entities"), std::string::npos) << r.message;
}

TEST(Limits, AMillionControlPointsAreRefusedAtOnce) {
  // 10^6 points of a B-spline: refused when the array is met, before a
  // point is converted or a knot checked.
  const Refusal r = refusal_of(job(bspline(1'000'000, 3)));
  EXPECT_EQ(r.id, "limit.points");
  EXPECT_EQ(r.where, "job.json: entities[0].points");
  EXPECT_NE(r.message.find("at most 100000 points in one entity"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("found 1000000"), std::string::npos) << r.message;
}

TEST(Limits, PointsPerEntityCountEveryArrayOfAPath) {
  // 17 segments of 6000 points: the 17th crosses 100000, and is named.
  std::string segs;
  for (int i = 0; i < 17; ++i) segs += (i ? "," : "") + bspline(6000, 1);
  // The segments do not meet end to end, but the count is met first.
  const Refusal r = refusal_of(job(R"({"type": "path", "segments": [)" + segs + "]}"));
  EXPECT_EQ(r.id, "limit.points");
  EXPECT_EQ(r.where, "job.json: entities[0].segments[16].points");
  EXPECT_NE(r.message.find("found 102000 with these"), std::string::npos) << r.message;
}

TEST(Limits, TheJobsExactBezierFormIsBounded) {
  // A cubic B-spline of 100000 points (at the entity limit) has about
  // 400000 points in Bézier form: two are read, the third crosses 10^6.
  const std::string one = bspline(kMaxEntityPoints, 3);
  EXPECT_EQ(parse_job(job(one), "job.json").entities[0].curve.pieces.size(), kMaxEntityPoints - 3);
  const Refusal r = refusal_of(job(one + "," + one + "," + one));
  EXPECT_EQ(r.id, "limit.points");
  EXPECT_EQ(r.where, "job.json: entities[2].points");
  EXPECT_NE(r.message.find("more than the limit of 1000000"), std::string::npos) << r.message;
}

TEST(Limits, DegreeSixtyIsReadAndAboveSixtyFourRefused) {
  EXPECT_EQ(parse_job(job(bezier_of_degree(60)), "job.json").entities[0].curve.max_degree(), 60);
  EXPECT_EQ(parse_job(job(bezier_of_degree(kMaxBezierDegree)), "job.json").entities[0].curve.max_degree(), 64);
  Refusal r = refusal_of(job(bezier_of_degree(kMaxBezierDegree + 1)));
  EXPECT_EQ(r.id, "curve.degree-too-high");
  EXPECT_EQ(r.where, "job.json: entities[0].points");
  r = refusal_of(job(bspline(100, kMaxBezierDegree + 1)));
  EXPECT_EQ(r.id, "curve.degree-too-high");
  EXPECT_EQ(r.where, "job.json: entities[0].degree");
}

TEST(Limits, ACoonsPatchOfTooManyCellsIsRefusedBeforeItIsBuilt) {
  // Degree-1 B-spline boundaries with 150 spans along u and 100 along v:
  // 15000 exact cells, over the limit of 10000.
  auto edge = [](size_t spans, const std::string& from, const std::string& to) {
    std::string pts;
    for (size_t i = 0; i <= spans; ++i) {
      const double t = double(i) / double(spans);
      // from + t (to - from), each of from and to given as "x,y,z" in {0,1}.
      const double fx = from[0] - '0', fy = from[2] - '0', tx = to[0] - '0', ty = to[2] - '0';
      pts += std::string(i ? "," : "") + "[" + std::to_string(fx + t * (tx - fx)) + "," +
             std::to_string(fy + t * (ty - fy)) + ",0]";
    }
    std::string knots = "0";
    for (size_t i = 0; i <= spans; ++i) knots += "," + std::to_string(i);
    knots += "," + std::to_string(spans);
    return R"({"type": "bspline", "degree": 1, "points": [)" + pts + R"(], "knots": [)" + knots + "]}";
  };
  const std::string patch = R"({"type": "coons_patch", "boundaries": {"v0": )" + edge(150, "0,0", "1,0") +
                            R"(, "v1": )" + edge(150, "0,1", "1,1") + R"(, "u0": )" + edge(100, "0,0", "0,1") +
                            R"(, "u1": )" + edge(100, "1,0", "1,1") + "}}";
  const Refusal r = refusal_of(job(patch));
  EXPECT_EQ(r.id, "limit.patch-cells");
  EXPECT_EQ(r.where, "job.json: entities[0].boundaries");
  EXPECT_NE(r.message.find("150 spans along u and 100 along v make 15000"), std::string::npos) << r.message;
}
