// The one surface step (shaders/surface.glsl) in every render mode: each material kind,
// under a uniform environment of radiance 1, returns at most 1 in the path tracer, the
// Whitted tracer and the SH mode (a mode that misreads a record creates energy); and a
// Textured surface shows the same albedo in every mode (issue 12's table: the Whitted mode
// read a Textured record's map slots as colours, (1.80, 1.80, 8.99), and the SH mode
// ignored its albedo, (1, 1, 1), where the path tracer showed the wood).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "gl_context.h"
#include "scene/xml_loader.h"
#include "scene_builders.h"
#include "test_paths.h"

using namespace pt;

namespace {

// The scene files' folder is the shipped textures', so the example's maps resolve.
Scene load(const std::string& text) { return load_scene_text(text, repo_path("assets/textures") + "/surface_step.xml"); }

const RenderMode kModes[] = {RenderMode::PathTracer, RenderMode::Whitted, RenderMode::SphericalHarmonics};

struct ImageMean {
  glm::dvec3 rgb;
  Estimate lum;
};

ImageMean image_mean(const RenderResult& r, int x0, int y0, int x1, int y1) {
  glm::dvec3 sum(0.0);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const float* p = &r.rgba[(size_t(y) * r.w + x) * 4];
      sum += glm::dvec3(p[0], p[1], p[2]);
    }
  return {sum / double((x1 - x0) * (y1 - y0)), region_mean(r, x0, y0, x1, y1)};
}

}  // namespace

TEST_CASE("surface step: no material kind returns more than 1 under a sky of 1, in any mode", "[gpu][modes][transport]") {
  test_gl();
  for (int i = 0; i < kNumMaterialKinds; ++i) {
    const MaterialKindInfo& k = kMaterialKinds[i];
    const std::string ex = kMaterialTraits[i].example;  // every kind's stem brings one
    INFO("material kind " << k.xml);
    // A sphere over a plane of the same material, seen from above at an angle, filling the view.
    const Scene s = load("<SceneLevel><Camera position=\"0 2.5 3\" yaw=\"90\" pitch=\"-35\"/><Environment color=\"1 1 1\"/><Objects>"
                         "<Plane normal=\"0 1 0\" d=\"-1\">" + ex + "</Plane>"
                         "<Sphere center=\"0 0 0\" radius=\"1\">" + ex + "</Sphere></Objects></SceneLevel>");
    for (const RenderMode mode : kModes) {
      RenderSettings st;
      st.mode = mode;
      const RenderResult r = render_scene(s, 32, 32, 64, st);
      const ImageMean m = image_mean(r, 0, 0, 32, 32);
      std::printf("%-18s %-8s mean (%.4f, %.4f, %.4f)  luminance %.4f (se %.4f)\n", k.xml, kRenderModeNames[int(mode)], m.rgb.x, m.rgb.y,
                  m.rgb.z, m.lum.mean, m.lum.se);
      INFO("mode " << kRenderModeNames[int(mode)] << ": luminance " << m.lum.mean << " (se " << m.lum.se << "), rgb " << m.rgb.x << " "
                   << m.rgb.y << " " << m.rgb.z);
      CHECK(r.counters.bad_samples == 0);
      CHECK(m.lum.mean <= 1.0 + 4.0 * m.lum.se + 1e-4);
      // Each channel (its own error is not kept; the luminance's, 6 times, screens a
      // channel that alone creates energy as the Whitted mode's Textured did: 8.99).
      for (int c = 0; c < 3; ++c) CHECK(m.rgb[c] <= 1.0 + 6.0 * m.lum.se + 1e-3);
    }
  }
}

TEST_CASE("surface step: a Textured plane's albedo is the same in every mode", "[gpu][modes][textured]") {
  // issue 12's table: a plane with <Textured diffuse="wood.png" n="10"/> under a sky of 1
  // at 96x64 and 16 spp. Lit by the sky alone, a single plane reflects exactly its albedo
  // rho(uv) in all three modes (nothing else in the scene: every scattered ray escapes;
  // the SH irradiance of a constant sky is exactly pi).
  test_gl();
  const Scene s = load("<SceneLevel><Camera position=\"0.3 6 0.2\" pitch=\"-89.9\"/><Environment color=\"1 1 1\"/><Objects>"
                       "<Plane normal=\"0 1 0\" d=\"0\"><Textured diffuse=\"wood_diffuse.png\" n=\"10\"/></Plane></Objects></SceneLevel>");
  const int W = 96, H = 64, B = 16;  // 6 x 4 blocks of 16 x 16 pixels
  std::vector<RenderResult> r;
  for (int i = 0; i < 3; ++i) {
    RenderSettings st;
    st.mode = kModes[i];
    r.push_back(render_scene(s, W, H, 16, st));
    CHECK(r[i].counters.bad_samples == 0);
    const ImageMean m = image_mean(r[i], 0, 0, W, H);
    std::printf("Textured plane, %-8s mean radiance (%.4f, %.4f, %.4f)\n", kRenderModeNames[int(kModes[i])], m.rgb.x, m.rgb.y, m.rgb.z);
  }
  const ImageMean path = image_mean(r[0], 0, 0, W, H);
  CHECK(path.lum.mean > 0.05);  // the wood, not black
  CHECK(path.rgb.x > 1.5 * path.rgb.z);  // and brown
  for (int i = 1; i < 3; ++i)
    for (int by = 0; by < H / B; ++by)
      for (int bx = 0; bx < W / B; ++bx) {
        const Estimate a = region_mean(r[0], bx * B, by * B, bx * B + B, by * B + B);
        const Estimate b = region_mean(r[i], bx * B, by * B, bx * B + B, by * B + B);
        const double se = std::sqrt(a.se * a.se + b.se * b.se);
        INFO(kRenderModeNames[int(kModes[i])] << " block " << bx << "," << by << ": " << b.mean << " vs path " << a.mean << " (se " << se << ")");
        CHECK(std::abs(a.mean - b.mean) < 4.5 * se + 1e-4);
      }
}
