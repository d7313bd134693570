// What every shape kind's stem is written against (shapes/<kind>.h):
//  - ShapeRecord: the geometry it writes into its shape record (core/records.h,
//    PT_SHAPE_RECORD: a, b, c, radius); the record's layout is shared, but each kind
//    decides what goes where (its <kind>.glsl reads the same slots). An analytic
//    primitive (PT_PRIM_RECORD) copies a, b and radius;
//  - ShapeBounds: the box the BVH holds (before padding) and the tests check its hits
//    against; ShapeContext: what bounds and intersection may need of the scene;
//  - its intersection: template <class Q> intersect(const Q&, int id, Hit&), where Q
//    (shapes/all.h: ShapeQuery) carries the ray, the per-ray data of the kinds whose
//    GLSL has a prepare_<kind> and the ShapeContext.
// A stem declares kXml (its element), kExample (an element the tests loop over), kUvArgs
// (the arguments its uv_<glsl> / tangent_<glsl> take after the shape record, before
// p and n), parse(XmlAttrs&) (strict) or kLoadedByLoader (its element reads files:
// the loader builds it), record(), bounds(ctx), position(), move(delta) and
// edit(editor) (its panel fields besides the position).
#pragma once
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/xml_attrs.h"
#include "shapes/mesh_data.h"
#include "shapes/ray.h"

namespace pt {

using MeshList = std::vector<std::shared_ptr<const MeshData>>;

struct ShapeRecord {
  glm::vec3 a{0.0f}, b{0.0f}, c{0.0f};
  float radius = 0.0f;
};

struct ShapeBounds {
  glm::vec3 lo{3.0e38f}, hi{-3.0e38f};  // empty: lo > hi
  void grow(glm::vec3 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
};

struct ShapeContext {
  const MeshList* meshes = nullptr;  // Scene::meshes (a Mesh's triangles)
  float motion_bound = 1.0f;         // the latest time a moving shape is seen at
};

// Motion blur (extension): `velocity` (per unit time), or `end`, the centre at time 1
// (velocity = end - start); not both. (Also read by <Light>.)
inline glm::vec3 parse_motion(XmlAttrs& a, glm::vec3 start) {
  if (a.has("velocity") && a.has("end")) a.fail("give either 'velocity' or 'end'");
  return a.has("end") ? a.vec3("end") - start : a.vec3("velocity", glm::vec3(0.0f));
}

}  // namespace pt
