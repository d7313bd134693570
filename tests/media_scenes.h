// The absorbing-media closed forms and scenes shared by tests/media_test.cpp,
// tests/rough_dielectric_test.cpp and tests/gltf_materials_test.cpp: glass of n 1.5
// (normal-incidence Fresnel F = ((n - 1) / (n + 1))^2 = 0.04) keeping kAttenuation per unit
// length, seen at (near) normal incidence through a camera of 0.2 degrees (the angles
// inside change path lengths and Fresnel factors by under 1e-5).
#pragma once
#include <cmath>

#include "materials/medium.h"
#include "scene_builders.h"

namespace pt {

inline constexpr double kGlassF = 0.04;
inline const glm::vec3 kAttenuation(0.5f, 0.8f, 0.2f);  // per unit length (attenuationDistance 1)

// A slab of thickness d in a sky of 1: what comes back, its reflectance plus its
// transmittance with every internal reflection, for a = exp(-sigma d):
//   T = (1 - F)^2 a / (1 - F^2 a^2),   R = F + (1 - F)^2 F a^2 / (1 - F^2 a^2).
inline double slab_returned(double a, double f = kGlassF) {
  const double k = 1.0 - f * f * a * a;
  return (1 - f) * (1 - f) * a / k + f + (1 - f) * (1 - f) * f * a * a / k;
}
// An emitter of radiance le inside the glass, its face at depth L (a = exp(-sigma L)), seen
// through the front face under a black sky: le (1 - F) a / n^2.
inline double emitter_seen(double le, double a, double f = kGlassF, double n = 1.5) { return le * (1 - f) * a / (n * n); }

// The camera at z = 10 looking down -z with a 0.2-degree field of view, under a sky of `sky`.
inline Scene looking_down(float sky) {
  Scene s;
  s.camera = camera_looking_down_z(glm::vec3(0.0f, 0.0f, 10.0f));
  s.camera.fov_y = 0.2f;
  s.environment.color = glm::vec3(sky);
  return s;
}
// The slab scene: glass `m` 1 thick (z in [-0.5, 0.5]), 40 wide, in a sky of 1.
inline Scene slab_scene(const Material& m) {
  Scene s = looking_down(1.0f);
  add_box(s, {-20.0f, -20.0f, -0.5f}, {20.0f, 20.0f, 0.5f}, add_material(s, m));
  return s;
}
// The emitter scene: a block of glass `m` (z in [-3, 1]) holding an emitting slab of
// radiance 2 whose face is at z = -0.5 (L = 1.5), under a black sky.
inline Scene emitter_scene(const Material& m) {
  Scene s = looking_down(0.0f);
  add_box(s, {-20.0f, -20.0f, -3.0f}, {20.0f, 20.0f, 1.0f}, add_material(s, m));
  Material lamp = Emit{};
  lamp.emission = glm::vec3(2.0f);
  add_box(s, {-19.0f, -19.0f, -1.0f}, {19.0f, 19.0f, -0.5f}, add_material(s, lamp));
  return s;
}

// Each channel's mean over the image.
inline glm::dvec3 image_mean(const RenderResult& r) {
  glm::dvec3 sum(0.0);
  for (int i = 0; i < r.w * r.h; ++i)
    for (int c = 0; c < 3; ++c) sum[c] += r.rgba[size_t(i) * 4 + c];
  return sum / double(r.w * r.h);
}

}  // namespace pt
