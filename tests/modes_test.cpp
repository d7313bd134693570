// The render modes on the production programs: the Whitted ray tracer against closed
// forms (a sphere light over a diffuse plane, directly and in a mirror; furnaces through
// delta surfaces), the SH irradiance mode on a diffuse plane, and the generator's choice
// of program per mode. Checks are |estimate - exact| < 4 standard errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "gl_context.h"
#include "render/camera.h"
#include "render/scene_render.h"
#include "render/sh.h"
#include "scene_builders.h"

using namespace pt;

namespace {

void check_close(const char* what, Estimate e, double exact, const RenderResult& r) {
  CHECK(r.counters.bad_samples == 0);
  std::printf("%-58s %.5f  exact %.5f  (%+.2f se, se %.5f)\n", what, e.mean, exact, (e.mean - exact) / e.se, e.se);
  INFO(what << ": " << e.mean << " vs " << exact << " (se " << e.se << ")");
  CHECK(std::abs(e.mean - exact) < 4.0 * e.se + 1e-6 * exact);
}

RenderSettings whitted(int bounces) {
  RenderSettings st;
  st.mode = RenderMode::Whitted;
  st.max_bounces = bounces;
  return st;
}

// Exact radiance along a ray in sphere_light_over_plane, optionally with a mirror plane
// z = mirror_z (facing +z) in front of the camera: the plane's L (r/D)^2 cos(theta),
// directly or after mirror reflections, up to `bounces` surfaces (the mode's limit).
// *sees_light: the ray meets the light sphere (such pixels are left out).
struct Analytic {
  glm::vec3 center;
  float radius, L;
  bool mirror;
  float mirror_z;
  double radiance(glm::vec3 o, glm::vec3 d, int bounces, bool* sees_light, bool* via_mirror) const {
    for (int b = 0; b < bounces + 1; ++b) {
      const glm::vec3 oc = o - center;
      const float bq = glm::dot(oc, d), cq = glm::dot(oc, oc) - radius * radius;
      const float disc = bq * bq - cq;
      const float ts = disc >= 0 && -bq + std::sqrt(disc) > 0 ? -bq - std::sqrt(disc) : 1e30f;
      const float tf = d.y < 0 ? -o.y / d.y : 1e30f;
      const float tm = mirror && d.z < 0 && o.z > mirror_z ? (mirror_z - o.z) / d.z : 1e30f;
      const float t = std::min({ts, tf, tm});
      if (t >= 1e30f) return 0;
      if (t == ts) return *sees_light = true, 0;
      if (b == bounces) return 0;  // the bounce limit: this surface scatters nothing
      const glm::vec3 x = o + t * d;
      if (t == tf) {
        const glm::vec3 to = center - x;
        const double dist = glm::length(to);
        return L * (radius / dist) * (radius / dist) * (to.y / dist);
      }
      *via_mirror = true;
      o = x;
      d.z = -d.z;
    }
    return 0;
  }
};

// Mean over the pixels that see no light (with a one-pixel margin), against the exact
// box-filtered pixel values; returns the number of pixels used and seen via the mirror.
void check_against(const char* what, const Scene& s, const Analytic& a, const RenderSettings& st, int spp,
                   int* used = nullptr, int* mirrored = nullptr) {
  const int W = 48, H = 48;
  const RenderResult r = render_scene(s, W, H, spp, st);
  const CameraBasis cb = camera_basis(s.camera, 1.0f);
  std::vector<double> exact(size_t(W * H));
  std::vector<char> light(size_t(W * H)), mirror(size_t(W * H));
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      bool sees = false, via = false;
      double sum = 0;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
          const glm::vec2 ndc = (glm::vec2(x + (i + 0.5f) / 4, y + (j + 0.5f) / 4) / float(W)) * 2.0f - 1.0f;
          const glm::vec3 d = glm::normalize(cb.forward + ndc.x * cb.right + ndc.y * cb.up);
          sum += a.radiance(cb.position, d, st.max_bounces, &sees, &via);
        }
      exact[size_t(y * W + x)] = sum / 16;
      light[size_t(y * W + x)] = sees;
      mirror[size_t(y * W + x)] = via;
    }
  double sum = 0, var = 0, ex = 0;
  int n = 0, nm = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      bool near = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) near |= light[size_t(std::clamp(y + dy, 0, H - 1) * W + std::clamp(x + dx, 0, W - 1))] != 0;
      if (near) continue;
      const float* p = &r.rgba[(size_t(y) * W + x) * 4];
      sum += p[1];
      var += double(p[3]) / r.spp;  // alpha: the luminance variance of the samples (white light: exact)
      ex += exact[size_t(y * W + x)];
      ++n;
      nm += mirror[size_t(y * W + x)];
    }
  REQUIRE(n > W * H / 2);
  check_close(what, Estimate{sum / n, std::sqrt(var) / n}, ex / n, r);
  if (used) *used = n;
  if (mirrored) *mirrored = nm;
}

}  // namespace

TEST_CASE("Whitted: a diffuse plane under a sphere light is L (r/D)^2 cos(theta)", "[gpu][modes]") {
  test_gl();
  const Analytic a{glm::vec3(0.3f, 2.0f, -0.2f), 0.5f, 10.0f, false, 0.0f};
  const Scene s = sphere_light_over_plane(a.center, a.radius, a.L);
  check_against("Whitted: plane under a sphere light", s, a, whitted(1), 256);
}

TEST_CASE("Whitted: the lit plane seen in a mirror, and nothing beyond the bounce limit", "[gpu][modes]") {
  test_gl();
  const Analytic a{glm::vec3(0.3f, 2.0f, -0.2f), 0.5f, 10.0f, true, -3.0f};
  Scene s = sphere_light_over_plane(a.center, a.radius, a.L);
  const Material mirror = Reflect{};
  s.shapes.push_back(Shape(Plane{.normal = glm::vec3(0, 0, 1), .d = a.mirror_z}, add_material(s, mirror)));  // dot(n, p) = d
  int used = 0, mirrored = 0;
  check_against("Whitted: plane and its mirror image, 2 bounces", s, a, whitted(2), 256, &used, &mirrored);
  CHECK(mirrored > used / 8);  // a good part of the view is the mirror image
  check_against("Whitted: 1 bounce: the mirror shows black", s, a, whitted(1), 64);
}

TEST_CASE("Whitted: furnaces through delta surfaces and direct light from a constant environment", "[gpu][modes]") {
  test_gl();
  // A sphere alone in a white environment: every ray through a smooth dielectric, a
  // Transmit or a mirror escapes with its weight intact (1), and a Lambertian sphere's
  // direct light from the unoccluded environment is its albedo.
  Material glass = SmoothDielectric{.ior = 1.5f}, diamond = SmoothDielectric{.ior = 2.4f}, transmit = Transmit{.innerIor = 1.33f},
           mirror = Reflect{}, half;
  half.tint = glm::vec3(0.5f);
  struct C {
    const char* name;
    Material m;
    double expect;
  };
  for (const C& c : {C{"Whitted furnace: smooth dielectric n=1.5 -> 1", glass, 1.0},
                     C{"Whitted furnace: smooth dielectric n=2.4 -> 1", diamond, 1.0},
                     C{"Whitted furnace: transmit n=1.33 -> 1", transmit, 1.0},
                     C{"Whitted furnace: mirror -> 1", mirror, 1.0}, C{"Whitted furnace: diffuse 0.5 -> 0.5", half, 0.5}}) {
    Scene s;
    s.camera = camera_looking_down_z(glm::vec3(0.0f, 0.0f, 4.0f));
    s.environment.color = glm::vec3(1.0f);
    add_sphere(s, glm::vec3(0.0f), 1.0f, add_material(s, c.m));
    const RenderResult r = render_scene(s, 64, 64, 64, whitted(64));
    check_close(c.name, region_mean(r, 24, 24, 40, 40), c.expect, r);
  }
}

TEST_CASE("Whitted: shadow rays: in a closed room, neither the environment nor a light outside reaches", "[gpu][modes]") {
  test_gl();
  Material wall;
  Scene s = closed_room(wall);
  s.environment.color = glm::vec3(1.0f);
  Material emit = Emit{};
  emit.emission = glm::vec3(10.0f);
  add_sphere(s, glm::vec3(0.0f, 3.0f, 0.0f), 0.5f, add_material(s, emit));  // above the room's ceiling
  s.camera.pitch = -60.0f;  // the floor, which faces the light
  for (bool env_map : {false, true}) {
    if (env_map) {  // the environment as a map instead: importance-sampled, still occluded
      auto map = std::make_shared<EnvImage>();
      map->width = 8;
      map->height = 4;
      map->rgba.assign(8 * 4 * 4, 1.0f);
      s.environment.map = map;
    }
    const RenderResult r = render_scene(s, 16, 16, 16, whitted(4));
    float peak = 0.0f;
    for (size_t i = 0; i < r.rgba.size(); i += 4) peak = std::max({peak, r.rgba[i], r.rgba[i + 1], r.rgba[i + 2]});
    INFO((env_map ? "map" : "constant colour") << ": brightest pixel " << peak);
    CHECK(peak == 0.0f);
  }
}

TEST_CASE("SH mode: a white diffuse plane under a constant environment has the environment's radiance", "[gpu][modes]") {
  test_gl();
  Scene s;
  s.camera.position = glm::vec3(0.0f, 3.0f, 0.0f);
  s.camera.pitch = -80.0f;  // only the plane in view
  s.environment.color = glm::vec3(0.3f, 0.6f, 1.5f);
  Material white, grey;
  grey.tint = glm::vec3(0.25f, 0.5f, 1.0f);
  s.shapes.push_back(Shape(Plane{.normal = glm::vec3(0, 1, 0), .d = 0.0f}, add_material(s, white)));
  RenderSettings st;
  st.mode = RenderMode::SphericalHarmonics;
  for (int pass = 0; pass < 2; ++pass) {
    const RenderResult r = render_scene(s, 16, 16, 4, st);
    const glm::vec3 expect = s.environment.color * s.materials[0].tint;  // albedo * E / pi, E = pi L
    for (size_t i = 0; i < r.rgba.size(); i += 4)
      for (int ch = 0; ch < 3; ++ch) REQUIRE(r.rgba[i + size_t(ch)] == Approx(expect[ch]).epsilon(1e-5));
    s.materials[0] = grey;
  }
  // Under a map: the plane facing +y shows albedo * E(+y) / pi from the CPU projection.
  auto map = std::make_shared<EnvImage>();
  map->width = 32;
  map->height = 16;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 32; ++i) map->rgba.insert(map->rgba.end(), {float(i % 5), float(j), 0.5f, 1.0f});
  s.environment.map = map;
  s.environment.rotation = 40.0f;
  const RenderResult r = render_scene(s, 16, 16, 4, st);
  const glm::vec3 expect = s.materials[0].tint * sh_irradiance(project_sh(s.environment), glm::vec3(0, 1, 0)) / float(M_PI);
  for (size_t i = 0; i < r.rgba.size(); i += 4)
    for (int ch = 0; ch < 3; ++ch) REQUIRE(r.rgba[i + size_t(ch)] == Approx(expect[ch]).epsilon(1e-4));
}

TEST_CASE("render modes: one program per mode, holding only what the mode needs", "[gpu][modes]") {
  test_gl();
  const Scene s = sphere_light_over_plane(glm::vec3(0, 2, 0), 0.5f, 10.0f);
  Renderer r;
  r.resize(8, 8);
  r.set_scene(s);
  RenderSettings st;
  const std::string path = r.integrator_source().text;
  st.mode = RenderMode::Whitted;
  r.set_settings(st);
  const std::string whitted = r.integrator_source().text;
  st.mode = RenderMode::SphericalHarmonics;
  r.set_settings(st);
  const std::string sh = r.integrator_source().text;
  CHECK(r.programs_compiled() == 3);
  const auto has = [](const std::string& text, const char* what) { return text.find(what) != std::string::npos; };
  CHECK(!has(path, "vec3 whitted_direct("));
  CHECK(has(whitted, "vec3 whitted_direct("));
  CHECK(has(sh, "vec3 sh_irradiance("));
  CHECK(!has(path, "vec3 sh_irradiance("));
  CHECK(!has(whitted, "vec3 sh_irradiance("));
  // The light-sampling dispatch exists for the modes that sample lights.
  CHECK(has(path, "return sample_light_sphere("));
  CHECK(has(whitted, "return sample_light_sphere("));
  CHECK(!has(sh, "return sample_light_sphere("));
  st.mode = RenderMode::PathTracer;
  r.set_settings(st);
  CHECK(r.integrator_source().text == path);  // back to the cached program
  CHECK(r.programs_compiled() == 3);
}

TEST_CASE("a scene's <Render> sets each setting the user did not set explicitly", "[modes]") {
  SceneRender r;
  r.bounces = 3;
  r.mode = RenderMode::Whitted;
  r.tonemap = ToneMap::Reinhard;
  r.exposure = 2.5f;
  r.samples = 0;
  const RenderSettings base;
  const RenderSettings scene = with_scene_render(base, r, UserSet{});
  CHECK(scene.max_bounces == 3);
  CHECK(scene.mode == RenderMode::Whitted);
  CHECK(scene.tonemap == ToneMap::Reinhard);
  CHECK(scene.exposure == 2.5f);
  CHECK(scene.sample_limit == 0);
  RenderSettings mine = base;
  mine.sample_limit = 64;
  const RenderSettings user = with_scene_render(mine, r, UserSet{true, true, true, true, true});
  CHECK(user == mine);
  CHECK(with_scene_render(base, SceneRender{}, UserSet{}) == base);  // an absent <Render> changes nothing
}
