// Box: <Box min="x y z" max="x y z" [velocity="x y z" | end="x y z"]>: an axis-aligned
// box (files written for the original program give min > max on some axes: normalised
// on load), translated by velocity * t over the shutter (motion blur, extension; `end`:
// its centre at time 1). Its record holds the corners lo = min, hi = max and the
// velocity; box.glsl intersects a moving box by translating the ray. Intersection by the slab method with rays parallel to an axis handled
// explicitly (box.glsl); the CPU twin below is the same arithmetic.
#pragma once
#include "shapes/shape.h"

namespace pt {

struct BoxRay {
  glm::vec3 inv;
  glm::bvec3 parallel;
};

// CPU twin of box.glsl's prepare_box.
inline BoxRay prepare_box(const Ray& r) {
  const glm::bvec3 par = glm::lessThan(glm::abs(r.d), glm::vec3(1e-30f));
  return {1.0f / glm::mix(r.d, glm::vec3(1.0f), glm::vec3(par)), par};
}

struct Box;
inline void intersect_box(const Box& s, int id, const Ray& r, const BoxRay& br, Hit& h);

struct Box {
  static constexpr const char* kXml = "Box";
  static constexpr const char* kExample = "<Box min=\"-0.5 -0.7 -0.3\" max=\"0.6 0.4 0.9\"/>";
  static constexpr const char* kUvArgs = "";
  glm::vec3 min{-1.0f}, max{1.0f};
  glm::vec3 velocity{0.0f};

#define PT_BOX_FIELDS(F) F(vec3, lo) F(vec3, hi) F(vec3, velocity)
  PT_KIND_RECORD(PT_BOX_FIELDS, PT_NO_FIELDS)

  void parse(XmlAttrs& a) {
    const glm::vec3 p = a.vec3("min"), q = a.vec3("max");
    min = glm::min(p, q);
    max = glm::max(p, q);
    if (min.x == max.x && min.y == max.y && min.z == max.z) a.fail("box has no extent");
    velocity = parse_motion(a, position());
  }
  void pack(ShapeWriter& w) const {
    w.set(rec::lo, min);
    w.set(rec::hi, max);
    w.set(rec::velocity, velocity);
  }
  // Over the times the shutter sees (shape.h: swept).
  ShapeBounds bounds(const ShapeContext& ctx) const {
    ShapeBounds b;
    b.grow(min);
    b.grow(max);
    return swept(b, velocity, ctx.motion_bound);
  }
  template <class Q>
  void intersect(const Q& q, int id, Hit& h) const { intersect_box(*this, id, q.r, q.box, h); }
  glm::vec3 position() const { return 0.5f * (min + max); }
  // Light sealing (render/light_select.h): a box is a closed solid; with an absorbing
  // material nothing from outside reaches its inside [lo, hi].
  bool solid(glm::vec3& lo, glm::vec3& hi) const {
    lo = min, hi = max;
    return true;
  }
  float area() const {  // light selection by power
    const glm::vec3 e = max - min;
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
  void move(glm::vec3 d) { min += d, max += d; }
  template <class E>
  bool edit(E&) { return false; }
};

// CPU twin of box.glsl's intersect_box.
inline void intersect_box(const Box& s, int id, const Ray& r, const BoxRay& br, Hit& h) {
  for (int k = 0; k < 3; ++k)
    if (br.parallel[k] && (r.o[k] < s.min[k] || r.o[k] > s.max[k])) return;
  const glm::vec3 ta = (s.min - r.o) * br.inv, tb = (s.max - r.o) * br.inv;
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
  h.p = glm::mix(h.p, glm::dot(h.n, axis) > 0.0f ? s.max : s.min, axis);
}

}  // namespace pt
