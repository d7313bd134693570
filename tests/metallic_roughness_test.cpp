// MetallicRoughness (the glTF 2.0 BSDF, materials/metallic_roughness.h) against closed
// forms: its smooth lobe reflects Schlick's Fresnel of the right f0 (the base colour for a
// metal, ((ior - 1) / (ior + 1))^2 = 0.04 at ior 1.5 for a dielectric); a smooth white
// metal is a perfect mirror (a furnace of exactly 1); the rough lobes' sampled weights are
// f cos / pdf of the evaluated BSDF. Its chi-square test and the surface step's bound (at
// most 1 under a sky of 1, in every mode) come from the tests that loop over every kind.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "gl_context.h"
#include "glsl_harness.h"
#include "scene_builders.h"
#include "stats.h"

using namespace pt;

namespace {

// The mean sampled weight (red channel) of material m at incidence cos_o, over n samples.
Estimate mean_weight(const Material& m, double cos_o, int n = 200000) {
  char wo[128];
  std::snprintf(wo, sizeof wo, "const vec3 WO = vec3(%.9f, 0.0, %.9f);\n", std::sqrt(1 - cos_o * cos_o), cos_o);
  GlslKernel k(glsl_material(m) + wo +
               "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 31u), 0u);\n  BsdfSample s;\n"
               "  if (!material_sample(make_material(), WO, true, vec3(rand01(), rand01(), rand01()), s)) return vec4(0.0);\n"
               "  return vec4(s.weight, s.delta ? 1.0 : 0.0);\n}\n");
  double sum = 0, sq = 0;
  for (const glm::vec4& v : k.run(n)) sum += v.x, sq += double(v.x) * v.x;
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sq / n - mean * mean) / n)};
}

}  // namespace

TEST_CASE("MetallicRoughness: the smooth lobe reflects Schlick's Fresnel of its f0", "[gpu][sampling]") {
  test_gl();
  for (double c : {1.0, 0.5, 0.1}) {
    // A smooth metal of base colour 0.3: a mirror of reflectance F(f0 = 0.3), every sample.
    const Estimate metal = mean_weight(Material(MetallicRoughness{.baseColor = glm::vec3(0.3f), .metallic = 1.0f, .roughness = 0.0f}), c);
    INFO("metal, cos " << c << ": " << metal.mean << " vs " << schlick(0.3, c));
    CHECK(metal.se < 1e-6);
    CHECK(std::abs(metal.mean - schlick(0.3, c)) < 1e-5);
    // A smooth dielectric over a black base (ior 1.5): only the coat reflects, F(f0 = 0.04),
    // reached through the lobe choice (weight F / p_s with probability p_s).
    const Estimate coat = mean_weight(Material(MetallicRoughness{.baseColor = glm::vec3(0.0f), .metallic = 0.0f, .roughness = 0.0f}), c);
    INFO("coat, cos " << c << ": " << coat.mean << " (se " << coat.se << ") vs " << schlick(0.04, c));
    CHECK(std::abs(coat.mean - schlick(0.04, c)) < 4 * coat.se + 1e-6);
  }
}

TEST_CASE("MetallicRoughness: a smooth white metal is a perfect mirror (furnace of 1)", "[gpu][transport]") {
  test_gl();
  RenderSettings st;
  st.max_bounces = 64;
  Scene s;
  s.camera = camera_looking_down_z(glm::vec3(0.0f, 0.0f, 4.0f));
  s.environment.color = glm::vec3(1.0f);
  add_sphere(s, glm::vec3(0.0f), 1.0f, add_material(s, MetallicRoughness{.metallic = 1.0f, .roughness = 0.0f}));
  const RenderResult r = render_scene(s, 64, 64, 16, st);
  const Estimate e = region_mean(r, 24, 24, 40, 40);
  std::printf("furnace: smooth white MetallicRoughness metal %.6f (se %.6f)\n", e.mean, e.se);
  CHECK(r.counters.bad_samples == 0);
  CHECK(std::abs(e.mean - 1.0) < 1e-5);
}

TEST_CASE("MetallicRoughness: sampled weights equal f cos / pdf of the evaluated BSDF", "[gpu][sampling]") {
  test_gl();
  for (float metallic : {0.0f, 0.4f, 1.0f})
    for (float roughness : {0.2f, 0.7f}) {
      const Material m = MetallicRoughness{.baseColor = glm::vec3(0.8f, 0.5f, 0.2f), .metallic = metallic, .roughness = roughness};
      const float worst = sampled_weight_error(m, glm::vec3(0.6f, 0.0f, 0.8f));
      INFO("metallic " << metallic << " roughness " << roughness);
      CHECK(worst < 1e-4f);
    }
}
