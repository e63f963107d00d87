// The job file's surface entities: bezier_patch, coons_patch (with a
// B-spline boundary parametrised by its knots), curve_on_surface (inline
// patch or a patch entity named by id), the toolpath object and the gouge
// key; every refusal names its JSON path.
#include <gtest/gtest.h>

#include "bezcam/error.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"

namespace bezcam {
namespace {

std::string job(const std::string& entities, const std::string& jobkeys = "") {
  return R"({"bezcam": 1, "job": {"feed": 100)" + jobkeys + R"(}, "entities": [)" + entities + "]}";
}

#define BEZCAM_TEST_NET \
  R"("points": [[[0,0,0],[0,50,5],[0,100,0]], [[50,0,5],[50,50,20],[50,100,5]], [[100,0,0],[100,50,5],[100,100,0]]])"
const char* kPatch = R"({"id": "p", "type": "bezier_patch", )" BEZCAM_TEST_NET
                     R"(, "toolpath": {"pattern": "raster", "direction": "v", "stepover": 2.5}})";
const char* kInlinePatch = R"({"type": "bezier_patch", )" BEZCAM_TEST_NET "}";

std::string refusal(const std::string& text) {
  try {
    parse_job(text, "t.json");
  } catch (const InputError& e) {
    return e.where() + ": " + e.message();
  }
  return "accepted";
}

TEST(JobJsonSurfaces, BezierPatchWithToolpath) {
  const Job j = parse_job(job(kPatch), "t.json");
  const Entity& e = j.entities[0];
  ASSERT_TRUE(e.surface);
  EXPECT_EQ(e.surface->kind, "bezier_patch");
  EXPECT_TRUE(e.curve.pieces.empty());  // not a curve: the curve emitters leave it alone
  EXPECT_EQ(e.surface->degree_u(), 2);
  EXPECT_EQ(e.toolpath.pattern, "raster");
  EXPECT_EQ(e.toolpath.direction, 'v');
  EXPECT_EQ(*e.toolpath.stepover, 2.5);
  EXPECT_NEAR(evaluate(*e.surface, 0.5, 0.5).z, 7.5, 1e-12);  // sum of B(2,i)(1/2) B(2,j)(1/2) z_ij
  // Defaults: zigzag along u, no stepover (asked for when cutting).
  const Job d =
      parse_job(job(R"({"type": "bezier_patch", "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,1]]]})"), "t.json");
  EXPECT_EQ(d.entities[0].toolpath.pattern, "zigzag");
  EXPECT_EQ(d.entities[0].toolpath.direction, 'u');
  EXPECT_FALSE(d.entities[0].toolpath.stepover);
}

TEST(JobJsonSurfaces, PatchRefusalsNameThePlace) {
  EXPECT_EQ(refusal(job(R"({"type": "bezier_patch", "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0],[2,1,0]]]})")),
            "t.json: entities[0].points[1]: expected a row of 2 points like points[0], found 3; every row of the "
            "net has the same length");
  EXPECT_EQ(refusal(job(R"({"type": "bezier_patch", "points": [[[0,0],[1,0]],[[0,1],[1,1]]]})")),
            "t.json: entities[0].points[0]: expected 3D points [x, y, z] (a patch lives in space), found 2D points");
  EXPECT_EQ(refusal(job(R"({"type": "bezier_patch", "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]],
                            "weights": [[1, 1], [1, -2]]})")),
            "t.json: entities[0].weights[1][1]: expected a finite weight > 0, found -2");
  const std::string one_row = refusal(job(R"({"type": "bezier_patch", "points": [[[0,0,0],[1,0,0]]]})"));
  EXPECT_EQ(one_row.substr(0, 49), "t.json: entities[0].points: expected an array of ") << one_row;
  EXPECT_NE(one_row.find("at least 2"), std::string::npos) << one_row;
  const std::string bad_tp = refusal(job(
      R"({"type": "bezier_patch", "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]], "toolpath": {"pattern": "spiral"}})"));
  EXPECT_EQ(bad_tp.substr(0, 38), "t.json: entities[0].toolpath.pattern: ") << bad_tp;
  EXPECT_NE(bad_tp.find("\"zigzag\", \"raster\" or \"boundary\""), std::string::npos);
  EXPECT_EQ(refusal(job(R"({"type": "bezier_patch", "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]],
                            "toolpath": {"direction": "w"}})"))
                .substr(0, 40),
            "t.json: entities[0].toolpath.direction: ");
  EXPECT_EQ(refusal(job(R"({"type": "bezier_patch", "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]],
                            "toolpath": {"stepover": 0}})")),
            "t.json: entities[0].toolpath.stepover: expected a number > 0, found 0");
}

TEST(JobJsonSurfaces, UnknownToolpathKeysAreRefused) {
  EXPECT_EQ(refusal(job(R"({"type": "bezier_patch", "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]],
                            "toolpath": {"stepover": 1, "angle": 30}})")),
            "t.json: entities[0].toolpath.angle: unknown key \"angle\" (a key bezcam does not know is refused: it "
            "would otherwise be ignored; keys of your own start with \"x-\")");
}

const char* kCoons = R"({"id": "c", "type": "coons_patch", "blend": "quintic", "boundaries": {
   "v0": {"type": "bezier", "points": [[0,0,0],[60,-15,12],[140,10,16],[200,0,6]]},
   "v1": {"type": "bspline", "degree": 3, "knots": [0,0,0,0,0.4,1,1,1,1],
          "points": [[0,150,10],[50,165,22],[100,140,26],[150,160,18],[200,150,4]]},
   "u0": {"type": "bezier", "points": [[0,0,0],[-12,50,10],[10,100,16],[0,150,10]]},
   "u1": {"type": "bezier", "points": [[200,0,6],[215,60,14],[190,110,10],[200,150,4]]}}})";

TEST(JobJsonSurfaces, CoonsPatchUsesTheBsplineKnotsAsItsParameter) {
  const Job j = parse_job(job(kCoons), "t.json");
  const SurfaceGeometry& s = *j.entities[0].surface;
  EXPECT_EQ(s.kind, "coons_patch");
  const auto& cp = std::get<CoonsPatch>(s.source);
  EXPECT_EQ(cp.blend, CoonsBlend::quintic);
  EXPECT_EQ(s.grid.ubreaks, (std::vector<double>{0, 0.4, 1}));
  // S(u,1) is the B-spline at its own parameter u (knots 0 .. 1).
  const NurbsCurve b = NurbsCurve::make(3, {{0, 150, 10}, {50, 165, 22}, {100, 140, 26}, {150, 160, 18}, {200, 150, 4}},
                                        {0, 0, 0, 0, 0.4, 1, 1, 1, 1}, {}, 3);
  for (double u : {0.0, 0.1, 0.4, 0.65, 1.0}) EXPECT_LE(dist(evaluate(s, u, 1), evaluate(b, u)), 1e-11) << u;
}

TEST(JobJsonSurfaces, CoonsRefusalsNameTheBoundary) {
  std::string bad = kCoons;
  bad.replace(bad.find("[200,150,4]]}}"), 11, "[200,150,9]");  // u1 no longer ends at v1's end
  const std::string r = refusal(job(bad));
  EXPECT_EQ(r.substr(0, 35), "t.json: entities[0].boundaries.u1: ") << r;
  EXPECT_NE(r.find("S(1,1) = (200, 150, 4), where v1 ends, found (200, 150, 9), 5 away"), std::string::npos) << r;
  std::string missing = kCoons;
  missing.replace(missing.find("\"u0\""), 4, "\"x-first\"");  // a key of the user's own
  const std::string m = refusal(job(missing));
  EXPECT_EQ(m.substr(0, 35), "t.json: entities[0].boundaries.u0: ") << m;
  EXPECT_NE(m.find("required key"), std::string::npos) << m;
  // "uO" is a likely typo of "u0": refused as such first, and the missing
  // key it hides is reported too.
  std::string typo = kCoons;
  typo.replace(typo.find("\"u0\""), 4, "\"uO\"");
  try {
    parse_job(job(typo), "t.json");
    ADD_FAILURE() << "accepted a misspelt boundary";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "job.key-typo");
    EXPECT_EQ(e.where(), "t.json: entities[0].boundaries.uO") << e.what();
    EXPECT_NE(std::string(e.what()).find("did you mean \"u0\""), std::string::npos) << e.what();
    ASSERT_EQ(e.more().size(), 1u);
    EXPECT_EQ(e.more()[0].where(), "t.json: entities[0].boundaries.u0") << e.more()[0].what();
  }
  std::string flat = kCoons;
  flat.replace(flat.find("[[0,0,0],[60,-15,12]"), 20, "[[0,0],[60,-15]");
  const std::string f = refusal(job(flat));
  EXPECT_NE(f.find("entities[0].boundaries.v0"), std::string::npos) << f;
  std::string blend = kCoons;
  blend.replace(blend.find("quintic"), 7, "septic");
  EXPECT_EQ(refusal(job(blend)),
            "t.json: entities[0].blend: expected \"linear\", \"cubic\" or \"quintic\", found the string \"septic\"");
}

TEST(JobJsonSurfaces, CurveOnSurfaceByIdOrInline) {
  const std::string arch = R"({"type": "curve_on_surface", "surface": "p", "curve": {"type": "path", "segments": [
      {"type": "bezier", "points": [[0.25,0],[0.25,0.3],[0.36,0.55],[0.5,0.55]]},
      {"type": "bspline", "degree": 2, "knots": [0,0,0,1,1,1], "points": [[0.5,0.55],[0.75,0.55],[0.75,0]]}]}})";
  const Job j = parse_job(job(std::string(kPatch) + "," + arch), "t.json");
  EXPECT_EQ(j.entities[1].surface, j.entities[0].surface);  // shared, not copied
  EXPECT_EQ(j.entities[1].uv_curve.pieces.size(), 2u);
  EXPECT_EQ(j.entities[1].uv_curve.dim, 2);
  // Before its patch, or inline: the same.
  EXPECT_NO_THROW(parse_job(job(arch + "," + kPatch), "t.json"));
  std::string inl = arch;
  inl.replace(inl.find("\"p\""), 3, kInlinePatch);
  const Job k = parse_job(job(inl), "t.json");
  ASSERT_TRUE(k.entities[0].surface);
  EXPECT_EQ(evaluate(*k.entities[0].surface, 0.5, 0.5), evaluate(*j.entities[0].surface, 0.5, 0.5));
}

TEST(JobJsonSurfaces, CurveOnSurfaceRefusals) {
  const std::string c = R"("curve": {"type": "bezier", "points": [[0.1,0.1],[0.9,0.9]]})";
  EXPECT_EQ(refusal(job(std::string(kPatch) + R"(, {"type": "curve_on_surface", "surface": "q", )" + c + "}")),
            "t.json: entities[1].surface: expected the id of a bezier_patch or coons_patch entity, found \"q\", "
            "which no entity has");
  EXPECT_EQ(
      refusal(job(R"({"id": "a", "type": "bezier", "points": [[0,0],[1,1]]}, {"type": "curve_on_surface",
                           "surface": "a", )" +
                  c + "}")),
      "t.json: entities[1].surface: expected the id of a bezier_patch or coons_patch entity, found \"a\", a bezier");
  EXPECT_EQ(refusal(job(std::string(kPatch) + R"(, {"type": "curve_on_surface", "surface": "p",
                           "curve": {"type": "bezier", "points": [[0.1,0.1],[1.2,0.5],[0.9,0.9]]}})")),
            "t.json: entities[1].curve: expected a curve in the patch's parameter square [0,1]^2 (u, v), found a "
            "control point (1.2, 0.5) of its Bézier form outside it");
  EXPECT_EQ(refusal(job(std::string(kPatch) + R"(, {"type": "curve_on_surface", "surface": "p",
                           "curve": {"type": "bezier", "points": [[0.1,0.1,0],[0.9,0.9,0]]}})")),
            "t.json: entities[1].curve: expected a 2D curve of (u, v) parameters, found 3D points");
  EXPECT_EQ(refusal(job(std::string(kPatch) + R"(, {"type": "curve_on_surface", "surface": 3, )" + c + "}")),
            "t.json: entities[1].surface: expected a patch object or the id of a patch entity, found 3");
}

TEST(JobJsonSurfaces, GougeKeyOnJobAndEntity) {
  const Job j = parse_job(job(std::string(kPatch) + R"(, {"type": "bezier_patch", "gouge": "refuse",
      "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]]})",
                              R"(, "gouge": "skip")"),
                          "t.json");
  EXPECT_EQ(j.params.gouge, GougePolicy::skip);
  EXPECT_EQ(j.entities[0].params.over(j.params).gouge, GougePolicy::skip);
  EXPECT_EQ(j.entities[1].params.over(j.params).gouge, GougePolicy::refuse);
  EXPECT_TRUE(j.warnings.empty());
  EXPECT_EQ(refusal(job(kPatch, R"(, "gouge": "ignore")")),
            "t.json: job.gouge: expected \"refuse\" or \"skip\", found the string \"ignore\"");
}

}  // namespace
}  // namespace bezcam
