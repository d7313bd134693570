// The scene pipeline (render/pipeline.h): a scene read, packed, staged and compiled in
// slices, however small, renders bit for bit as the same scene set at once; its stages
// come in order with a progress that never goes back; a failure in any slice is thrown
// with its file and leaves the renderer's scene and samples; a scene in memory starts at
// the packing; a lost context re-stages; without a renderer it reads and packs only; the
// program of another mode is built ahead and not again at the swap.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "gl_context.h"
#include "render/pipeline.h"
#include "scene_builders.h"
#include "test_paths.h"

using namespace pt;

namespace {

const std::string kScene = mixed_scene_xml(4);

// A scene file under the build folder, written once per name.
std::string scene_file(const std::string& name, const std::string& text) {
  const std::filesystem::path dir = std::filesystem::path(PT_BINARY_DIR) / "pipeline-test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

std::vector<float> render(Renderer& r, int sweeps) {
  r.resize(48, 32);
  r.restart();
  for (int n = 0; n < sweeps;) n += r.step() > 0 ? 1 : 0;
  return r.read_radiance();
}

// The image of the scene file set at once, without the pipeline.
std::vector<float> reference(const std::string& path) {
  Renderer r;
  r.set_scene(load_scene_file(path));
  return render(r, 2);
}

}  // namespace

TEST_CASE("a scene through the pipeline in slices renders as the scene set at once", "[gpu][pipeline]") {
  test_gl();
  const std::string path = scene_file("sliced.xml", kScene);
  const std::vector<float> want = reference(path);
  for (long units : {7L, 1000L, ScenePipeline::kWorkUnits}) {
    INFO("slices of " << units << " units");
    Renderer r;
    ScenePipeline p(path, &r);
    std::vector<std::string> stages;
    double last = 0.0;
    int steps = 0;
    while (p.step(units)) {
      if (stages.empty() || stages.back() != p.stage()) stages.push_back(p.stage());
      REQUIRE(p.progress() >= last);  // never goes back
      REQUIRE(p.progress() <= 1.0);
      REQUIRE_FALSE(p.ready());
      last = p.progress();
      ++steps;
    }
    CHECK(p.progress() == Approx(1.0));
    CHECK(p.times().read_slices > 0);
    CHECK(p.times().pack_slices > 0);
    if (units == 7) CHECK(steps > 100);  // it did stop and resume
    const std::vector<std::string> order = {"generating the mesh", "building the scene", "starting the packing",
                                            "transforming, bounding", "building the BVH", "writing primitives",
                                            "writing BVH nodes", "uploading"};
    size_t at = 0;  // every stage seen is the next of the order (small slices see them all)
    for (const std::string& s : stages) {
      while (at < order.size() && order[at] != s) ++at;
      INFO("stage " << s);
      CHECK(at < order.size());
    }
    if (units == 7) CHECK(stages == order);
    CHECK(p.stage() == "compiling");
    while (!p.ready()) {
    }
    CHECK(r.samples() == 0);
    p.finish();
    CHECK(render(r, 2) == want);
    const PackedScene packed = p.take_packed();
    CHECK(packed.prims.raw() == pack_scene(load_scene_file(path)).prims.raw());
  }
}

TEST_CASE("the pipeline's work() runs the stages in slices of a time budget", "[gpu][pipeline]") {
  test_gl();
  const std::string path = scene_file("budget.xml", kScene);
  const std::vector<float> want = reference(path);
  Renderer r;
  const std::string analytic = scene_file("analytic.xml", R"(<SceneLevel><Camera position="0 0 3" yaw="90" pitch="0"/><Objects>
    <Sphere center="0 0 0" radius="0.5"><Diffuse/></Sphere></Objects></SceneLevel>)");
  ScenePipeline small(analytic, &r);
  CHECK_FALSE(small.work(1e6));  // a small scene is ready in one call with time to spare
  small.finish();
  CHECK(render(r, 2) == reference(analytic));
  Renderer r2;
  ScenePipeline p(path, &r2);
  int calls = 1;
  while (p.work(0.01)) ++calls;
  CHECK(calls > 3);  // each stage got at least one slice
  CHECK(p.times().pack_slices > 0);
  CHECK_FALSE(p.work(1.0));  // nothing left to do
  p.finish();
  CHECK(render(r2, 2) == want);
}

TEST_CASE("a failure in a slice names its file and leaves the renderer's scene", "[gpu][pipeline]") {
  test_gl();
  const std::string good = scene_file("good.xml", kScene);
  Renderer r;
  ScenePipeline first(good, &r);
  first.finish();
  render(r, 1);
  const int samples = r.samples();
  REQUIRE(samples > 0);
  const std::string broken = scene_file("broken.xml", "<SceneLevel><Objects><Sphere center=\"0 0 0\"><Diffuse/></Sphere></Objects></SceneLevel>");
  CHECK_THROWS_WITH([&] {
    ScenePipeline b(broken, &r);
    while (b.step(100)) {
    }
  }(), Catch::Contains("broken.xml:1: <Sphere>: missing attribute 'radius'"));
  ScenePipeline missing(scene_file("missing.xml", "<SceneLevel><Objects><Mesh src=\"missing.obj\"><Diffuse/></Mesh></Objects></SceneLevel>"), &r);
  CHECK_THROWS_WITH([&] { while (missing.step(100)) {} }(), Catch::Contains("missing.obj: cannot open the mesh file"));
  CHECK(r.samples() == samples);
  CHECK_THROWS_AS(ScenePipeline(scene_file("absent.xml", "") + ".none", &r), InputError);  // no such file
}

TEST_CASE("a scene in memory starts at the packing, and a lost context stages it again", "[gpu][pipeline]") {
  test_gl();
  const std::string path = scene_file("memory.xml", kScene);
  const std::vector<float> want = reference(path);
  auto lost = std::make_unique<Renderer>();
  ScenePipeline p(load_scene_file(path), lost.get());
  CHECK_FALSE(p.reading());
  CHECK(p.stage() == "transforming, bounding");
  while (p.stage() != "uploading" || p.progress() < 0.95) REQUIRE(p.step(500));  // part of the textures uploaded
  REQUIRE(p.preparing());
  Renderer r;  // the context is back: another renderer
  lost.reset();
  p.context_restored(r);
  CHECK(p.stage() == "uploading");
  CHECK(p.progress() == Approx(0.9));  // the upload starts over
  while (p.step(1000)) {
  }
  p.finish();
  CHECK(render(r, 2) == want);
}

TEST_CASE("without a renderer the pipeline reads and packs only, and on_read may change the scene", "[pipeline]") {
  const std::string path = scene_file("nogl.xml", kScene);
  ScenePipeline p(path);
  int calls = 0;
  p.on_read([&](Scene& s, const ScenePipeline::Times& t) {
    ++calls;
    CHECK(t.read_slices > 0);
    s.camera.position = glm::vec3(0, 0, 5);
  });
  std::vector<std::string> stages;
  while (p.step(ScenePipeline::kWorkUnits)) stages.push_back(p.stage());
  CHECK(calls == 1);
  CHECK(p.packed());
  CHECK_FALSE(p.preparing());
  CHECK_FALSE(p.ready());
  CHECK(std::find(stages.begin(), stages.end(), "uploading") == stages.end());
  CHECK(p.scene().camera.position == glm::vec3(0, 0, 5));
}

TEST_CASE("the pipeline builds the program of the mode the scene will be shown in, ahead", "[gpu][pipeline]") {
  test_gl();
  const std::string path = scene_file("mode.xml", kScene);
  Renderer r;  // in the path tracer's mode
  ScenePipeline p(path, &r, [](const Scene&) { return RenderMode::Whitted; });
  while (p.step(ScenePipeline::kWorkUnits)) {
  }
  while (!p.ready()) {
  }
  const size_t built = r.programs_compiled();
  CHECK(built == 1);  // the Whitted program, and no other
  RenderSettings s = r.settings();
  s.mode = RenderMode::Whitted;
  p.finish(&s);
  CHECK(r.programs_compiled() == built);  // nothing compiled at the swap
  CHECK(r.settings().mode == RenderMode::Whitted);
  Renderer whitted;
  whitted.set_settings(s);
  whitted.set_scene(load_scene_file(path));
  CHECK(render(r, 1) == render(whitted, 1));
}
