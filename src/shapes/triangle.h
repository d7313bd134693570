// Triangle: <Triangle v0="x y z" v1=".." v2=".." [uv0="u v" uv1=".." uv2=".."]
// [velocity="x y z" | end="x y z"]>: one triangle (its vertices' texture coordinates, an
// extension, are read by <Textured>; they live in the uv records, core/records.h),
// translated by velocity * t over the shutter (motion blur, extension; `end`: its
// centroid at time 1). Its record holds v0, v1, v2 (light sampling reads them) and the
// velocity; in the BVH it is a triangle primitive with its vertices (at time 0) inline,
// marked as moving (prim `extra`: triangle.glsl translates the ray by the velocity of
// shape `tag`), bounded over the shutter. Intersection watertight (Woop et al.
// 2013, "Watertight Ray/Triangle Intersection", JCGT 2(1)) with the canonical edge order
// that makes shared edges exact (triangle.glsl); the CPU twins below are the same
// arithmetic.
#pragma once
#include <utility>

#include "shapes/shape.h"

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

// CPU twin of triangle.glsl's prepare_triangle.
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

struct Triangle;
inline void intersect_triangle(const Triangle& s, int id, const Ray& r, const TriangleRay& tr, Hit& h);

struct Triangle {
  static constexpr const char* kXml = "Triangle";
  static constexpr const char* kExample = "<Triangle v0=\"-0.8 -0.5 0.1\" v1=\"0.9 -0.3 -0.2\" v2=\"0.1 0.8 0.4\"/>";
  static constexpr const char* kUvArgs = "load_uv(h.id), ";  // its vertex uv: the uv record of its shape index
  glm::vec3 v0{0.0f}, v1{1.0f, 0.0f, 0.0f}, v2{0.0f, 1.0f, 0.0f};
  glm::vec2 uv0{0.0f, 0.0f}, uv1{1.0f, 0.0f}, uv2{0.0f, 1.0f};
  glm::vec3 velocity{0.0f};

#define PT_TRIANGLE_FIELDS(F) F(vec3, v0) F(vec3, v1) F(vec3, v2) F(vec3, velocity)
  PT_KIND_RECORD(PT_TRIANGLE_FIELDS, PT_NO_FIELDS)

  void parse(XmlAttrs& a) {
    v0 = a.vec3("v0");
    v1 = a.vec3("v1");
    v2 = a.vec3("v2");
    if (a.has("uv0")) uv0 = a.vec2("uv0");
    if (a.has("uv1")) uv1 = a.vec2("uv1");
    if (a.has("uv2")) uv2 = a.vec2("uv2");
    if (!(glm::length(glm::cross(v1 - v0, v2 - v0)) > 0.0f)) a.fail("triangle has zero area");
    velocity = parse_motion(a, position());
  }
  void pack(ShapeWriter& w) const {
    w.set(rec::v0, v0);
    w.set(rec::v1, v1);
    w.set(rec::v2, v2);
    w.set(rec::velocity, velocity);
  }
  // Its primitive in the BVH (BvhRole::Triangles): the vertices, inline.
  void vertices(glm::vec3 v[3]) const { v[0] = v0, v[1] = v1, v[2] = v2; }
  float area() const { return 0.5f * glm::length(glm::cross(v1 - v0, v2 - v0)); }  // light selection by power
  ShapeBounds bounds(const ShapeContext& ctx) const {
    ShapeBounds b;
    for (const glm::vec3& q : {v0, v1, v2}) b.grow(q);
    return swept(b, velocity, ctx.motion_bound);
  }
  template <class Q>
  void intersect(const Q& q, int id, Hit& h) const { intersect_triangle(*this, id, q.r, q.triangle, h); }
  glm::vec3 position() const { return (v0 + v1 + v2) / 3.0f; }  // the centroid
  void move(glm::vec3 d) { v0 += d, v1 += d, v2 += d; }
  template <class E>
  bool edit(E&) { return false; }
};

// CPU twin of triangle.glsl's intersect_triangle.
inline void intersect_triangle(const Triangle& s, int id, const Ray& r, const TriangleRay& tr, Hit& h) {
  const glm::vec3 a = s.v0 - r.o, b = s.v1 - r.o, c = s.v2 - r.o;
  const glm::vec2 a2(glm::dot(tr.x, a), glm::dot(tr.y, a));
  const glm::vec2 b2(glm::dot(tr.x, b), glm::dot(tr.y, b));
  const glm::vec2 c2(glm::dot(tr.x, c), glm::dot(tr.y, c));
  const float u = edge_function(s.v2, s.v1, c2, b2);
  const float v = edge_function(s.v0, s.v2, a2, c2);
  const float w = edge_function(s.v1, s.v0, b2, a2);
  if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return;
  const float det = u + v + w;
  if (det == 0.0f) return;
  const float t = (u * glm::dot(tr.z, a) + v * glm::dot(tr.z, b) + w * glm::dot(tr.z, c)) / det;
  if (!(t > 0.0f) || t >= h.t) return;
  h.t = t;
  h.id = id;
  h.n = glm::normalize(glm::cross(s.v1 - s.v0, s.v2 - s.v0));
  h.p = (u * s.v0 + v * s.v1 + w * s.v2) / det;
}

}  // namespace pt
