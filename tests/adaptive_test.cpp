// Adaptive sampling on the GPU (render/adaptive.h, PT_ADAPTIVE in camera_pass.glsl): every
// pixel stays the plain mean of its own samples. The samples of a pixel are a fixed
// sequence (sample index 0, 1, 2, ... of the pixel's sampler), so a pixel whose tile got n
// samples must read what a uniform render of n samples per pixel reads there, whatever
// the other tiles got and however its n was split across sweeps; and a scene with a
// closed form converges to it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <vector>

#include "gl_context.h"
#include "scene/xml_loader.h"
#include "scene_builders.h"
#include "test_paths.h"

using namespace pt;

namespace {

std::vector<float> uniform_render(const Scene& scene, int w, int h, int spp, bool compute) {
  Renderer r;
  r.resize(w, h);
  RenderSettings st;
  st.compute = compute;
  st.sample_limit = spp;
  st.spp_per_pass = 1;
  r.set_settings(st);
  r.set_scene(scene);
  while (!r.converged()) r.step();
  return r.read_radiance();
}

}  // namespace

TEST_CASE("adaptive: each pixel is the mean of its own samples", "[gpu][adaptive]") {
  test_gl();
  const Scene scene = load_scene_file(repo_path("scenes/cornell-box.xml"));
  const int w = 70, h = 45;  // the last tiles' row and column cut short
  // Bands that cut tiles of counts (both kernels), and whole sweeps, which the compute
  // kernel dispatches tile by tile, the most samples first (Accumulator::ordered_dispatch).
  for (auto [compute, bands] : {std::pair{false, 20}, std::pair{true, 20}, std::pair{true, 0}}) {
    Renderer r;
    r.resize(w, h);
    RenderSettings st;
    st.compute = compute;
    st.adaptive = true;
    st.sample_limit = 40;
    st.spp_per_pass = 3;  // sweeps of 3 on average: tiles get other splits than 1, 1, 1, ...
    st.band_rows = bands;
    r.set_settings(st);
    r.set_scene(scene);
    while (!r.converged()) r.step();
    const TileCounts* c = r.accumulator().tile_counts();
    REQUIRE(c);
    REQUIRE(r.samples() == 40);
    const std::vector<float> img = r.read_radiance();
    std::map<int, int> tiles_of;  // count -> tiles
    for (int n : c->counts()) ++tiles_of[n];
    std::printf("adaptive (%s, %s): %zu tiles, counts", compute ? "compute" : "fragment", bands ? "bands" : "whole sweeps",
                c->counts().size());
    for (auto [n, k] : tiles_of) std::printf(" %d:%d", n, k);
    std::printf("; %.2f spp on average\n", c->total() / (w * h));
    REQUIRE(tiles_of.size() >= 3);  // the counts differ, or this proves nothing
    CHECK(c->total() / (w * h) == Approx(40.0).margin(1.0));
    // Each count of tiles that see something (the image's black margins read as noiseless
    // and keep the floor): a uniform render of that many samples.
    std::map<int, double> brightest;  // count -> its pixels' largest value
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int k = 0; k < 3; ++k) brightest[c->at(x, y)] = std::max(brightest[c->at(x, y)], double(img[(size_t(y) * w + x) * 4 + k]));
    std::vector<int> lit;
    for (auto [n, v] : brightest)
      if (v > 0) lit.push_back(n);
    REQUIRE(lit.size() >= 3);
    // Every count: a tile that a sweep missed or drew twice (a wrong dispatch order) would
    // show wherever it is.
    std::set<int> picks(lit.begin(), lit.end());
    for (int n : picks) {
      const std::vector<float> ref = uniform_render(scene, w, h, n, compute);
      double worst = 0, largest = 0;
      int pixels = 0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          if (c->at(x, y) != n) continue;
          ++pixels;
          for (int k = 0; k < 3; ++k) {
            const size_t i = (size_t(y) * w + x) * 4 + k;
            worst = std::max(worst, std::abs(double(img[i]) - ref[i]) / (std::abs(double(ref[i])) + 1e-3));
            largest = std::max(largest, double(ref[i]));
          }
        }
      std::printf("  %d spp: %d pixels, max relative difference from a uniform %d spp render %.3g (max value %.3g)\n", n, pixels,
                  n, worst, largest);
      INFO(n << " spp, " << (compute ? "compute" : "fragment") << (bands ? ", bands" : ", whole sweeps"));
      CHECK(pixels > 0);
      CHECK(largest > 0.0);
      // Float rounding only: the running mean is blended in other steps (3 + 2 + 4 ...
      // instead of 1 + 1 + 1 ...).
      CHECK(worst < 1e-5);
    }
  }
}

TEST_CASE("adaptive: the closed room converges to Le / (1 - rho)", "[gpu][adaptive]") {
  test_gl();
  Material wall;
  wall.tint = glm::vec3(0.5f);
  wall.emission = glm::vec3(1.0f);
  const Scene scene = closed_room(wall);
  Renderer r;
  r.resize(48, 48);
  RenderSettings st;
  st.adaptive = true;
  st.max_bounces = 64;
  st.sample_limit = 64;
  st.spp_per_pass = 4;
  r.set_settings(st);
  r.set_scene(scene);
  while (!r.converged()) r.step();
  const std::vector<float> img = r.read_radiance();
  double sum = 0, var = 0;
  const TileCounts* c = r.accumulator().tile_counts();
  REQUIRE(c);
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x) {
      const size_t i = (size_t(y) * 48 + x) * 4;
      sum += img[i + 1];
      var += img[i + 3] / c->at(x, y);  // the luminance variance of the samples / this pixel's count
    }
  const double mean = sum / (48 * 48), se = std::sqrt(var) / (48 * 48);
  std::printf("closed room, adaptive: mean %.5f (exact %.5f), standard error %.3g\n", mean, 2.0 - std::ldexp(2.0, -64), se);
  CHECK(se > 0.0);
  CHECK(std::abs(mean - 2.0) < 4.0 * se + 1e-5);
}
