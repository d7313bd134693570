// Every tone map of shaders/tonemap.glsl (the display program's GLSL, run through the
// harness) against its published curve evaluated here in double precision, at values
// across the range, with exposure; plus anchor values that identify each curve.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "gl_context.h"
#include "glsl_harness.h"
#include "render/renderer.h"
#include "core/tonemap.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

double clamp01(double x) { return std::min(1.0, std::max(0.0, x)); }
double gamma22(double x) { return std::pow(clamp01(x), 1.0 / 2.2); }
double srgb(double x) {
  x = clamp01(x);
  return x < 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}
double hable(double x) {  // Hable's Uncharted 2 operator (filmicgames.com/archives/75)
  const double A = 0.15, B = 0.50, C = 0.10, D = 0.20, E = 0.02, F = 0.30;
  return (x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F) - E / F;
}

// The curves, as published; x is radiance times exposure.
double curve(ToneMap op, double x) {
  x = std::max(0.0, x);
  switch (op) {
    case ToneMap::None: return clamp01(x);
    case ToneMap::Linear: return gamma22(x);
    case ToneMap::Reinhard: return gamma22(x / (1 + x));
    case ToneMap::Filmic: {  // Hejl and Burgess-Dawson, gamma built in
      const double y = std::max(0.0, x - 0.004);
      return y * (6.2 * y + 0.5) / (y * (6.2 * y + 1.7) + 0.06);
    }
    case ToneMap::Srgb: return srgb(x);
    case ToneMap::Uncharted2: return gamma22(hable(2 * x) / hable(11.2));
    case ToneMap::Aces:  // Narkowicz's fit, then the sRGB curve
      return srgb(clamp01(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14)));
  }
  return -1;
}

// tone_map(vec3(v), op, exposure).r for each input (v, op, exposure).
std::vector<float> gpu_tone_map(const std::vector<glm::vec4>& in) {
  test_gl();
  GlslKernel k("#include \"tonemap.glsl\"\n"
               "vec4 kernel(vec4 x, int i) { return vec4(tone_map(vec3(x.x, x.x, 0.5 * x.x), int(x.y), x.z), 0.0); }\n");
  std::vector<float> out;
  for (glm::vec4 v : k.run(in)) out.push_back(v.x);
  return out;
}

}  // namespace

TEST_CASE("tone maps: each GLSL curve equals its closed form, with exposure", "[tonemap][gpu]") {
  REQUIRE(kNumToneMaps == 7);
  const double values[] = {0.0, 1e-4, 0.002, 0.01, 0.18, 0.5, 1.0, 2.0, 5.6, 11.2, 100.0};
  const float exposures[] = {1.0f, 0.25f, 3.0f};
  std::vector<glm::vec4> in;
  for (int op = 0; op < kNumToneMaps; ++op)
    for (float e : exposures)
      for (double v : values) in.emplace_back(float(v), float(op), e, 0.0f);
  const std::vector<float> out = gpu_tone_map(in);
  for (size_t i = 0; i < in.size(); ++i) {
    const ToneMap op = ToneMap(int(in[i].y));
    const double exact = curve(op, double(in[i].x) * in[i].z);
    INFO(kToneMapNames[int(op)] << "(" << in[i].x << " x exposure " << in[i].z << ")");
    CHECK(out[i] == Approx(exact).margin(2e-5).epsilon(1e-4));
  }
}

TEST_CASE("tone maps: anchor values that tell the curves apart", "[tonemap][gpu]") {
  struct A {
    ToneMap op;
    float x;
    double expect;
  };
  const A anchors[] = {
      {ToneMap::None, 0.5f, 0.5},          {ToneMap::None, 3.0f, 1.0},
      {ToneMap::Linear, 0.5f, 0.72974005}, // 0.5^(1/2.2)
      {ToneMap::Reinhard, 1.0f, 0.72974005},  // (1/2)^(1/2.2)
      {ToneMap::Filmic, 0.004f, 0.0},      {ToneMap::Srgb, 0.0031308f, 0.040449936},
      {ToneMap::Srgb, 1.0f, 1.0},          {ToneMap::Uncharted2, 5.6f, 1.0},  // the white point 11.2 after the 2x bias
      {ToneMap::Aces, 1000.0f, 1.0},       {ToneMap::Aces, 0.0f, 0.0}};
  std::vector<glm::vec4> in;
  for (const A& a : anchors) in.emplace_back(a.x, float(int(a.op)), 1.0f, 0.0f);
  const std::vector<float> out = gpu_tone_map(in);
  for (size_t i = 0; i < in.size(); ++i) {
    INFO(kToneMapNames[int(anchors[i].op)] << "(" << anchors[i].x << ")");
    CHECK(out[i] == Approx(anchors[i].expect).margin(1e-4));
  }
}

// The display pass compiles one program per tone map (the map a constant, so that a
// software GL does not run every map's branch for every pixel): each must show the
// estimate through its own curve.
TEST_CASE("tone maps: the display program of each map shows the estimate through its curve", "[tonemap][gpu]") {
  test_gl();
  Renderer r;
  r.resize(24, 16);
  RenderSettings s;
  s.sample_limit = 2;
  r.set_settings(s);
  r.set_scene(load_scene_file(repo_path("scenes/reference/scene2.xml")));
  while (!r.converged()) r.step();
  const std::vector<float> radiance = r.read_radiance();
  for (int op = 0; op < kNumToneMaps; ++op) {
    s.tonemap = ToneMap(op);
    s.exposure = 0.7f;
    r.set_settings(s);
    CHECK(r.samples() == 2);  // display settings keep the estimate
    const std::vector<uint8_t> shown = r.read_display();
    int worst = 0;
    for (size_t i = 0; i < shown.size(); ++i) {
      if (i % 4 == 3) continue;
      const double want = 255.0 * curve(ToneMap(op), double(radiance[i]) * s.exposure);
      worst = std::max(worst, int(std::ceil(std::abs(shown[i] - want))));
    }
    INFO(kToneMapNames[op]);
    CHECK(worst <= 1);  // 8-bit rounding
  }
}
