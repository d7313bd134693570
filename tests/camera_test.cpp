// Camera effects against what they must preserve: a thin lens leaves the plane of focus
// unchanged and conserves the light of an out-of-focus emitter while spreading it;
// motion blur gives the time average of a closed form.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "gl_context.h"
#include "render/camera.h"
#include "scene_builders.h"

using namespace pt;

namespace {

// Camera at the origin looking down -z at a white wall in the plane z = -10, lit by a
// sphere light between them; a small emitter sits on the wall's side of the light.
Scene wall_scene(float aperture, float focal_distance) {
  Scene s;
  s.camera = camera_looking_down_z(glm::vec3(0.0f));
  s.camera.aperture = aperture;
  s.camera.focal_distance = focal_distance;
  s.environment.color = glm::vec3(0.0f);
  Material white, lamp = Emit{};
  lamp.emission = glm::vec3(40.0f);
  add_box(s, glm::vec3(-50, -50, -11), glm::vec3(50, 50, -10), add_material(s, white));
  add_sphere(s, glm::vec3(1.0f, 1.5f, -9.0f), 0.25f, add_material(s, lamp));
  return s;
}

double sum_luminance(const RenderResult& r) {
  double s = 0;
  for (size_t i = 0; i < r.rgba.size(); i += 4) s += 0.2126 * r.rgba[i] + 0.7152 * r.rgba[i + 1] + 0.0722 * r.rgba[i + 2];
  return s;
}

}  // namespace

TEST_CASE("thin lens: the plane of focus is unchanged, an emitter out of focus is spread", "[gpu][camera]") {
  test_gl();
  const int W = 48, T = 8;
  const RenderResult pinhole = render_scene(wall_scene(0.0f, 1.0f), W, W, 256);
  const RenderResult lens = render_scene(wall_scene(0.3f, 10.0f), W, W, 256);
  // Tiles that see only the wall (not the emitter, whose depth is 9, out of focus).
  double worst = 0;
  for (int ty = 0; ty < W / T; ++ty)
    for (int tx = 0; tx < W / T; ++tx) {
      if (tx >= 3 && ty >= 3) continue;  // the emitter's quarter of the image
      const Estimate a = region_mean(pinhole, tx * T, ty * T, (tx + 1) * T, (ty + 1) * T);
      const Estimate b = region_mean(lens, tx * T, ty * T, (tx + 1) * T, (ty + 1) * T);
      worst = std::max(worst, std::abs(a.mean - b.mean) / std::sqrt(a.se * a.se + b.se * b.se + 1e-12));
    }
  std::printf("thin lens, wall in focus: worst tile |z| = %.2f\n", worst);
  CHECK(worst < 5.0);
  CHECK(lens.counters.bad_samples == 0);

  // Focused far away, the emitter (and the wall) blur: the image keeps its light.
  const RenderResult blurred = render_scene(wall_scene(1.0f, 1000.0f), W, W, 256);
  const double s0 = sum_luminance(pinhole), s1 = sum_luminance(blurred);
  float peak0 = 0, peak1 = 0;
  for (size_t i = 0; i < pinhole.rgba.size(); i += 4) peak0 = std::max(peak0, pinhole.rgba[i + 1]);
  for (size_t i = 0; i < blurred.rgba.size(); i += 4) peak1 = std::max(peak1, blurred.rgba[i + 1]);
  std::printf("thin lens, out of focus: image sum %.1f vs %.1f, peak %.2f vs %.2f\n", s1, s0, double(peak1), double(peak0));
  CHECK(std::abs(s1 - s0) < 0.02 * s0);
  CHECK(peak1 < 0.5f * peak0);
}

TEST_CASE("motion blur: a moving sphere light over a plane gives the time-averaged closed form", "[gpu][camera]") {
  test_gl();
  const float L = 10.0f, radius = 0.4f, shutter = 0.8f;
  const glm::vec3 start(-0.6f, 2.0f, -0.2f), velocity(1.5f, 0.3f, 0.2f);
  Scene s = sphere_light_over_plane(start, radius, L);
  s.camera.shutter = shutter;
  s.shapes.back().as<Sphere>()->velocity = velocity;
  RenderSettings st;
  st.max_bounces = 1;
  const int W = 40;
  const RenderResult r = render_scene(s, W, W, 256, st);
  const CameraBasis cb = camera_basis(s.camera, 1.0f);
  constexpr int kSub = 4, kTimes = 64;
  double sum = 0, var = 0, exact = 0;
  int n = 0;
  for (int y = 0; y < W; ++y)
    for (int x = 0; x < W; ++x) {
      // Leave out pixels near any position of the light in the image (a 1-pixel margin).
      bool near = false;
      double e = 0;
      for (int a = -kSub; a < 2 * kSub && !near; ++a)
        for (int b = -kSub; b < 2 * kSub && !near; ++b) {
          const glm::vec2 ndc = (glm::vec2(x + (a + 0.5f) / kSub, y + (b + 0.5f) / kSub) / float(W)) * 2.0f - 1.0f;
          const glm::vec3 d = glm::normalize(cb.forward + ndc.x * cb.right + ndc.y * cb.up);
          const bool inside = a >= 0 && a < kSub && b >= 0 && b < kSub;
          const glm::vec3 p = cb.position + (-cb.position.y / d.y) * d;
          for (int k = 0; k < kTimes; ++k) {
            const glm::vec3 c = start + velocity * (shutter * (k + 0.5f) / kTimes);
            const glm::vec3 oc = cb.position - c;
            const float bq = glm::dot(oc, d), cq = glm::dot(oc, oc) - radius * radius;
            if (bq * bq - cq >= 0.0f) near = true;
            if (inside) {
              const glm::vec3 to = c - p;
              const double dist = glm::length(to);
              e += L * (radius / dist) * (radius / dist) * (to.y / dist) / double(kSub * kSub * kTimes);
            }
          }
        }
      if (near) continue;
      const float* px = &r.rgba[(size_t(y) * W + x) * 4];
      sum += px[1];
      var += double(px[3]) / r.spp;  // alpha: the luminance variance of the samples
      exact += e;
      ++n;
    }
  REQUIRE(n > W * W / 2);
  const double mean = sum / n, se = std::sqrt(var) / n, ex = exact / n;
  std::printf("motion blur, moving light over a plane: %.5f exact %.5f (%+.2f se)\n", mean, ex, (mean - ex) / se);
  CHECK(std::abs(mean - ex) < 4.0 * se + 1e-4 * ex);
  CHECK(r.counters.bad_samples == 0);
}

TEST_CASE("field of view: 45 degrees vertically, the seed's; an emitter spans the rows it should", "[gpu][camera]") {
  test_gl();
  // An emissive box facing the camera at distance 10, as tall as half the view there
  // (|y| < 10 tan(22.5 deg) / 2) and wider than the view: exactly the middle half of the
  // rows must see it. With another field of view the edge moves by whole rows.
  Scene s;
  CHECK(s.camera.fov_y == 45.0f);
  s.camera = camera_looking_down_z(glm::vec3(0.0f));
  s.environment.color = glm::vec3(0.0f);
  Material lamp = Emit{};
  lamp.emission = glm::vec3(1.0f);
  const float half = 10.0f * std::tan(glm::radians(22.5f)) * 0.5f;
  add_box(s, glm::vec3(-100.0f, -half, -11.0f), glm::vec3(100.0f, half, -10.0f), add_material(s, lamp));
  const int W = 64, H = 64;
  const RenderResult r = render_scene(s, W, H, 16);
  int wrong = 0;
  for (int y = 0; y < H; ++y) {
    const double lum = r.rgba[(size_t(y) * W + W / 2) * 4 + 1];
    const bool inside = y >= H / 4 && y < 3 * H / 4;  // rows 16..47 see the emitter
    const bool edge = y == H / 4 - 1 || y == H / 4 || y == 3 * H / 4 - 1 || y == 3 * H / 4;
    if (!edge && (inside ? std::abs(lum - 1.0) > 1e-4 : lum > 1e-4)) ++wrong;
  }
  // The rows at the edges are cut at their boundary: about half their samples see it.
  const double below = r.rgba[(size_t(H / 4 - 1) * W + W / 2) * 4 + 1], above = r.rgba[(size_t(H / 4) * W + W / 2) * 4 + 1];
  std::printf("fov 45: rows outside/inside wrong %d; edge rows %.3f (outside) %.3f (inside)\n", wrong, below, above);
  CHECK(wrong == 0);
  CHECK(below < 0.25);
  CHECK(above > 0.75);
}
