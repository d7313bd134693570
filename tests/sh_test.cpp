// Spherical-harmonic projection of environments (render/sh.cpp) and the irradiance the
// production GLSL (shaders/sh.glsl) evaluates from it, against closed forms: a constant
// environment, a single bright texel (a near-delta source), the clamped-cosine lobe's
// known coefficients, and rotation of the map.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "gl_context.h"
#include "glsl_harness.h"
#include "render/sh.h"
#include "stats.h"

using namespace pt;

namespace {

std::shared_ptr<EnvImage> blank_map(int w, int h, float value = 0.0f) {
  auto m = std::make_shared<EnvImage>();
  m->width = w;
  m->height = h;
  m->rgba.assign(size_t(w) * h * 4, value);
  return m;
}

void set_texel(EnvImage& m, int i, int j, glm::vec3 v) {
  float* p = &m.rgba[(size_t(j) * m.width + i) * 4];
  p[0] = v.x, p[1] = v.y, p[2] = v.z;
}

// The GPU's E(n) for the given coefficients, through the production sh_irradiance.
std::vector<glm::vec3> gpu_irradiance(const ShCoeffs& c, const std::vector<glm::vec3>& normals) {
  test_gl();
  GlslKernel k("#include \"sh.glsl\"\nvec4 kernel(vec4 x, int i) { return vec4(sh_irradiance(x.xyz), 0.0); }\n");
  k.program().use();
  glUniform3fv(k.program().loc("u_sh"), 9, &c[0].x);
  std::vector<glm::vec4> in;
  for (glm::vec3 n : normals) in.emplace_back(n, 0.0f);
  std::vector<glm::vec3> out;
  for (glm::vec4 v : k.run(in)) out.emplace_back(v);
  return out;
}

std::vector<glm::vec3> test_normals() {
  std::vector<glm::vec3> n = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0, 0, -1}};
  uint32_t s = 7u;
  auto u = [&]() { return float((s = s * 1664525u + 1013904223u) >> 8) / 16777216.0f; };
  for (int i = 0; i < 60; ++i) {
    const float z = 2 * u() - 1, phi = float(2 * kPi) * u(), r = std::sqrt(1 - z * z);
    n.emplace_back(r * std::cos(phi), z, r * std::sin(phi));
  }
  return n;
}

// The direction of the centre of texel (i, j) (shaders/environment.glsl's env_dir).
glm::vec3 texel_dir(const EnvImage& m, int i, int j, float rotation_deg) {
  const double phi = 2 * kPi * (i + 0.5) / m.width + rotation_deg * kPi / 180, theta = kPi * (j + 0.5) / m.height;
  return glm::vec3(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)), float(std::sin(theta) * std::sin(phi)));
}

}  // namespace

TEST_CASE("SH: a constant environment has only L00 = 4 pi Y00 L, and E(n) = pi L", "[sh][gpu]") {
  const glm::vec3 L(0.3f, 0.6f, 2.5f);
  Environment colour;
  colour.color = L;
  Environment map;  // the same radiance as a 64x32 map (texel integrals summed)
  auto m = blank_map(64, 32);
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 64; ++i) set_texel(*m, i, j, L * 0.5f);
  map.map = m;
  map.intensity = 2.0f;
  map.rotation = 57.0f;
  for (const Environment* e : {&colour, &map}) {
    const ShCoeffs c = project_sh(*e);
    for (int ch = 0; ch < 3; ++ch) CHECK(c[0][ch] == Approx(4 * kPi * 0.28209479177 * L[ch]).epsilon(1e-5));
    for (int k = 1; k < 9; ++k)
      for (int ch = 0; ch < 3; ++ch) CHECK(std::abs(c[size_t(k)][ch]) < 1e-5f * L[ch]);
    const std::vector<glm::vec3> n = test_normals();
    const std::vector<glm::vec3> e_gpu = gpu_irradiance(c, n);
    for (size_t i = 0; i < n.size(); ++i)
      for (int ch = 0; ch < 3; ++ch) {
        CHECK(e_gpu[i][ch] == Approx(kPi * L[ch]).epsilon(1e-5));
        CHECK(sh_irradiance(c, n[i])[ch] == Approx(kPi * L[ch]).epsilon(1e-5));
      }
  }
}

TEST_CASE("SH: one bright texel projects to Y_lm(direction) times its power; E is the order-2 clamped cosine",
          "[sh][gpu]") {
  // A texel of radiance V subtending solid angle W is a source of power P = V W from its
  // centre direction d, up to O(texel size^2): L_lm = P Y_lm(d). Its irradiance truncated
  // at order 2 is P sum_l A_l (2l + 1) / (4 pi) P_l(cos g) = P (1/4 + c/2 + 5/32 (3c^2 - 1)),
  // c = n.d (the exact clamped cosine P max(c, 0), projected onto bands 0..2).
  auto m = blank_map(512, 256);
  const int ti = 300, tj = 70;
  const float V = 1000.0f;
  set_texel(*m, ti, tj, glm::vec3(V, 0.5f * V, 0.0f));
  Environment e;
  e.map = m;
  e.rotation = 33.0f;
  e.intensity = 2.0f;
  const double t0 = kPi * tj / 256, t1 = kPi * (tj + 1) / 256;
  const double P = 2.0 * V * (2 * kPi / 512) * (std::cos(t0) - std::cos(t1));
  const glm::vec3 d = texel_dir(*m, ti, tj, e.rotation);
  const ShCoeffs c = project_sh(e);
  const std::array<float, 9> y = sh_basis(d);
  for (int k = 0; k < 9; ++k) {
    INFO("coefficient " << k);
    CHECK(c[size_t(k)].x == Approx(P * y[size_t(k)]).margin(3e-4 * P));
    CHECK(c[size_t(k)].y == Approx(0.5 * P * y[size_t(k)]).margin(3e-4 * P));
    CHECK(c[size_t(k)].z == 0.0f);
  }
  const std::vector<glm::vec3> n = test_normals();
  const std::vector<glm::vec3> e_gpu = gpu_irradiance(c, n);
  for (size_t i = 0; i < n.size(); ++i) {
    const double cg = glm::dot(n[i], d);
    const double exact = P * (0.25 + 0.5 * cg + 5.0 / 32.0 * (3 * cg * cg - 1));
    INFO("n.d = " << cg);
    CHECK(e_gpu[i].x == Approx(exact).margin(1e-3 * P));
    CHECK(e_gpu[i].y == Approx(0.5 * exact).margin(1e-3 * P));
  }
}

TEST_CASE("SH: the clamped-cosine lobe's band coefficients are 0.886, 1.023, 0.495 (A_l = pi, 2pi/3, pi/4)", "[sh]") {
  // max(cos theta, 0) about +y as a map (each row holds its exact mean of cos over the
  // row's solid angle). The band norms sqrt(sum_m L_lm^2) of a zonal function are its
  // zonal coefficients, for the clamped cosine sqrt(pi)/2, sqrt(pi/3), sqrt(5 pi)/8
  // (R&H 2001, eq. 8); the convolution factors are A_l = sqrt(4 pi / (2l + 1)) times them.
  const int w = 8, h = 2048;
  auto m = blank_map(w, h);
  for (int j = 0; j < h / 2; ++j) {
    const double t0 = kPi * j / h, t1 = kPi * (j + 1) / h;
    const double mean_cos = 0.5 * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)) / (std::cos(t0) - std::cos(t1));
    for (int i = 0; i < w; ++i) set_texel(*m, i, j, glm::vec3(float(mean_cos)));
  }
  Environment e;
  e.map = m;
  const ShCoeffs c = project_sh(e);
  double band[3] = {};
  for (int k = 0; k < 9; ++k) band[sh_band(k)] += double(c[size_t(k)].x) * c[size_t(k)].x;
  const double expect[3] = {std::sqrt(kPi) / 2, std::sqrt(kPi / 3), std::sqrt(5 * kPi) / 8};
  CHECK(expect[0] == Approx(0.886227).epsilon(1e-5));
  CHECK(expect[1] == Approx(1.023327).epsilon(1e-5));
  CHECK(expect[2] == Approx(0.495416).epsilon(1e-5));
  for (int l = 0; l < 3; ++l) {
    CHECK(std::sqrt(band[l]) == Approx(expect[l]).epsilon(1e-4));
    CHECK(kShA[l] == Approx(std::sqrt(4 * kPi / (2 * l + 1)) * expect[l]).epsilon(1e-6));
  }
}

TEST_CASE("SH: rotating the map rotates the coefficients band by band", "[sh]") {
  // Rotation by a about +y maps L(d) to L(R^-1 d), so in each band the expansion is the
  // same function of R^-1 n: sum_m L'_lm Y_lm(n) = sum_m L_lm Y_lm(R^-1 n) for every n.
  auto m = blank_map(40, 20);
  uint32_t s = 99u;
  auto u = [&]() { return float((s = s * 1664525u + 1013904223u) >> 8) / 16777216.0f; };
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 40; ++i) set_texel(*m, i, j, glm::vec3(u(), u() < 0.05f ? 50.0f : u(), 0.0f));
  Environment e0, e1;
  e0.map = e1.map = m;
  e0.rotation = 10.0f;
  const float a_deg = 71.0f;
  e1.rotation = e0.rotation + a_deg;
  const ShCoeffs c0 = project_sh(e0), c1 = project_sh(e1);
  const double a = a_deg * kPi / 180, ca = std::cos(a), sa = std::sin(a);
  double norm[3] = {};
  for (int k = 0; k < 9; ++k) norm[sh_band(k)] += double(c0[size_t(k)].y) * c0[size_t(k)].y;
  for (glm::vec3 n : test_normals()) {
    // R^-1 n: phi -> phi - a in the x-z plane (phi runs from +x towards +z).
    const glm::vec3 rn(float(n.x * ca + n.z * sa), n.y, float(-n.x * sa + n.z * ca));
    const std::array<float, 9> yn = sh_basis(n), yr = sh_basis(rn);
    double f1[3] = {}, f0[3] = {};
    for (int k = 0; k < 9; ++k) {
      f1[sh_band(k)] += double(c1[size_t(k)].y) * yn[size_t(k)];
      f0[sh_band(k)] += double(c0[size_t(k)].y) * yr[size_t(k)];
    }
    for (int l = 0; l < 3; ++l) CHECK(f1[l] == Approx(f0[l]).margin(1e-5 * std::sqrt(norm[l]) + 1e-6));
  }
  // And the map was really changed by the rotation (the test is not vacuous).
  double diff = 0;
  for (int k = 1; k < 9; ++k) diff += std::abs(double(c1[size_t(k)].y) - c0[size_t(k)].y);
  CHECK(diff > 0.1 * std::sqrt(norm[1] + norm[2]));
}
