// CPU twin of box.glsl's prepare_box and intersect_box (slab method, parallel axes
// handled explicitly).
#pragma once
#include "scene/scene.h"
#include "shapes/ray.h"

namespace pt {

struct BoxRay {
  glm::vec3 inv;
  glm::bvec3 parallel;
};

inline BoxRay prepare_box(const Ray& r) {
  const glm::bvec3 par = glm::lessThan(glm::abs(r.d), glm::vec3(1e-30f));
  return {1.0f / glm::mix(r.d, glm::vec3(1.0f), glm::vec3(par)), par};
}

inline void intersect_box(const Shape& s, int id, const Ray& r, const BoxRay& br, Hit& h) {
  for (int k = 0; k < 3; ++k)
    if (br.parallel[k] && (r.o[k] < s.a[k] || r.o[k] > s.b[k])) return;
  const glm::vec3 ta = (s.a - r.o) * br.inv, tb = (s.b - r.o) * br.inv;
  glm::vec3 tmin = glm::min(ta, tb), tmax = glm::max(ta, tb);
  for (int k = 0; k < 3; ++k)
    if (br.parallel[k]) tmin[k] = -T_INF, tmax[k] = T_INF;
  const float t_near = max3(tmin);
  const float t_far = glm::min(glm::min(tmax.x, tmax.y), tmax.z);
  if (t_near > t_far || t_far <= 0.0f) return;
  const bool inside = t_near <= 0.0f;
  const float t = inside ? t_far : t_near;
  if (t >= h.t) return;
  const glm::vec3 sel = inside ? tmax : tmin;
  const glm::vec3 axis = sel.x == t ? glm::vec3(1, 0, 0) : (sel.y == t ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1));
  const float along = glm::dot(axis, r.d) >= 0.0f ? 1.0f : -1.0f;
  h.t = t;
  h.id = id;
  h.n = axis * (inside ? along : -along);
  h.p = r.o + t * r.d;
  h.p = glm::mix(h.p, glm::dot(h.n, axis) > 0.0f ? s.b : s.a, axis);
}

}  // namespace pt
