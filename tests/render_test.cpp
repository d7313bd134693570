// GPU render tests through headless EGL: every kind compiles on the driver, values never
// recompile, and each reference scene matches its stored reference statistically.
//
// Statistical comparison: the accumulator's alpha holds the running mean of squared
// luminance, so each pixel's variance of the mean is (E[l^2] - E[l]^2) / n. The image is
// cut into 8x8 tiles; each tile's mean luminance gets a standard error from its pixels,
// and z = (mean - ref) / sqrt(se^2 + se_ref^2) must stay below kMaxZ in every tile.
// References: tests/references/<scene>.ref, made by
//   PT_WRITE_REFERENCES=1 build/native/pt_tests "[reference]"
// (kRefSpp samples per pixel, same size and settings as the test).
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/image.h"
#include "gl_context.h"
#include "render/pacing.h"
#include "render/renderer.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

constexpr int kSize = 64, kTile = 8, kTiles = kSize / kTile;
constexpr int kTestSpp = 256, kRefSpp = 16384;
constexpr double kMaxZ = 5.0;

struct TileStats {
  double mean[kTiles * kTiles];
  double se[kTiles * kTiles];
};

std::vector<float> render(const Scene& scene, int spp, RenderSettings s = {}, double* bad_samples = nullptr) {
  test_gl();
  Renderer r;
  r.resize(kSize, kSize);
  s.sample_limit = spp;
  s.spp_per_pass = 16;
  r.set_settings(s);
  r.set_scene(scene);
  while (!r.converged()) r.step();
  if (bad_samples) *bad_samples = r.counters().bad_samples;
  return r.read_radiance();
}

TileStats tile_stats(const std::vector<float>& img, int spp) {
  TileStats t{};
  for (int ty = 0; ty < kTiles; ++ty)
    for (int tx = 0; tx < kTiles; ++tx) {
      double sum = 0, var = 0;
      for (int y = ty * kTile; y < (ty + 1) * kTile; ++y)
        for (int x = tx * kTile; x < (tx + 1) * kTile; ++x) {
          const float* p = &img[(size_t(y) * kSize + x) * 4];
          const double l = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
          sum += l;
          var += double(p[3]) / spp;  // alpha: the luminance variance of the samples
        }
      const int n = kTile * kTile;
      t.mean[ty * kTiles + tx] = sum / n;
      t.se[ty * kTiles + tx] = std::sqrt(var) / n;
    }
  return t;
}

std::string ref_path(const std::string& scene) { return repo_path("tests/references/" + scene + ".ref"); }

}  // namespace

TEST_CASE("every shape and material kind compiles and links on this GL", "[gpu]") {
  test_gl();
  Features all;
  all.shapes = (1u << kNumShapeKinds) - 1;
  all.materials = (1u << kNumMaterialKinds) - 1;
  const ShaderSource src = generate_integrator(all);
  CHECK_NOTHROW(Program(fullscreen_vertex(), src));
}

TEST_CASE("a GLSL compile error on the driver names the snippet file and its line", "[gpu]") {
  test_gl();
  try {
    Program(fullscreen_vertex(),
            resolve_includes("#version 300 es\nprecision highp float;\n#include \"fresnel.glsl\"\nout vec4 o;\n"
                             "void main() { o = vec4(no_such_thing); }\n", "broken.glsl"));
    FAIL("compiled");
  } catch (const GlError& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find("broken.glsl:5:") != std::string::npos);
  }
}

TEST_CASE("editing values re-uploads data and never recompiles", "[gpu]") {
  test_gl();
  Scene s = load_scene_file(repo_path("scenes/reference/scene2.xml"));
  Renderer r;
  r.resize(8, 8);
  r.set_scene(s);
  CHECK(r.programs_compiled() == 1);
  s.lights[0].intensity = 5.0f;
  s.materials[0].tint = glm::vec3(0.2f);
  s.shapes[3].as<Box>()->min.x += 1.0f;
  r.set_scene(s);
  CHECK(r.programs_compiled() == 1);
  r.step();
  CHECK(r.samples() == 1);
  RenderSettings st;
  st.max_bounces = 3;
  r.set_settings(st);
  CHECK(r.samples() == 0);  // a transport change restarts
}

TEST_CASE("reference scenes: no NaN/Inf and tile statistics match the reference", "[gpu][render]") {
  for (const char* name : {"scene0", "scene1", "scene2"}) {
    DYNAMIC_SECTION(name) {
      const Scene scene = load_scene_file(repo_path(std::string("scenes/reference/") + name + ".xml"));
      double bad_samples = -1;
      const std::vector<float> img = render(scene, kTestSpp, {}, &bad_samples);
      const ImageStats st = image_stats(img);
      CHECK(bad_samples == 0);  // counted per sample in the shader
      REQUIRE(st.bad == 0);
      const TileStats t = tile_stats(img, kTestSpp);
      std::ifstream in(ref_path(name));
      REQUIRE(in.good());
      int size = 0, spp = 0;
      in >> size >> spp;
      REQUIRE(size == kSize);
      double worst = 0;
      int worst_tile = -1;
      for (int i = 0; i < kTiles * kTiles; ++i) {
        double m = 0, se = 0;
        in >> m >> se;
        // The reference has seen far more of the tail of each pixel's distribution (caustics,
        // fireflies), so its variance, scaled to the test's sample count, is the better
        // estimate of the test's own standard error; take the larger of the two.
        const double se_test = std::max(t.se[i], se * std::sqrt(double(spp) / kTestSpp));
        const double z = std::abs(t.mean[i] - m) / std::sqrt(se_test * se_test + se * se + 1e-12);
        if (z > worst) worst = z, worst_tile = i;
      }
      REQUIRE(in.good());
      INFO(name << ": worst tile " << worst_tile << " |z| = " << worst);
      CHECK(worst < kMaxZ);
    }
  }
}

TEST_CASE("write references (run explicitly with PT_WRITE_REFERENCES=1)", "[.reference]") {
  if (!std::getenv("PT_WRITE_REFERENCES")) return;
  for (const char* name : {"scene0", "scene1", "scene2"}) {
    const Scene scene = load_scene_file(repo_path(std::string("scenes/reference/") + name + ".xml"));
    const TileStats t = tile_stats(render(scene, kRefSpp), kRefSpp);
    std::ofstream out(ref_path(name));
    out << kSize << " " << kRefSpp << "\n";
    out.precision(9);
    for (int i = 0; i < kTiles * kTiles; ++i) out << t.mean[i] << " " << t.se[i] << "\n";
  }
}

TEST_CASE("bands of rows give exactly the whole-image estimate", "[gpu][tiles]") {
  test_gl();
  const Scene scene = load_scene_file(repo_path("scenes/reference/scene2.xml"));
  RenderSettings whole, bands;
  bands.band_rows = 7;  // does not divide the height: the last band is short
  const std::vector<float> a = render(scene, 32, whole), b = render(scene, 32, bands);
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, double(std::abs(a[i] - b[i])));
  CHECK(worst == 0.0);  // the same samples, per pixel, in the same order
}

TEST_CASE("tiles, resized between any two draws, give exactly the whole-image estimate", "[gpu][tiles]") {
  test_gl();
  const Scene scene = load_scene_file(repo_path("scenes/reference/scene2.xml"));
  RenderSettings whole;
  const std::vector<float> a = render(scene, 32, whole);
  // A pacer may change the tile size between any two draws, mid-band too: a band keeps
  // the rows it started with, and every pixel is drawn once per sweep.
  Renderer r;
  r.resize(kSize, kSize);
  RenderSettings s;
  s.sample_limit = 32;
  s.spp_per_pass = 16;
  r.set_settings(s);
  r.set_scene(scene);
  const int sizes[][2] = {{7, 9}, {3, 0}, {5, 13}, {0, 30}, {2, 64}, {11, 1}, {4, 17}};
  int draws = 0, pixels = 0, sweeps = 0;
  double drawn = 0;  // paths of every draw: Renderer::paths() counts mid-sweep progress (tools/peers/)
  bool paths_ok = true;
  while (!r.converged()) {
    s.band_rows = sizes[draws % 7][0];
    s.band_columns = sizes[draws % 7][1];
    r.set_settings(s);
    const bool sweep_end = r.step() > 0;
    pixels += int(r.last_draw_samples() / s.spp_per_pass);
    drawn += double(r.last_draw_samples());
    paths_ok = paths_ok && r.paths() == drawn;
    ++draws;
    if (sweep_end) {
      CHECK(pixels == kSize * kSize);  // each pixel once: the estimate would differ otherwise, but say why
      pixels = 0;
      ++sweeps;
    }
  }
  CHECK(sweeps == 2);
  CHECK(draws > 2 * kSize / 11);
  CHECK(paths_ok);
  CHECK(r.paths() == 32.0 * kSize * kSize);
  const std::vector<float> b = r.read_radiance();
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, double(std::abs(a[i] - b[i])));
  CHECK(worst == 0.0);
}

TEST_CASE("a heavy scene on the software GL: every draw stays under the bound", "[.serial][gpu][tiles]") {
  test_gl();
  // scene1 at 64 bounces and 512x512: one whole-image sample takes well over the
  // bound on llvmpipe. Starting from one small band, the pacer must keep every draw below.
  const Scene scene = load_scene_file(repo_path("scenes/reference/scene1.xml"));
  const int W = 512;
  Renderer r;
  r.resize(W, W);
  RenderSettings s;
  s.max_bounces = 64;
  s.band_rows = 4;
  s.sample_limit = 3;
  r.set_settings(s);
  r.set_scene(scene);
  constexpr double kTargetMs = 25.0, kBoundMs = 100.0;
  DrawPacer pacer(kTargetMs);
  double worst = 0, total = 0;
  int draws = 0, widest = 0;
  while (!r.converged()) {
    const int rows = s.band_rows > 0 ? s.band_rows : W, spp = s.spp_per_pass;
    widest = std::max(widest, rows);
    glFinish();
    const auto t0 = std::chrono::steady_clock::now();
    r.step();
    glFinish();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    worst = std::max(worst, ms);
    total += ms;
    ++draws;
    pacer.record(ms, rows, spp);
    pacer.apply(W, s);
    r.set_settings(s);
  }
  const double per_sample = total / r.samples();
  std::printf("heavy scene: %d draws, longest %.1f ms (bound %.0f ms), mean %.1f ms, widest band %d rows; one whole-image sample takes %.0f ms\n",
              draws, worst, kBoundMs, total / draws, widest, per_sample);
  CHECK(worst < kBoundMs);
  // The bands follow the measured time: they grow from 4 rows until a draw costs about
  // the target (a pacer that kept the first size would pass the bound with tiny draws).
  CHECK(widest >= 16);
  CHECK(total / draws > kTargetMs / 4);
  CHECK(per_sample > 1.5 * kBoundMs);  // meaningful only if whole-image draws would break the bound
}

TEST_CASE("every scene shipped in scenes/ loads, compiles and renders without NaN", "[gpu][scenes]") {
  test_gl();
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(repo_path("scenes"))) {
    if (entry.path().extension() != ".xml") continue;
    INFO(entry.path().string());
    const Scene scene = load_scene_file(entry.path().string());
    double bad = -1;
    const std::vector<float> img = render(scene, 4, {}, &bad);
    CHECK(bad == 0);
    CHECK(image_stats(img).bad == 0);
    ++count;
  }
  CHECK(count >= 10);
}
