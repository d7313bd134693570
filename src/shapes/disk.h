// Disk: <Disk center="x y z" normal="x y z" radius="r" [velocity="x y z" | end="x y z"]>:
// the points of the plane through `center` with unit normal `normal` (made unit on load)
// within `radius` of the centre, the centre moving to center + velocity * t over the
// shutter (motion blur, extension; disk.glsl translates the ray).
// Its normal is fixed, as a plane's: an emissive disk emits on the side the normal points
// to (the surface step's front), and is light-sampled uniformly by area. Its record holds
// the centre, the radius, the normal and the velocity. Intersection: the plane's distance, then the
// point (snapped onto the plane) tested against the radius (disk.glsl); the CPU twin below
// is the same arithmetic. Bounds: per axis, centre +- radius * sqrt(1 - normal_i^2), the
// disk's exact extent (pbrt-v4's Disk bounds its local z slab; this is the world box),
// swept over the shutter.
#pragma once
#include <cmath>

#include "shapes/shape.h"

namespace pt {

struct Disk;
inline void intersect_disk(const Disk& s, int id, const Ray& r, Hit& h);

struct Disk {
  static constexpr const char* kXml = "Disk";
  static constexpr const char* kExample = "<Disk center=\"0.1 -0.2 0.2\" normal=\"0.3 1 -0.4\" radius=\"0.9\"/>";
  static constexpr const char* kUvArgs = "";
  glm::vec3 center{0.0f};
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  float radius = 1.0f;
  glm::vec3 velocity{0.0f};

#define PT_DISK_FIELDS(F) F(vec3, center) F(float, radius) F(vec3, normal) F(vec3, velocity)
  PT_KIND_RECORD(PT_DISK_FIELDS, PT_NO_FIELDS)

  void parse(XmlAttrs& a) {
    center = a.vec3("center");
    const glm::vec3 n = a.vec3("normal");
    const float len = glm::length(n);
    if (!(len > 0.0f) || !std::isfinite(len)) a.fail("disk normal must be non-zero");
    normal = n / len;
    radius = a.number("radius");
    if (!(radius > 0.0f)) a.fail("radius must be positive");
    velocity = parse_motion(a, center);
  }
  void pack(ShapeWriter& w) const {
    w.set(rec::center, center);
    w.set(rec::radius, radius);
    w.set(rec::normal, normal);
    w.set(rec::velocity, velocity);
  }
  float area() const { return 3.14159265f * radius * radius; }  // light selection by power
  // Over the times the shutter sees (shape.h: swept).
  ShapeBounds bounds(const ShapeContext& ctx) const {
    const glm::vec3 e = radius * glm::sqrt(glm::max(glm::vec3(1.0f) - normal * normal, glm::vec3(0.0f)));
    return swept({center - e, center + e}, velocity, ctx.motion_bound);
  }
  template <class Q>
  void intersect(const Q& q, int id, Hit& h) const { intersect_disk(*this, id, q.r, h); }
  glm::vec3 position() const { return center; }
  void move(glm::vec3 d) { center += d; }
  template <class E>
  bool edit(E& e) { return edit_radius(e, radius); }
};

// CPU twin of disk.glsl's intersect_disk.
inline void intersect_disk(const Disk& s, int id, const Ray& r, Hit& h) {
  const float denom = glm::dot(s.normal, r.d);
  if (denom == 0.0f) return;
  const float t = glm::dot(s.normal, s.center - r.o) / denom;
  if (!(t > 0.0f) || t >= h.t) return;
  glm::vec3 q = r.o + t * r.d - s.center;
  q -= s.normal * glm::dot(s.normal, q);  // onto the disk's plane
  if (glm::dot(q, q) > s.radius * s.radius) return;
  h.t = t;
  h.id = id;
  h.n = s.normal;
  h.p = s.center + q;
}

}  // namespace pt
