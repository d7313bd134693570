// CPU twin of plane.glsl's intersect_plane: dot(s.a, p) = s.radius.
#pragma once
#include "scene/scene.h"
#include "shapes/ray.h"

namespace pt {

inline void intersect_plane(const Shape& s, int id, const Ray& r, Hit& h) {
  const float denom = glm::dot(s.a, r.d);
  if (denom == 0.0f) return;
  const float t = (s.radius - glm::dot(s.a, r.o)) / denom;
  if (!(t > 0.0f) || t >= h.t) return;
  h.t = t;
  h.id = id;
  h.n = s.a;
  h.p = r.o + t * r.d;
  h.p -= s.a * (glm::dot(s.a, h.p) - s.radius);
}

}  // namespace pt
