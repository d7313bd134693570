// render --count-ops (RenderSettings::count_ops): the camera pass counts the traversal's
// box and primitive tests (bvh.glsl) into the statistics in place of the variance, for the
// operation counts behind docs/benchmarks.md's fraction of the GPU's peak. The counts are
// checked where they are known exactly, and the image must not change with them.
#include <catch2/catch.hpp>

#include <cmath>

#include "accel_run.h"
#include "render/renderer.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

AccelRun run_counted(const Scene& scene, Accel accel, bool compute, bool count, bool nee) {
  RenderSettings st;
  st.accel = accel;
  st.compute = compute;
  st.count_ops = count;
  st.nee = nee;
  st.sample_limit = 4;
  st.spp_per_pass = 2;
  return run_render(scene, st, 23, 19);
}

// Five analytic primitives, no planes: a flat loop tests all five on every nearest-hit query.
const char* kFive =
    "<SceneLevel><Camera position=\"0 1 6\" yaw=\"90\"/><Objects>"
    "<Sphere center=\"-1.5 0 0\" radius=\"0.7\"><Diffuse/></Sphere>"
    "<Sphere center=\"1.5 0 0\" radius=\"0.7\"><Diffuse/></Sphere>"
    "<Box min=\"-3 -1.2 -3\" max=\"3 -1 3\"><Diffuse/></Box>"
    "<Box min=\"-0.4 -1 -1\" max=\"0.4 0.5 -0.2\"><Diffuse/></Box>"
    "<Sphere center=\"0 4 0\" radius=\"1\"><Emit><Absorb intensity=\"4\" color=\"1 1 1\"/></Emit></Sphere>"
    "</Objects></SceneLevel>";

}  // namespace

TEST_CASE("count-ops: exact counts where they are known, and the same image", "[gpu][accel]") {
  const Scene five = load_scene_text(kFive, repo_path("scenes/count-ops.xml"));
  for (bool compute : {false, true}) {
    INFO((compute ? "compute kernel" : "fragment pass"));
    // BSDF sampling only: every query is a nearest hit, and a flat loop tests every
    // primitive for each, so primitive tests = 5 x rays exactly; no node is visited.
    const AccelRun flat = run_counted(five, Accel::Flat, compute, true, false);
    REQUIRE(flat.counters.rays > 23 * 19 * 4);
    CHECK(flat.counters.prim_tests == 5 * flat.counters.rays);
    CHECK(flat.counters.box_tests == 0);
    // The BVH: the root's box is tested once per ray and each interior node visited adds
    // its two children's, so box tests - rays is even and at least 0; it tests no more
    // primitives than the loop, and fewer here (the spheres and boxes are apart).
    const AccelRun bvh = run_counted(five, Accel::Bvh, compute, true, false);
    CHECK(bvh.counters.rays == flat.counters.rays);
    CHECK(bvh.counters.box_tests >= bvh.counters.rays);
    CHECK(std::fmod(bvh.counters.box_tests - bvh.counters.rays, 2.0) == 0.0);
    CHECK(bvh.counters.prim_tests > 0);
    CHECK(bvh.counters.prim_tests < flat.counters.prim_tests);
    // Counting changes the statistics' z and w only: the mean is the same, bit for bit.
    const AccelRun plain = run_counted(five, Accel::Bvh, compute, false, false);
    CHECK(plain.counters.box_tests == 0);
    CHECK(plain.counters.prim_tests == 0);
    bool same = plain.rgba.size() == bvh.rgba.size();
    for (size_t i = 0; same && i < plain.rgba.size(); i += 4)
      same = plain.rgba[i] == bvh.rgba[i] && plain.rgba[i + 1] == bvh.rgba[i + 1] && plain.rgba[i + 2] == bvh.rgba[i + 2];
    CHECK(same);
    // With next-event estimation a shadow query ends at its first hit: fewer than five tests
    // per ray on average, but more than one.
    const AccelRun nee = run_counted(five, Accel::Flat, compute, true, true);
    CHECK(nee.counters.prim_tests < 5 * nee.counters.rays);
    CHECK(nee.counters.prim_tests > nee.counters.rays);
  }
  // A camera looking away from everything: one ray per sample, which misses the root.
  const Scene away = load_scene_text(
      "<SceneLevel><Camera position=\"0 0 5\" yaw=\"270\"/><Objects><Sphere center=\"0 0 0\" radius=\"1\"><Diffuse/></Sphere>"
      "<Sphere center=\"3 0 0\" radius=\"1\"><Diffuse/></Sphere></Objects></SceneLevel>",
      repo_path("scenes/count-ops.xml"));
  const AccelRun sky = run_counted(away, Accel::Bvh, true, true, true);
  CHECK(sky.counters.rays == 23 * 19 * 4);
  CHECK(sky.counters.box_tests == sky.counters.rays);
  CHECK(sky.counters.prim_tests == 0);
}
