// Plane: <Plane normal="x y z" d="d" [velocity="x y z" | end="x y z"]>: the points p
// with dot(normal, p) = d, normal made unit on load (d scales with it), translated by
// velocity * t over the shutter (motion blur, extension: only the velocity's part along
// the normal moves the surface, the rest slides an image map; `end`: the point
// normal * d at time 1). Unbounded: outside the BVH, every ray tests it.
// Its record holds the unit normal, d and the velocity (plane.glsl); the CPU twin below is the same
// arithmetic.
#pragma once
#include <cmath>

#include "shapes/shape.h"

namespace pt {

struct Plane;
inline void intersect_plane(const Plane& s, int id, const Ray& r, Hit& h);

struct Plane {
  static constexpr const char* kXml = "Plane";
  static constexpr const char* kExample = "<Plane normal=\"0.1 1 -0.2\" d=\"-0.4\"/>";
  static constexpr const char* kUvArgs = "";
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  float d = 0.0f;
  glm::vec3 velocity{0.0f};

#define PT_PLANE_FIELDS(F) F(vec3, normal) F(float, d) F(vec3, velocity)
  PT_KIND_RECORD(PT_PLANE_FIELDS, PT_NO_FIELDS)

  void parse(XmlAttrs& a) {
    const glm::vec3 n = a.vec3("normal");
    const float d0 = a.number("d");
    const float len = glm::length(n);
    if (!(len > 0.0f) || !std::isfinite(len)) a.fail("plane normal must be non-zero");
    normal = n / len;  // d = dot(normal, p0) scales with the normal's length
    d = d0 / len;
    velocity = parse_motion(a, position());
  }
  void pack(ShapeWriter& w) const {
    w.set(rec::normal, normal);
    w.set(rec::d, d);
    w.set(rec::velocity, velocity);
  }
  ShapeBounds bounds(const ShapeContext&) const { return {glm::vec3(-T_INF), glm::vec3(T_INF)}; }  // everything
  template <class Q>
  void intersect(const Q& q, int id, Hit& h) const { intersect_plane(*this, id, q.r, h); }
  glm::vec3 position() const { return normal * d; }  // the point closest to the origin
  void move(glm::vec3 delta) { d += glm::dot(normal, delta); }  // only the offset along the normal moves it
  template <class E>
  bool edit(E&) { return false; }
};

// CPU twin of plane.glsl's intersect_plane.
inline void intersect_plane(const Plane& s, int id, const Ray& r, Hit& h) {
  const float denom = glm::dot(s.normal, r.d);
  if (denom == 0.0f) return;
  const float t = (s.d - glm::dot(s.normal, r.o)) / denom;
  if (!(t > 0.0f) || t >= h.t) return;
  h.t = t;
  h.id = id;
  h.n = s.normal;
  h.p = r.o + t * r.d;
  h.p -= s.normal * (glm::dot(s.normal, h.p) - s.d);
}

}  // namespace pt
