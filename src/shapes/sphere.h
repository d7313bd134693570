// CPU twin of sphere.glsl's intersect_sphere (same arithmetic, Haines et al.'s form),
// at shutter time 0: the centre is s.a.
#pragma once
#include <cmath>

#include "scene/scene.h"
#include "shapes/ray.h"

namespace pt {

inline void intersect_sphere(const Shape& s, int id, const Ray& r, Hit& h) {
  const glm::vec3 center = s.a;
  const glm::vec3 f = r.o - center;
  const float b = -glm::dot(f, r.d);
  const glm::vec3 l = f + b * r.d;
  const float r2 = s.radius * s.radius;
  const float disc = r2 - glm::dot(l, l);
  if (disc < 0.0f) return;
  const float q = b + (b >= 0.0f ? 1.0f : -1.0f) * std::sqrt(disc);
  const float c = glm::dot(f, f) - r2;
  const float t0 = c / q, t1 = q;
  float t = glm::min(t0, t1);
  if (t <= 0.0f) t = glm::max(t0, t1);
  if (!(t > 0.0f) || t >= h.t) return;
  h.t = t;
  h.id = id;
  h.n = glm::normalize(r.o + t * r.d - center);
  h.p = center + s.radius * h.n;
}

}  // namespace pt
