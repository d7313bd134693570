// What every shape kind's stem is written against (shapes/<kind>.h):
//  - PT_KIND_RECORD (core/kind_record.h): its record fields, laid out over the shape
//    record's payload slots q0.. (core/records.h) in the order listed, and pack(ShapeWriter&)
//    writing them; its <kind>.glsl reads them as <glsl>_rec(s) (a struct <Type>Rec the
//    generator emits from the same list). An analytic primitive (PT_PRIM_RECORD) carries
//    a copy of the first prim_rec::kAnalyticSlots slots;
//  - ShapeBounds: the box the BVH holds (before padding) and the tests check its hits
//    against; ShapeContext: what bounds and intersection may need of the scene;
//  - its intersection: template <class Q> intersect(const Q&, int id, Hit&), where Q
//    (shapes/all.h: ShapeQuery) carries the ray, the per-ray data of the kinds whose
//    GLSL has a prepare_<kind> and the ShapeContext.
// A stem declares kXml (its element), kExample (an element the tests loop over), kUvArgs
// (the arguments its uv_<glsl> / tangent_<glsl> take after the shape record, before
// p and n), parse(XmlAttrs&) (strict) or kLoadedByLoader (its element reads files:
// the loader builds it), pack(w), bounds(ctx), position(), move(delta) and
// edit(editor) (its panel fields besides the position); optionally kNeeds (bits of the
// shape kinds whose GLSL its own calls) and, for BvhRole::Triangles, vertices(v).
#pragma once
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/kind_record.h"
#include "core/xml_attrs.h"
#include "shapes/kinds.h"
#include "shapes/mesh_data.h"
#include "shapes/ray.h"

namespace pt {

using MeshList = std::vector<std::shared_ptr<const MeshData>>;

// Writes a kind's fields into a shape record's payload, or into an analytic primitive's
// copy of them.
class ShapeWriter : public KindWriter {
 public:
  ShapeWriter(RecordBuffer& b, int record, const KindField* fields, PayloadSlots slots) : KindWriter(b, record, fields, slots) {}
};

constexpr unsigned shape_bit(ShapeKind k) { return 1u << int(k); }

// A radius as a panel field, through a copy: a typed-in value <= 0 is ignored.
template <class E>
bool edit_radius(E& e, float& radius) {
  float r = radius;
  if (!e.drag("radius", r, 0.2f, 1e-4f, 1e6f) || !(r > 0.0f)) return false;
  radius = r;
  return true;
}

struct ShapeBounds {
  glm::vec3 lo{3.0e38f}, hi{-3.0e38f};  // empty: lo > hi
  void grow(glm::vec3 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
};

// b and b moved by velocity * t: the box a translation sweeps over times [0, t] (the
// union of the two ends is exact for a straight-line motion of a box).
inline ShapeBounds swept(ShapeBounds b, glm::vec3 velocity, float t) {
  const glm::vec3 d = velocity * t;
  b.lo = glm::min(b.lo, b.lo + d);
  b.hi = glm::max(b.hi, b.hi + d);
  return b;
}

struct ShapeContext {
  const MeshList* meshes = nullptr;  // Scene::meshes (a Mesh's triangles)
  float motion_bound = 1.0f;         // the latest time a moving shape is seen at
};

// Motion blur (extension), on every kind: a translation over the shutter, `velocity`
// (per unit time), or `end`, the kind's position() (a sphere's or disk's centre, a box's
// centre, a triangle's centroid, a mesh instance's `position`, a plane's point closest to
// the origin) at time 1 (velocity = end - start); not both. (Also read by <Light>.)
inline glm::vec3 parse_motion(XmlAttrs& a, glm::vec3 start) {
  if (a.has("velocity") && a.has("end")) a.fail("give either 'velocity' or 'end'");
  return a.has("end") ? a.vec3("end") - start : a.vec3("velocity", glm::vec3(0.0f));
}

}  // namespace pt
