// CPU twin of triangle.glsl's prepare_triangle and intersect_triangle (watertight, Woop
// et al. 2013, with the canonical edge order that makes shared edges exact).
#pragma once
#include "scene/scene.h"
#include "shapes/ray.h"

namespace pt {

inline bool vertex_before(glm::vec3 p, glm::vec3 q) {
  return p.x < q.x || (p.x == q.x && (p.y < q.y || (p.y == q.y && p.z < q.z)));
}

// Which of the edges (c, b), (a, c), (b, a) run in canonical order (bits 0, 1, 2): the
// BVH's triangle primitives carry them, computed once when packing (triangle.glsl).
inline int triangle_edge_order(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  return (vertex_before(c, b) ? 1 : 0) | (vertex_before(a, c) ? 2 : 0) | (vertex_before(b, a) ? 4 : 0);
}

inline float edge_function(glm::vec3 p, glm::vec3 q, glm::vec2 ps, glm::vec2 qs) {
  return vertex_before(p, q) ? ps.x * qs.y - ps.y * qs.x : -(qs.x * ps.y - qs.y * ps.x);
}

struct TriangleRay {
  glm::vec3 x, y, z;
};

inline TriangleRay prepare_triangle(const Ray& r) {
  const glm::vec3 ad = glm::abs(r.d);
  const glm::vec3 ez = ad.x > ad.y ? (ad.x > ad.z ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1))
                                   : (ad.y > ad.z ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1));
  glm::vec3 ex(ez.z, ez.x, ez.y);  // the next axis after kz
  glm::vec3 ey(ex.z, ex.x, ex.y);
  const float dz = glm::dot(r.d, ez);
  if (dz < 0.0f) std::swap(ex, ey);  // keep the winding
  const float sz = 1.0f / dz;
  return {ex - glm::dot(r.d, ex) * sz * ez, ey - glm::dot(r.d, ey) * sz * ez, sz * ez};
}

inline void intersect_triangle(const Shape& s, int id, const Ray& r, const TriangleRay& tr, Hit& h) {
  const glm::vec3 a = s.a - r.o, b = s.b - r.o, c = s.c - r.o;
  const glm::vec2 a2(glm::dot(tr.x, a), glm::dot(tr.y, a));
  const glm::vec2 b2(glm::dot(tr.x, b), glm::dot(tr.y, b));
  const glm::vec2 c2(glm::dot(tr.x, c), glm::dot(tr.y, c));
  const float u = edge_function(s.c, s.b, c2, b2);
  const float v = edge_function(s.a, s.c, a2, c2);
  const float w = edge_function(s.b, s.a, b2, a2);
  if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return;
  const float det = u + v + w;
  if (det == 0.0f) return;
  const float t = (u * glm::dot(tr.z, a) + v * glm::dot(tr.z, b) + w * glm::dot(tr.z, c)) / det;
  if (!(t > 0.0f) || t >= h.t) return;
  h.t = t;
  h.id = id;
  h.n = glm::normalize(glm::cross(s.b - s.a, s.c - s.a));
  h.p = (u * s.a + v * s.b + w * s.c) / det;
}

}  // namespace pt
