// Light transport against closed forms, on the production integrator: white furnaces,
// a closed room of emitting diffuse walls, a sphere light over a plane, Fresnel values.
// Each check is |estimate - exact| < kZ standard errors of the estimate (the error is
// printed), so a biased estimator fails and a correct one passes at any sample count.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "gl_context.h"
#include "glsl_harness.h"
#include "render/camera.h"
#include "scene/env_map.h"
#include "scene/xml_loader.h"
#include "scene_builders.h"
#include "test_paths.h"

using namespace pt;

namespace {

constexpr double kZ = 4.0;

void check_close(const char* what, Estimate e, double exact, const RenderResult* r = nullptr) {
  if (r) {
    INFO(what << ": NaN/Inf samples");
    CHECK(r->counters.bad_samples == 0);
    CHECK(r->counters.rays >= double(r->w) * r->h * r->spp);
  }
  std::printf("%-58s %.5f  exact %.5f  (%+.2f se, se %.5f)\n", what, e.mean, exact, (e.mean - exact) / e.se, e.se);
  INFO(what << ": " << e.mean << " vs " << exact << " (se " << e.se << ")");
  CHECK(std::abs(e.mean - exact) < kZ * e.se + 1e-6 * exact);
}

Scene furnace(const Material& m, const std::vector<Material>& children = {}) {
  Scene s;
  s.camera = camera_looking_down_z(glm::vec3(0.0f, 0.0f, 4.0f));
  s.environment.color = glm::vec3(1.0f);
  for (const Material& c : children) add_material(s, c);  // indices 0, 1, ...
  add_sphere(s, glm::vec3(0.0f), 1.0f, add_material(s, m));
  return s;
}

}  // namespace

TEST_CASE("white furnace: energy-conserving materials return the environment", "[gpu][transport]") {
  test_gl();
  RenderSettings st;
  st.max_bounces = 64;
  struct C {
    const char* name;
    Material m;
    double expect;
  };
  Material diffuse, half, glass = SmoothDielectric{.ior = 1.5f}, transmit = Transmit{.outerIor = 1.0f, .innerIor = 1.33f},
                    mirror = Reflect{};
  half.tint = glm::vec3(0.5f);
  Material glass_tir = SmoothDielectric{.ior = 2.4f};  // diamond: much total internal reflection inside
  for (const C& c : {C{"furnace: diffuse albedo 1 -> 1", diffuse, 1.0}, C{"furnace: diffuse albedo 0.5 -> 0.5", half, 0.5},
                     C{"furnace: smooth dielectric n=1.5 -> 1", glass, 1.0},
                     C{"furnace: smooth dielectric n=2.4 -> 1", glass_tir, 1.0},
                     C{"furnace: transmit n=1.33 -> 1", transmit, 1.0}, C{"furnace: mirror (Reflect) -> 1", mirror, 1.0}}) {
    // The sphere (radius 1 at distance 4) covers the central 16x16 pixels of 64x64.
    const RenderResult r = render_scene(furnace(c.m), 64, 64, 64, st);
    check_close(c.name, region_mean(r, 24, 24, 40, 40), c.expect, &r);
  }
}

TEST_CASE("white furnace: every kind that loses no energy (its kFurnace) returns 1", "[gpu][transport]") {
  test_gl();
  RenderSettings st;
  st.max_bounces = 64;
  int tested = 0;
  for (int k = 0; k < kNumMaterialKinds; ++k) {
    const char* e = kMaterialTraits[k].furnace;
    if (!e) continue;
    Scene s = load_scene_text(std::string("<SceneLevel><Camera position=\"0 0 4\"/><Objects><Sphere center=\"0 0 0\" radius=\"1\">") + e +
                                  "</Sphere></Objects></SceneLevel>",
                              repo_path("scenes") + "/furnace.xml");
    s.camera = camera_looking_down_z(glm::vec3(0.0f, 0.0f, 4.0f));  // the sphere covers the central 16x16 pixels of 64x64
    s.environment.color = glm::vec3(1.0f);
    REQUIRE(s.shapes.size() == 1);
    const RenderResult r = render_scene(s, 64, 64, 64, st);
    check_close((std::string("furnace: ") + e + " -> 1").c_str(), region_mean(r, 24, 24, 40, 40), 1.0, &r);
    ++tested;
  }
  CHECK(tested >= 4);  // Diffuse, SmoothDielectric, Transmit, Reflect today
}

TEST_CASE("white furnace: a Fresnel composite of a mirror and a refraction returns 1", "[gpu][transport]") {
  test_gl();
  RenderSettings st;
  st.max_bounces = 64;
  const Material mirror = Reflect{}, refract = Transmit{.innerIor = 1.5f};
  const Material composite = FresnelComposite{.na = 1.0f, .nb = 1.5f, .reflective = 0, .transmissive = 1};
  const RenderResult r = render_scene(furnace(composite, {mirror, refract}), 64, 64, 64, st);
  check_close("furnace: FresnelComposite(Reflect, Transmit) -> 1", region_mean(r, 24, 24, 40, 40), 1.0, &r);
  // Against the equivalent smooth dielectric, pixel region by pixel region.
  const Material glass = SmoothDielectric{.ior = 1.5f};
  const RenderResult g = render_scene(furnace(glass), 64, 64, 64, st);
  const Estimate a = region_mean(r, 20, 20, 44, 44), b = region_mean(g, 20, 20, 44, 44);
  INFO("composite " << a.mean << " vs dielectric " << b.mean);
  CHECK(std::abs(a.mean - b.mean) < 4.0 * std::sqrt(a.se * a.se + b.se * b.se) + 1e-6);
}

TEST_CASE("closed room of emitting diffuse walls: Le * sum of rho^k up to the bounce limit", "[gpu][transport]") {
  test_gl();
  struct C {
    float le, rho;
    int bounces;
    bool nee;
  };
  for (const C& c : {C{1.0f, 0.5f, 1, true}, C{1.0f, 0.5f, 3, true}, C{0.5f, 0.8f, 64, true}, C{0.5f, 0.8f, 64, false},
                     C{2.0f, 0.3f, 16, true}}) {
    Material wall;
    wall.tint = glm::vec3(c.rho);
    wall.emission = glm::vec3(c.le);
    RenderSettings st;
    st.max_bounces = c.bounces;
    st.nee = c.nee;
    const RenderResult r = render_scene(closed_room(wall), 32, 32, 64, st);
    double exact = 0;
    for (int k = 0; k <= c.bounces; ++k) exact += c.le * std::pow(double(c.rho), k);
    char name[128];
    std::snprintf(name, sizeof name, "closed room Le=%.1f rho=%.1f bounces=%d %s", double(c.le), double(c.rho), c.bounces,
                  c.nee ? "NEE+MIS" : "BSDF only");
    check_close(name, region_mean(r, 0, 0, 32, 32), exact, &r);
  }
}

namespace {

struct SphereLight {
  glm::vec3 center;
  float radius, L;
};

// Sphere lights of radiance L fully above a Lambertian plane of albedo 1: each gives
// irradiance E = pi L (r/D)^2 cos(theta) (like a point source), so the plane's radiance
// is the sum of L (r/D)^2 cos(theta) over the lights (none shadows another's light on
// the plane here). One bounce, black environment.
void check_sphere_lights(const std::vector<SphereLight>& lights, const char* what) {
  test_gl();
  Scene s = sphere_light_over_plane(lights[0].center, lights[0].radius, lights[0].L);
  for (size_t i = 1; i < lights.size(); ++i) {
    Material emit = Emit{};
    emit.emission = glm::vec3(lights[i].L);
    add_sphere(s, lights[i].center, lights[i].radius, add_material(s, emit));
  }
  for (bool nee : {true, false}) {
  RenderSettings st;
  st.max_bounces = 1;
  st.nee = nee;
  const int W = 48, H = 48;
  const RenderResult r = render_scene(s, W, H, nee ? 256 : 4096, st);
  // The exact pixel value: the analytic radiance averaged over the pixel (box filter).
  const CameraBasis cb = camera_basis(s.camera, 1.0f);
  auto exact_pixel = [&](int px, int py, bool* valid) {
    double sum = 0;
    *valid = true;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const glm::vec2 ndc = (glm::vec2(float(px) + (a + 0.5f) / 4, float(py) + (b + 0.5f) / 4) / float(W)) * 2.0f - 1.0f;
        const glm::vec3 d = glm::normalize(cb.forward + ndc.x * cb.right + ndc.y * cb.up);
        const float t = -cb.position.y / d.y;
        const glm::vec3 x = cb.position + t * d;
        if (d.y >= 0) *valid = false;
        for (const SphereLight& l : lights) {
          const glm::vec3 to = l.center - x;
          const double dist = glm::length(to);
          // Skip pixels where a light sphere itself is in view.
          const glm::vec3 oc = cb.position - l.center;
          const float bq = glm::dot(oc, d), cq = glm::dot(oc, oc) - l.radius * l.radius;
          if (bq * bq - cq >= 0) *valid = false;
          sum += l.L * (l.radius / dist) * (l.radius / dist) * (to.y / dist);
        }
      }
    return sum / 16;
  };
  // Pixels that see any of a light sphere are left out, with a one-pixel margin: a
  // sliver of an emitter 50x brighter than the plane would dominate a pixel.
  std::vector<double> exact_at(size_t(W * H));
  std::vector<char> sees_light(size_t(W * H));
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      bool valid;
      exact_at[size_t(y * W + x)] = exact_pixel(x, y, &valid);
      sees_light[size_t(y * W + x)] = !valid;
    }
  double sum = 0, var = 0, exact = 0;
  int n = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      bool near_light = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = std::clamp(x + dx, 0, W - 1), yy = std::clamp(y + dy, 0, H - 1);
          near_light |= sees_light[size_t(yy * W + xx)] != 0;
        }
      if (near_light) continue;
      const float* p = &r.rgba[(size_t(y) * W + x) * 4];
      sum += p[1];  // grey: any channel
      var += double(p[3]) / r.spp;  // alpha: the luminance variance of the samples
      exact += exact_at[size_t(y * W + x)];
      ++n;
    }
  REQUIRE(n > W * H / 2);
  const std::string name = std::string(what) + (nee ? ", NEE+MIS (mean of the plane's pixels)" : ", BSDF only");
  check_close(name.c_str(), Estimate{sum / n, std::sqrt(var) / n}, exact / n, &r);
  }
}

}  // namespace

TEST_CASE("sphere light over a white plane: radiance = L (r/D)^2 cos(theta)", "[gpu][transport]") {
  check_sphere_lights({{glm::vec3(0.3f, 2.0f, -0.2f), 0.5f, 10.0f}}, "sphere light over plane");
}

TEST_CASE("several lights: the plane's radiance is the sum of each light's closed form", "[gpu][transport]") {
  // Three lights of different sizes and radiances, one far off to the side: light
  // selection and MIS over several emitters must still add up to the sum.
  check_sphere_lights({{glm::vec3(0.3f, 2.0f, -0.2f), 0.5f, 10.0f},
                       {glm::vec3(-1.5f, 1.2f, 0.8f), 0.25f, 40.0f},
                       {glm::vec3(2.5f, 3.0f, -2.0f), 0.8f, 3.0f}},
                      "three sphere lights over plane");
}

TEST_CASE("Fresnel closed forms", "[gpu][transport]") {
  GlslKernel k(
      "vec4 kernel(vec4 x, int i) {\n"
      "  return vec4(fresnel_dielectric(x.x, x.y), fresnel_conductor(x.x, x.y, x.z), 0.0, 0.0);\n}\n");
  const std::vector<glm::vec4> out = k.run({{1.0f, 1.5f, 0.0f, 0.0f},
                                            {1.0f, 1.0f / 1.5f, 0.0f, 0.0f},
                                            {0.5f, 1.0f / 1.5f, 0.0f, 0.0f},  // beyond the critical angle (cos 0.745)
                                            {0.01f, 1.0f / 1.33f, 0.0f, 0.0f},
                                            {1.0f, 0.2f, 3.0f, 0.0f},
                                            {0.6f, 1.5f, 0.0f, 0.0f}});
  CHECK(out[0].x == Approx(0.04).epsilon(1e-5));                 // (n-1)^2/(n+1)^2 for n = 1.5
  CHECK(out[1].x == Approx(0.04).epsilon(1e-5));                 // the same from inside
  CHECK(out[2].x == 1.0f);                                       // total internal reflection
  CHECK(out[3].x == 1.0f);
  CHECK(out[4].y == Approx((0.64 + 9.0) / (1.44 + 9.0)).epsilon(1e-5));  // ((n-1)^2+k^2)/((n+1)^2+k^2)
  CHECK(out[5].y == Approx(out[5].x).epsilon(1e-5));             // k = 0: the dielectric formula
  // Oblique dielectric value against the Fresnel equations evaluated on the CPU.
  const double ci = 0.6, eta = 1.5, st2 = (1 - ci * ci) / (eta * eta), ct = std::sqrt(1 - st2);
  const double rs = (ci - eta * ct) / (ci + eta * ct), rp = (eta * ci - ct) / (eta * ci + ct);
  CHECK(out[5].x == Approx(0.5 * (rs * rs + rp * rp)).epsilon(1e-5));
}

namespace {

// For a piecewise-constant map the radiance of a Lambertian plane of albedo 1 facing +y
// is exactly (1/pi) sum over upper-hemisphere texels of L * (2 pi / w) *
// (sin^2 theta1 - sin^2 theta0) / 2, whatever the rotation. Light sampling of the map
// (importance by luminance * sin theta) and MIS with the BSDF must reproduce it.
void check_plane_under_map(std::shared_ptr<const EnvImage> map, float rotation, float intensity, const std::string& what) {
  double exact = 0.0;
  const double pi = 3.14159265358979323846;
  for (int y = 0; 2 * y < map->height; ++y)
    for (int x = 0; x < map->width; ++x) {
      const float* p = &map->rgba[size_t(y * map->width + x) * 4];
      const double t0 = pi * y / map->height, t1 = pi * (y + 1) / map->height;
      const double lum = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
      exact += lum * (2 * pi / map->width) * 0.5 * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)) / pi;
    }
  Scene s;
  s.camera.position = glm::vec3(0.0f, 3.0f, 0.0f);
  s.camera.pitch = -80.0f;
  s.environment.map = std::move(map);
  s.environment.rotation = rotation;
  s.environment.intensity = intensity;
  Material white;
  s.shapes.push_back(Shape(Plane{.normal = glm::vec3(0, 1, 0), .d = 0.0f}, add_material(s, white)));
  for (bool nee : {true, false}) {
    RenderSettings st;
    st.max_bounces = 1;
    st.nee = nee;
    const RenderResult r = render_scene(s, 32, 32, nee ? 64 : 512, st);
    const std::string name = what + (nee ? ", NEE+MIS" : ", BSDF only");
    check_close(name.c_str(), region_mean(r, 0, 0, 32, 32), double(intensity) * exact, &r);
  }
}

}  // namespace

TEST_CASE("white plane under an HDR environment map: the exact irradiance integral", "[gpu][transport]") {
  test_gl();
  auto map = std::make_shared<EnvImage>();
  map->width = 24;
  map->height = 12;
  map->rgba.assign(size_t(map->width * map->height * 4), 0.0f);
  uint32_t state = 12345u;
  auto next = [&]() { return float((state = state * 1664525u + 1013904223u) >> 8) / 16777216.0f; };
  for (int y = 0; y < map->height; ++y)
    for (int x = 0; x < map->width; ++x) {
      float* p = &map->rgba[size_t(y * map->width + x) * 4];
      const float hot = next() < 0.05f ? 60.0f : 0.0f;
      p[0] = next() + hot;
      p[1] = 0.5f * next() + hot;
      p[2] = 0.2f * next();
      p[3] = 1.0f;
    }
  check_plane_under_map(map, 123.0f, 1.7f, "plane under an environment map");
}

TEST_CASE("the shipped environments (assets/env) load and light a plane exactly", "[gpu][transport][env]") {
  test_gl();
  int maps = 0;
  for (const char* name : {"morning", "afternoon", "night"}) {
    const auto map = load_env_map(repo_path(std::string("assets/env/") + name + ".hdr"));
    REQUIRE(map->width == 2 * map->height);
    check_plane_under_map(map, 300.0f, 2.5f, std::string("plane under assets/env/") + name + ".hdr");
    ++maps;
  }
  CHECK(maps == 3);
}
