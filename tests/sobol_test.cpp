// The low-discrepancy sampler: direction numbers against the published Sobol sequence,
// and on the GPU the properties that scrambling must keep: every 1D projection of the
// first 2^m points is stratified, and dimensions 0 and 1 form a (0,m,2)-net (each
// elementary interval of area 2^-m holds exactly one point), for any pixel seed.
#include <catch2/catch.hpp>

#include "glsl_harness.h"
#include "core/sobol.h"

using namespace pt;

TEST_CASE("Sobol direction numbers give the published sequence", "[sobol]") {
  // new-joe-kuo-6.21201, first 8 points of dimensions 1..4 (here 0..3), in natural
  // index order (x_i = XOR of the direction numbers of i's set bits), worked out by hand
  // from the recurrences; they are scipy's unscrambled Sobol points in its Gray-code order.
  const double expected[4][8] = {{0, .5, .25, .75, .125, .625, .375, .875},
                                 {0, .5, .75, .25, .625, .125, .375, .875},
                                 {0, .5, .75, .25, .375, .875, .625, .125},
                                 {0, .5, .75, .25, .125, .625, .875, .375}};
  for (int d = 0; d < 4; ++d)
    for (uint32_t i = 0; i < 8; ++i) CHECK(sobol_sample(i, d) / 4294967296.0 == expected[d][i]);
}

TEST_CASE("the shader's Sobol points equal the CPU's, bit for bit", "[gpu][sobol]") {
  GlslKernel k("vec4 kernel(vec4 x, int i) {\n  return vec4(uvec4(sobol4(uint(i) * 2654435761u) >> 8u));\n}\n");
  const int n = 4096;
  const std::vector<glm::vec4> p = k.run(std::vector<glm::vec4>(size_t(n), glm::vec4(0.0f)));
  int wrong = 0;
  for (int i = 0; i < n; ++i) {
    const uint32_t index = uint32_t(i) * 2654435761u;  // all 32 bits in play
    for (int d = 0; d < 4; ++d) wrong += uint32_t(p[size_t(i)][d]) != sobol_sample(index, d) >> 8;
  }
  CHECK(wrong == 0);
}

TEST_CASE("scrambled Sobol points keep stratification and the (0,m,2)-net property", "[gpu][sobol]") {
  GlslKernel k(
      "vec4 kernel(vec4 x, int i) {\n  uint seed = pcg_hash(uint(x.x));\n"
      "  return owen_sobol4(uint(i % 256), seed);\n}\n");
  const int m = 8, n = 1 << m;
  for (int seed = 0; seed < 4; ++seed) {
    const std::vector<glm::vec4> p = k.run(std::vector<glm::vec4>(size_t(n), glm::vec4(float(seed * 7919 + 3))));
    for (int d = 0; d < 4; ++d) {
      std::vector<int> bins(size_t(n), 0);
      for (const glm::vec4& v : p) ++bins[size_t(std::min(n - 1, int(v[d] * n)))];
      INFO("seed " << seed << " dim " << d);
      CHECK(*std::min_element(bins.begin(), bins.end()) == 1);
    }
    for (int a = 0; a <= m; ++a) {
      const int nx = 1 << a, ny = 1 << (m - a);
      std::vector<int> cells(size_t(n), 0);
      for (const glm::vec4& v : p) ++cells[size_t(std::min(ny - 1, int(v.y * ny)) * nx + std::min(nx - 1, int(v.x * nx)))];
      INFO("seed " << seed << " intervals " << nx << "x" << ny);
      CHECK(*std::max_element(cells.begin(), cells.end()) == 1);
    }
  }
}
