// The allocation of adaptive sampling (render/adaptive.h): the budget spent exactly, counts
// in proportion to the target density, the floor, the cap; no GL.
#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>

#include "render/adaptive.h"

using namespace pt;

namespace {

double pixel_samples(const std::vector<int>& pixels, const std::vector<int>& spp) {
  double s = 0;
  for (size_t t = 0; t < pixels.size(); ++t) s += double(pixels[t]) * spp[t];
  return s;
}

}  // namespace

TEST_CASE("adaptive: the tile grid cuts the last row and column short", "[adaptive]") {
  TileCounts c;
  c.reset(40, 20, 16);  // 3 x 2 tiles: 16, 16, 8 columns; 16, 4 rows
  REQUIRE(c.tiles_x() == 3);
  REQUIRE(c.tiles_y() == 2);
  CHECK(c.pixels() == std::vector<int>{256, 256, 128, 64, 64, 32});
  CHECK(std::accumulate(c.pixels().begin(), c.pixels().end(), 0) == 40 * 20);
}

TEST_CASE("adaptive: each sweep spends its budget, to the sample over a run", "[adaptive]") {
  const std::vector<int> pixels{256, 256, 128, 64, 64, 32};
  const std::vector<double> w{1.0, 3.0, 0.5, 8.0, 0.25, 2.0};
  std::vector<int> counts(pixels.size(), 8);
  std::vector<double> credit(pixels.size(), 0.0);
  const double P = std::accumulate(pixels.begin(), pixels.end(), 0.0);
  double spent = 0, asked = 0;
  for (int sweep = 0; sweep < 200; ++sweep) {
    const int spp = 1 + sweep % 3;
    const std::vector<int> s = allocate_sweep(pixels, counts, w, spp * P, 64, credit);
    for (size_t t = 0; t < s.size(); ++t) {
      CHECK(s[t] >= 0);
      counts[t] += s[t];
    }
    spent += pixel_samples(pixels, s);
    asked += spp * P;
    // What was not spent is the fractions carried over: under one sample per tile.
    double carried = 0;
    for (size_t t = 0; t < pixels.size(); ++t) carried += credit[t] * pixels[t];
    CHECK(std::abs(asked - spent - carried) < 1e-6 * asked);
    CHECK(asked - spent < P);
    CHECK(asked - spent >= -1e-6 * asked);
  }
}

TEST_CASE("adaptive: counts move to the target density, sqrt of the relative variance", "[adaptive]") {
  const std::vector<int> pixels(4, 256);
  const std::vector<double> rel_var{1.0, 4.0, 16.0, 0.25};  // sqrt: 1, 2, 4, 0.5
  const std::vector<double> w = tile_weights(pixels, rel_var, 0.0);
  REQUIRE(w == std::vector<double>{1.0, 2.0, 4.0, 0.5});
  std::vector<int> counts(4, 8);
  std::vector<double> credit(4, 0.0);
  for (int sweep = 0; sweep < 100; ++sweep) {
    const std::vector<int> s = allocate_sweep(pixels, counts, w, 4.0 * 4 * 256, 64, credit);
    for (size_t t = 0; t < 4; ++t) counts[t] += s[t];
  }
  // 8 + 100 x 4 = 408 spp on average; the targets n_t = 408 x 4 w_t / sum w (7.5).
  const double mean = std::accumulate(counts.begin(), counts.end(), 0.0) / 4.0;
  CHECK(mean == Approx(408.0).margin(1.0));
  for (size_t t = 0; t < 4; ++t) {
    INFO("tile " << t << ": " << counts[t]);
    CHECK(counts[t] == Approx(mean * 4.0 * w[t] / 7.5).margin(2.0));
  }
}

TEST_CASE("adaptive: a tile that reads as noiseless keeps the floor", "[adaptive]") {
  const std::vector<int> pixels(4, 100);
  const std::vector<double> w = tile_weights(pixels, {0.0, 1.0, 1.0, 1.0}, 0.25);
  // The floor is 0.25 x the mean of sqrt(r): 0.25 x 0.75.
  CHECK(w[0] == Approx(0.1875));
  CHECK(w[1] == 1.0);
  std::vector<int> counts(4, 8);
  std::vector<double> credit(4, 0.0);
  for (int sweep = 0; sweep < 200; ++sweep) {
    const std::vector<int> s = allocate_sweep(pixels, counts, w, 2.0 * 400, 64, credit);
    for (size_t t = 0; t < 4; ++t) counts[t] += s[t];
  }
  const double mean = std::accumulate(counts.begin(), counts.end(), 0.0) / 4.0;  // 408
  INFO("counts " << counts[0] << " " << counts[1] << " " << counts[2] << " " << counts[3]);
  CHECK(counts[0] >= 0.25 * 0.75 / (0.1875 + 3.0) * 4.0 * mean - 2.0);  // its target: w_0 / mean w
  CHECK(counts[0] > 0.05 * mean);
  CHECK(counts[1] == Approx(counts[2]).margin(1));
  // Every r_t = 0 (a constant image): uniform.
  CHECK(tile_weights(pixels, {0.0, 0.0, 0.0, 0.0}, 0.25) == std::vector<double>(4, 1.0));
}

TEST_CASE("adaptive: a tile at the cap gives its share to the others", "[adaptive]") {
  const std::vector<int> pixels(3, 100);
  const std::vector<double> w{100.0, 1.0, 1.0};
  std::vector<int> counts(3, 8);
  std::vector<double> credit(3, 0.0);
  const std::vector<int> s = allocate_sweep(pixels, counts, w, 8.0 * 300, 10, credit);
  CHECK(s[0] == 10);
  CHECK(pixel_samples(pixels, s) == Approx(2400.0).margin(200.0));  // within a sample per tile
  CHECK(s[1] + s[2] >= 13);
  // Uniform weights and counts: the same for every tile.
  std::vector<double> c2(3, 0.0);
  CHECK(allocate_sweep(pixels, counts, {1.0, 1.0, 1.0}, 4.0 * 300, 64, c2) == std::vector<int>{4, 4, 4});
}

TEST_CASE("adaptive: TileCounts plans uniform sweeps, then by weight", "[adaptive]") {
  TileCounts c;
  c.reset(32, 16, 16);  // two tiles of 256
  c.plan(2, true, 64);
  c.commit();
  CHECK(c.counts() == std::vector<int>{2, 2});
  CHECK(c.uniform());
  c.set_weights({3.0, 1.0});
  c.plan(4, false, 64);  // 2048 more: targets 3 x 3072 / 1024 = 9 and 3 spp, lacking 7 and 1
  c.commit();
  CHECK(c.total() == 512.0 * 2 + 2048.0);
  CHECK(c.counts() == std::vector<int>{9, 3});
  CHECK_FALSE(c.uniform());
  c.restart();
  CHECK(c.counts() == std::vector<int>{0, 0});
  CHECK(c.total() == 0.0);
}

TEST_CASE("adaptive: a sweep's tiles are dispatched the most samples first", "[adaptive]") {
  CHECK(dispatch_order({2, 7, 0, 7, 3}) == std::vector<int>{1, 3, 4, 0, 2});  // ties in raster order
  CHECK(dispatch_order({4, 4, 4}) == std::vector<int>{0, 1, 2});
  CHECK(dispatch_order({}).empty());
  // Two threads taking half each: the heaviest and the lightest with the next two between.
  CHECK(dispatch_order({2, 7, 0, 7, 3, 1}, 2) == std::vector<int>{1, 0, 5, 3, 4, 2});  // 7+2+1 | 7+3+0
  CHECK(dispatch_order({5, 4, 3}, 4) == std::vector<int>{0, 1, 2});                     // more chunks than tiles
}
