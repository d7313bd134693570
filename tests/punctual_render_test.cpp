// Punctual lights against closed forms, in every render mode that lights with them
// (path, whitted, sh): a white Lambertian plane y = 0 (normal +y) under one light, black
// environment, one bounce. The plane's radiance at x is albedo / pi * E(x) with
//   point:       E = I cos / d^2 x KHR_lights_punctual's window clamp(1 - (d / range)^4, 0, 1)
//   spot:        the point's E x the extension's falloff: the square of
//                clamp((cos theta - cos outer) / (cos inner - cos outer), 0, 1)
//   directional: E = E0 cos (the same everywhere)
// (cos: between the plane's normal and the direction to the light; theta: between the
// spot's axis and the direction from it to x). Each pixel's exact value is that radiance
// averaged over the pixel (8x8 points of its box filter); the image is checked band by
// band (rows; for the spot, also pixels wholly inside the inner cone, in the falloff
// ring, and wholly outside the outer cone, which must be exactly black), each band's
// mean within 4 standard errors plus the 8x8 quadrature's own error (2e-4 relative).
// Then a point light together with a sphere light 100x less powerful: the sum of the two
// closed forms (selection by power stays unbiased).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "gl_context.h"
#include "render/camera.h"
#include "scene_builders.h"

using namespace pt;

namespace {

constexpr double kZ = 4.0;
constexpr double kQuadrature = 2e-4;  // relative error of the 8x8 pixel quadrature (smooth radiance)
constexpr int kW = 48, kH = 48;

double window(double d, double range) {
  if (range <= 0.0) return 1.0;
  const double x = d / range;
  return std::clamp(1.0 - x * x * x * x, 0.0, 1.0);
}

// Irradiance at x on the plane (normal +y) from light l (grey: channel 1).
double irradiance(const PunctualLight& pl, glm::dvec3 x) {
  if (const PointLight* l = pl.as<PointLight>()) {
    const glm::dvec3 to = glm::dvec3(l->position) - x;
    const double d = glm::length(to);
    return l->intensity.y * std::max(to.y / d, 0.0) / (d * d) * window(d, l->range);
  }
  if (const SpotLight* l = pl.as<SpotLight>()) {
    const glm::dvec3 to = glm::dvec3(l->position) - x;
    const double d = glm::length(to);
    const double ct = glm::dot(glm::dvec3(l->direction), -to / d), ci = std::cos(double(l->inner)), co = std::cos(double(l->outer));
    const double a = std::clamp((ct - co) / (ci - co), 0.0, 1.0);
    return l->intensity.y * std::max(to.y / d, 0.0) / (d * d) * window(d, l->range) * a * a;
  }
  const DirectionalLight* l = pl.as<DirectionalLight>();
  return l->intensity.y * std::max(-double(l->direction.y), 0.0);
}

Scene plane_under(const std::vector<PunctualLight>& lights) {
  Scene s;
  s.camera.position = glm::vec3(0.0f, 6.0f, 3.0f);
  s.camera.yaw = 90.0f;
  s.camera.pitch = -60.0f;
  s.environment.color = glm::vec3(0.0f);
  Material white;
  s.shapes.push_back(Shape(Plane{.normal = glm::vec3(0, 1, 0), .d = 0.0f}, add_material(s, white)));
  s.punctual = lights;
  return s;
}

// Per pixel: the exact mean radiance over its box filter (radiance(x) for plane points
// x; NaN where a ray misses the plane), and how much of it lies in each class of
// `klass(x)` (0, 1, 2: the spot's inner cone, ring, outside).
struct Exact {
  std::vector<double> value;
  std::vector<int> klass;  // the class all 64 points share, or -1
};
Exact exact_image(const Scene& s, const std::function<double(glm::dvec3)>& radiance, const std::function<int(glm::dvec3)>& klass) {
  const CameraBasis cb = camera_basis(s.camera, 1.0f);
  Exact e{std::vector<double>(size_t(kW * kH)), std::vector<int>(size_t(kW * kH))};
  for (int py = 0; py < kH; ++py)
    for (int px = 0; px < kW; ++px) {
      double sum = 0.0;
      int k = -2;
      for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b) {
          const glm::vec2 ndc = (glm::vec2(float(px) + (a + 0.5f) / 8, float(py) + (b + 0.5f) / 8) / float(kW)) * 2.0f - 1.0f;
          const glm::dvec3 d = glm::normalize(glm::dvec3(cb.forward + ndc.x * cb.right + ndc.y * cb.up));
          if (d.y >= 0.0) sum = NAN;
          const glm::dvec3 x = glm::dvec3(cb.position) + (-double(cb.position.y) / d.y) * d;
          sum += radiance(x);
          const int c = klass(x);
          k = k == -2 ? c : (k == c ? k : -1);
        }
      e.value[size_t(py * kW + px)] = sum / 64.0;
      e.klass[size_t(py * kW + px)] = k;
    }
  return e;
}

// Checks the rendered image band by band: rows in 4 bands, and each class of `klass`.
void check_image(const std::string& what, const RenderResult& r, const Exact& e, int classes) {
  INFO(what << ": NaN/Inf samples");
  CHECK(r.counters.bad_samples == 0);
  int checked = 0;
  for (int band = 0; band < 4 + classes; ++band) {
    double sum = 0, var = 0, exact = 0;
    int n = 0, zero_wrong = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const size_t i = size_t(y * kW + x);
        if (std::isnan(e.value[i])) continue;
        if (band < 4 ? y * 4 / kH != band : e.klass[i] != band - 4) continue;
        const float* p = &r.rgba[i * 4];
        // Where no light reaches any of a pixel's neighbourhood, nothing may be added.
        bool dark = true;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int xx = std::clamp(x + dx, 0, kW - 1), yy = std::clamp(y + dy, 0, kH - 1);
            dark &= e.value[size_t(yy * kW + xx)] == 0.0;
          }
        if (dark && p[1] != 0.0f) ++zero_wrong;
        sum += p[1];
        var += double(p[3]) / r.spp;  // alpha: the luminance variance of the samples
        exact += e.value[i];
        ++n;
      }
    if (n == 0) continue;
    ++checked;
    const double mean = sum / n, se = std::sqrt(var) / n, ex = exact / n;
    const std::string name = what + (band < 4 ? ", rows band " + std::to_string(band) : ", class " + std::to_string(band - 4));
    std::printf("%-64s %.5f  exact %.5f  (%+.2f se, se %.5f, %d px)\n", name.c_str(), mean, ex, se > 0 ? (mean - ex) / se : 0.0, se, n);
    INFO(name << ": " << mean << " vs " << ex << " (se " << se << ")");
    CHECK(std::abs(mean - ex) <= kZ * se + kQuadrature * ex + 1e-7);
    CHECK(zero_wrong == 0);
  }
  CHECK(checked >= 4);
}

void check_modes(const std::string& what, const std::vector<PunctualLight>& lights, const std::function<int(glm::dvec3)>& klass,
                 int classes) {
  test_gl();
  const Scene s = plane_under(lights);
  const Exact e = exact_image(
      s,
      [&](glm::dvec3 x) {
        double E = 0.0;
        for (const PunctualLight& l : lights) E += irradiance(l, x);
        return E / M_PI;
      },
      klass);
  for (RenderMode mode : {RenderMode::PathTracer, RenderMode::Whitted, RenderMode::SphericalHarmonics}) {
    RenderSettings st;
    st.max_bounces = 1;
    st.mode = mode;
    const RenderResult r = render_scene(s, kW, kH, 64, st);
    check_image(what + " (" + kRenderModeNames[int(mode)] + ")", r, e, classes);
  }
}

int no_class(glm::dvec3) { return 0; }

}  // namespace

TEST_CASE("point light over a white plane: L = I cos / (pi d^2), range window", "[gpu][transport][lights]") {
  check_modes("point light, range 4", {{PointLight{.position = glm::vec3(0.3f, 1.5f, -0.5f), .intensity = glm::vec3(5.0f), .range = 4.0f}, 0}},
              no_class, 0);
  check_modes("point light, no range", {{PointLight{.position = glm::vec3(-0.4f, 2.0f, 0.2f), .intensity = glm::vec3(3.0f)}, 0}}, no_class, 0);
}

TEST_CASE("spot light over a white plane: full inside the inner cone, the spec's falloff, black outside", "[gpu][transport][lights]") {
  const SpotLight spot{.position = glm::vec3(0.2f, 3.0f, -0.6f), .direction = glm::normalize(glm::vec3(0.1f, -1.0f, 0.05f)),
                       .intensity = glm::vec3(12.0f), .inner = glm::radians(12.0f), .outer = glm::radians(28.0f)};
  const double ci = std::cos(double(spot.inner)), co = std::cos(double(spot.outer));
  check_modes(
      "spot light", {{spot, 0}},
      [&](glm::dvec3 x) {
        const double c = glm::dot(glm::dvec3(spot.direction), glm::normalize(x - glm::dvec3(spot.position)));
        return c >= ci ? 0 : (c > co ? 1 : 2);
      },
      3);
}

TEST_CASE("directional light on a white plane: L = E0 cos / pi", "[gpu][transport][lights]") {
  check_modes("directional light", {{DirectionalLight{.direction = glm::normalize(glm::vec3(0.5f, -1.0f, 0.3f)), .intensity = glm::vec3(2.0f)}, 0}},
              no_class, 0);
}

TEST_CASE("a point light and a sphere light 100x weaker: the sum of both closed forms", "[gpu][transport][lights][selection]") {
  test_gl();
  // Sphere: radiance 4, radius 0.1 (power 4 * 4 pi 0.01 * pi = 1.58); point: I = 12.6
  // (power 4 pi 12.6 = 158): selection by power gives the sphere 1% of the samples.
  const glm::vec3 c(-0.8f, 1.0f, -0.4f);
  const float R = 0.1f, Ls = 4.0f;
  const PointLight p{.position = glm::vec3(0.5f, 2.0f, -0.3f), .intensity = glm::vec3(12.6f)};
  Scene s = plane_under({{p, 0}});
  Material emit = Emit{};
  emit.emission = glm::vec3(Ls);
  add_sphere(s, c, R, add_material(s, emit));
  const CameraBasis cb = camera_basis(s.camera, 1.0f);
  // Whether the sphere hides the point light from plane point x.
  auto shadowed = [&](glm::dvec3 x) {
    const glm::dvec3 to = glm::dvec3(p.position) - x, d = glm::normalize(to), oc = x - glm::dvec3(c);
    const double b = glm::dot(oc, d), q = glm::dot(oc, oc) - double(R) * R, disc = b * b - q;
    return disc >= 0.0 && -b - std::sqrt(disc) > 0.0 && -b - std::sqrt(disc) < glm::length(to);
  };
  const Exact e = exact_image(
      s,
      [&](glm::dvec3 x) {
        const glm::dvec3 to = glm::dvec3(c) - x;
        const double d = glm::length(to);
        const double sphere = Ls * (R / d) * (R / d) * (to.y / d);  // L (r/D)^2 cos: exact for a sphere above the horizon
        return (shadowed(x) ? 0.0 : irradiance({p, 0}, x) / M_PI) + sphere;
      },
      [&](glm::dvec3 x) {  // 1: the camera ray passes near the sphere (left out below); 2: in its shadow
        const glm::dvec3 d = glm::normalize(x - glm::dvec3(cb.position)), oc = glm::dvec3(cb.position) - glm::dvec3(c);
        const double b = glm::dot(oc, d), q = glm::dot(oc, oc) - 4.0 * R * R;
        return b * b - q >= 0.0 ? 1 : (shadowed(x) ? 2 : 0);
      });
  Exact kept = e;  // pixels near the sphere, or partly in its shadow, are left out
  for (size_t i = 0; i < kept.value.size(); ++i)
    if (e.klass[i] != 0 && e.klass[i] != 2) kept.value[i] = NAN;
  RenderSettings st;
  st.max_bounces = 1;  // (BSDF sampling alone, --no-nee, never reaches a delta light)
  const RenderResult r = render_scene(s, kW, kH, 256, st);
  check_image("point + weak sphere light (path, NEE+MIS)", r, kept, 3);
}

TEST_CASE("a light sealed in an absorbing box with the camera inside: still lights what is inside", "[gpu][transport][lights][selection]") {
  // The sphere light over the plane (transport_test's closed form L (r/D)^2 cos), all of it
  // and the camera inside a black Emit box: the light is sealed (weight 0) for cameras
  // outside, so inside the renderer must select uniformly (u_lights_uniform); whitted,
  // which has no BSDF-sampled emission, would be black without that.
  test_gl();
  const glm::vec3 c(0.3f, 2.0f, -0.2f);
  const float R = 0.5f, L = 10.0f;
  Scene s = sphere_light_over_plane(c, R, L);
  Material black = Emit{};
  add_box(s, glm::vec3(-8, -1, -8), glm::vec3(8, 9, 8), add_material(s, black));
  const CameraBasis cb = camera_basis(s.camera, 1.0f);
  const Exact e = exact_image(
      s,
      [&](glm::dvec3 x) {
        const glm::dvec3 to = glm::dvec3(c) - x;
        const double d = glm::length(to);
        return L * (R / d) * (R / d) * (to.y / d);
      },
      [&](glm::dvec3 x) {
        const glm::dvec3 d = glm::normalize(x - glm::dvec3(cb.position)), oc = glm::dvec3(cb.position) - glm::dvec3(c);
        const double b = glm::dot(oc, d), q = glm::dot(oc, oc) - 4.0 * R * R;
        return b * b - q >= 0.0 ? 1 : 0;
      });
  Exact kept = e;
  for (size_t i = 0; i < kept.value.size(); ++i)
    if (e.klass[i] != 0) kept.value[i] = NAN;
  for (RenderMode mode : {RenderMode::PathTracer, RenderMode::Whitted}) {
    RenderSettings st;
    st.max_bounces = 1;
    st.mode = mode;
    const RenderResult r = render_scene(s, kW, kH, 256, st);
    check_image(std::string("sealed light, camera inside (") + kRenderModeNames[int(mode)] + ")", r, kept, 1);
  }
}
