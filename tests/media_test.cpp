// Absorbing media (materials/smooth_dielectric.h: attenuationColor, attenuationDistance;
// shaders/media.glsl) against closed forms, in the path tracer and the Whitted mode, at
// (near) normal incidence through a camera of 0.2-degree field of view (the angles inside
// change path lengths and Fresnel factors by under 1e-5):
//  - a slab of glass (n 1.5, thickness d) in a sky of 1: what comes back towards the camera
//    is the slab's reflectance plus its transmittance, R + T = 1 - A, with every internal
//    reflection: F = ((n - 1) / (n + 1))^2, a = exp(-sigma d),
//        T = (1 - F)^2 a / (1 - F^2 a^2),   R = F + (1 - F)^2 F a^2 / (1 - F^2 a^2);
//  - an emitting slab (Emit: it absorbs) inside a block of that glass, seen through the
//    block's front face, its own face at depth L: Le (1 - F) exp(-sigma L) / n^2 (the radiance leaving the
//    glass; the reflection off the front face sees a black sky). The segment ends on the
//    ball, not on the block's own surface: the path must know it is inside the medium.
// Each channel's mean over the image within 4 standard errors (from the spread between
// pixels, which see the same thing) and 2e-4 relative.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "gl_context.h"
#include "scene/xml_loader.h"
#include "media_scenes.h"
#include "test_paths.h"

using namespace pt;

namespace {

constexpr int kN = 16;

Material glass(glm::vec3 attenuation) {
  return SmoothDielectric{.ior = 1.5f, .sigma = sigma_from(attenuation, 1.0f)};
}

// Each channel's mean over the image and its standard error from the spread between pixels.
void check_channels(const RenderResult& r, const glm::dvec3& expect, const char* what) {
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0, sq = 0.0;
    const int n = r.w * r.h;
    for (int i = 0; i < n; ++i) {
      const double v = r.rgba[size_t(i) * 4 + c];
      sum += v;
      sq += v * v;
    }
    const double mean = sum / n, se = std::sqrt(std::max(0.0, sq / n - mean * mean) / (n - 1));
    std::printf("%s, channel %d: %.6f +- %.6f, closed form %.6f\n", what, c, mean, se, expect[c]);
    CHECK(std::abs(mean - expect[c]) <= 4.0 * se + 2e-4 * expect[c]);
  }
  CHECK(r.counters.bad_samples == 0);
}

}  // namespace

TEST_CASE("media: an absorbing glass slab returns R + T of its closed form (Beer-Lambert, every internal reflection)", "[gpu][transport][media]") {
  test_gl();
  for (RenderMode mode : {RenderMode::PathTracer, RenderMode::Whitted}) {
    const Scene s = slab_scene(glass(kAttenuation));
    RenderSettings st;
    st.mode = mode;
    st.max_bounces = 16;
    const RenderResult r = render_scene(s, kN, kN, 1024, st);
    glm::dvec3 expect;
    for (int c = 0; c < 3; ++c) expect[c] = slab_returned(kAttenuation[c]);
    check_channels(r, expect, mode == RenderMode::PathTracer ? "slab, path" : "slab, whitted");
  }
}

TEST_CASE("media: an emitter inside absorbing glass is seen through exp(-sigma L) of it, the segment ending on the emitter", "[gpu][transport][media]") {
  test_gl();
  for (RenderMode mode : {RenderMode::PathTracer, RenderMode::Whitted}) {
    const Scene s = emitter_scene(glass(kAttenuation));  // the lamp's face at depth L = 1.5
    RenderSettings st;
    st.mode = mode;
    const RenderResult r = render_scene(s, kN, kN, 256, st);
    glm::dvec3 expect;
    for (int c = 0; c < 3; ++c) expect[c] = emitter_seen(2.0, std::pow(double(kAttenuation[c]), 1.5));
    check_channels(r, expect, mode == RenderMode::PathTracer ? "emitter inside, path" : "emitter inside, whitted");
  }
}

TEST_CASE("media: attenuationColor and attenuationDistance load as an absorption coefficient", "[loader][media]") {
  auto load = [](const std::string& attrs) {
    return load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects><Sphere center=\"0 0 0\" radius=\"1\"><SmoothDielectric ior=\"1.5\" " + attrs +
                               "/></Sphere></Objects></SceneLevel>",
                           "media.xml");
  };
  const Scene s = load("attenuationColor=\"0.5 1 0\" attenuationDistance=\"2\"");
  const SmoothDielectric* d = std::get_if<SmoothDielectric>(&s.materials.at(0).params);
  REQUIRE(d);
  CHECK(d->sigma.x == Approx(std::log(2.0) / 2.0));
  CHECK(d->sigma.y == 0.0f);
  CHECK(d->sigma.z == kMaxSigma);  // nothing gets through, finite
  CHECK(material_features(s.materials[0].params) == feature_bit(MaterialFeature::Media));
  CHECK(material_features(load("").materials[0].params) == 0u);  // clear glass: no medium code
  CHECK(material_features(load("attenuationColor=\"1 1 1\" attenuationDistance=\"1\"").materials[0].params) == 0u);
  CHECK_THROWS_WITH(load("attenuationColor=\"0.5 0.5 0.5\""), Catch::Contains("go together"));
  CHECK_THROWS_WITH(load("attenuationDistance=\"1\""), Catch::Contains("go together"));
  CHECK_THROWS_WITH(load("attenuationColor=\"1.5 0.5 0.5\" attenuationDistance=\"1\""), Catch::Contains("[0, 1]"));
  CHECK_THROWS_WITH(load("attenuationColor=\"0.5 0.5 0.5\" attenuationDistance=\"0\""), Catch::Contains("> 0"));
}
