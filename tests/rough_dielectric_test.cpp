// RoughDielectric (materials/rough_dielectric.h): the GGX microfacet dielectric's sampler
// against its own density from both sides (outside: entering; inside: where total
// internal reflection takes part), at two roughnesses and a grazing incidence; its
// sampled weights against eval / pdf; a white furnace (a sphere of it under a sky of 1)
// that returns at most 1 and, when nearly smooth, nearly all of it (single scattering
// loses only what bounces between microfacets: the table is printed); and a slab that
// matches the smooth closed form (tests/media_test.cpp) as its roughness goes to 0.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "direction_chi2.h"
#include "gl_context.h"
#include "glsl_harness.h"
#include "media_scenes.h"

using namespace pt;

namespace {

constexpr int kChi2Cases = 2 * 2 * 3;  // sides x roughnesses x incidences below
const double kRoughAlpha = sidak_alpha(0.01, kChi2Cases);

Material rough(float roughness, glm::vec3 sigma = glm::vec3(0.0f)) {
  return RoughDielectric{.ior = 1.5f, .roughness = roughness, .sigma = sigma};
}

}  // namespace

TEST_CASE("RoughDielectric: chi-square of its sampler from outside and inside (total internal reflection)", "[gpu][sampling][media]") {
  test_gl();
  for (bool entering : {true, false})
    for (float r : {0.15f, 0.7f})
      for (double c : {0.9, 0.5, 0.05}) {
        const std::string side = entering ? "true" : "false";
        const std::string rec = glsl_material(rough(r));
        DirectionCase dc{rec + incident(c) + "float eval_pdf(vec3 d) { float pdf; material_eval(make_material(), WO, d, " + side +
                             ", pdf); return pdf; }\n",
                         "  BsdfSample s;\n  ok = material_sample(make_material(), WO, " + side +
                             ", vec3(rand01(), rand01(), rand01()), s) && s.pdf > 0.0;\n  wi = s.wi;",
                         "eval_pdf(d)"};
        char name[96];
        std::snprintf(name, sizeof name, "RoughDielectric %s roughness %.2f cos_o %.2f", entering ? "outside" : "inside", double(r), c);
        CHECK(direction_chi2(dc, name).p_value >= kRoughAlpha);
      }
}

TEST_CASE("RoughDielectric: sampled weights equal f cos / pdf of the evaluated BSDF", "[gpu][sampling][media]") {
  test_gl();
  for (float r : {0.1f, 0.5f, 1.0f})
    for (double c : {0.9, 0.3}) {
      const float worst = sampled_weight_error(rough(r), glm::vec3(float(std::sqrt(1 - c * c)), 0.0f, float(c)));
      INFO("roughness " << r << " cos_o " << c);
      CHECK(worst < 1e-4f);
    }
}

TEST_CASE("RoughDielectric: a white furnace returns at most 1, nearly 1 when nearly smooth", "[gpu][transport][media]") {
  test_gl();
  std::printf("RoughDielectric ior 1.5, a sphere under a sky of 1 (single scattering):\n| roughness | returned |\n|---|---|\n");
  for (float r : {0.05f, 0.2f, 0.5f, 1.0f}) {
    Scene s;
    s.camera = camera_looking_down_z(glm::vec3(0.0f, 0.0f, 4.0f));
    s.environment.color = glm::vec3(1.0f);
    add_sphere(s, glm::vec3(0.0f), 1.0f, add_material(s, rough(r)));
    RenderSettings st;
    st.max_bounces = 16;
    const RenderResult res = render_scene(s, 32, 32, 256, st);
    const Estimate e = region_mean(res, 12, 12, 20, 20);  // inside the sphere's disc
    std::printf("| %.2f | %.4f +- %.4f |\n", double(r), e.mean, e.se);
    CHECK(res.counters.bad_samples == 0);
    CHECK(e.mean <= 1.0 + 4.0 * e.se);
    if (r <= 0.05f) CHECK(e.mean >= 0.99 - 4.0 * e.se);
  }
}

TEST_CASE("RoughDielectric: a nearly smooth absorbing slab matches the smooth closed form", "[gpu][transport][media]") {
  test_gl();
  RenderSettings st;
  st.max_bounces = 16;
  const RenderResult r = render_scene(slab_scene(rough(0.04f, sigma_from(kAttenuation, 1.0f))), 16, 16, 1024, st);
  CHECK(r.counters.bad_samples == 0);
  const glm::dvec3 mean = image_mean(r);
  for (int c = 0; c < 3; ++c) {
    const double expect = slab_returned(kAttenuation[c]);
    std::printf("rough slab (roughness 0.04), channel %d: %.5f, smooth closed form %.5f\n", c, mean[c], expect);
    // Microfacets tilt the paths inside (a longer way through, other Fresnel factors):
    // within 1% of the smooth value at this roughness.
    CHECK(mean[c] == Approx(expect).epsilon(0.01));
  }
}

// Radiance leaving the glass is compressed by 1 / n^2 (what a closed object's slab cannot
// show: in and out cancel): an emitting slab inside a nearly smooth block, seen through its
// front face, is Le (1 - F) exp(-sigma L) / n^2 as for the smooth kind (media_test.cpp).
TEST_CASE("RoughDielectric: an emitter inside it is seen through (1 - F) exp(-sigma L) / n^2", "[gpu][transport][media]") {
  test_gl();
  const RenderResult r = render_scene(emitter_scene(rough(0.04f, sigma_from(kAttenuation, 1.0f))), 16, 16, 256);
  CHECK(r.counters.bad_samples == 0);
  const glm::dvec3 mean = image_mean(r);
  for (int c = 0; c < 3; ++c) {
    const double expect = emitter_seen(2.0, std::pow(double(kAttenuation[c]), 1.5));
    std::printf("emitter inside rough glass (roughness 0.04), channel %d: %.5f, smooth closed form %.5f\n", c, mean[c], expect);
    CHECK(mean[c] == Approx(expect).epsilon(0.01));
  }
}
