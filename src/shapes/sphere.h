// Sphere: <Sphere center="x y z" radius="r" [velocity="x y z" | end="x y z"]>: the
// points at distance `radius` of the centre, which moves to center + velocity * t over
// the shutter (motion blur, extension; a <Light> is an emissive sphere too). Its record
// holds the centre, the radius and the velocity. Intersection in Haines et al.'s form ("Precision
// Improvements for Ray/Sphere Intersection", Ray Tracing Gems, ch. 7), sphere.glsl; the
// CPU twin below is the same arithmetic at shutter time 0.
#pragma once
#include <cmath>

#include "shapes/shape.h"

namespace pt {

struct Sphere;
inline void intersect_sphere(const Sphere& s, int id, const Ray& r, Hit& h);

struct Sphere {
  static constexpr const char* kXml = "Sphere";
  static constexpr const char* kExample = "<Sphere center=\"0.2 -0.1 0.3\" radius=\"0.8\"/>";
  static constexpr const char* kUvArgs = "";
  glm::vec3 center{0.0f};
  float radius = 1.0f;
  glm::vec3 velocity{0.0f};

#define PT_SPHERE_FIELDS(F) F(vec3, center) F(float, radius) F(vec3, velocity)
  PT_KIND_RECORD(PT_SPHERE_FIELDS, PT_NO_FIELDS)

  void parse(XmlAttrs& a) {
    center = a.vec3("center");
    radius = a.number("radius");
    if (!(radius > 0.0f)) a.fail("radius must be positive");
    velocity = parse_motion(a, center);
  }
  void pack(ShapeWriter& w) const {
    w.set(rec::center, center);
    w.set(rec::radius, radius);
    w.set(rec::velocity, velocity);
  }
  // Over the times the shutter sees (the centre's path is a segment).
  ShapeBounds bounds(const ShapeContext& ctx) const {
    ShapeBounds b;
    for (const glm::vec3 c : {center, center + velocity * ctx.motion_bound}) {
      b.grow(c - glm::vec3(radius));
      b.grow(c + glm::vec3(radius));
    }
    return b;
  }
  template <class Q>
  void intersect(const Q& q, int id, Hit& h) const { intersect_sphere(*this, id, q.r, h); }
  glm::vec3 position() const { return center; }
  float area() const { return 4.0f * 3.14159265f * radius * radius; }  // light selection by power
  // Light sealing (render/light_select.h): all of the sphere but a set of zero area lies
  // strictly inside the box [lo, hi] over the shutter's times (inside a box, a sphere
  // meets a face's plane in one point at most, so touching the faces is allowed).
  bool inside_box(glm::vec3 lo, glm::vec3 hi, float motion_bound) const {
    for (const glm::vec3 c : {center, center + velocity * motion_bound})
      if (glm::any(glm::lessThan(c - radius, lo)) || glm::any(glm::greaterThan(c + radius, hi))) return false;
    return true;
  }
  void move(glm::vec3 d) { center += d; }
  template <class E>
  bool edit(E& e) { return edit_radius(e, radius); }
};

// CPU twin of sphere.glsl's intersect_sphere.
inline void intersect_sphere(const Sphere& s, int id, const Ray& r, Hit& h) {
  const glm::vec3 c0 = s.center;
  const glm::vec3 f = r.o - c0;
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
  h.n = glm::normalize(r.o + t * r.d - c0);
  h.p = c0 + s.radius * h.n;
}

}  // namespace pt
