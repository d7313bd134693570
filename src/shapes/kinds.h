// The one list of shape kinds (the material kinds: materials/kinds.h). A kind is one
// stem: shapes/<glsl>.h (its parameters with the XML's names, strict parse, record,
// bounds, CPU intersection twin, position and panel fields, an example, the model's
// comment; shapes/shape.h is what it is written against) beside shapes/<glsl>.glsl.
// Adding a kind = its stem + one line here + its #include in shapes/all.h (+ its test).
// The XML dispatch, the scene model (a std::variant, shapes/all.h), the packing, picking,
// the selection panel, the shader generator and the tests all iterate this list.
//
//   Shapes:    X(Type, glsl_name, "XmlElement", samplable, per_ray, bvh)
//              samplable: an emissive one is light-sampled (its snippet defines
//              sample_light_<name> / pdf_light_<name>); per_ray: its intersection uses
//              data computed once per ray (<Name>Ray prepare_<name>(Ray), passed to
//              intersect_<name> after the ray); bvh: how it enters the acceleration
//              structure (Analytic: one bounded primitive tested through its shape record;
//              Triangles: its triangle is a primitive with its vertices inline;
//              Instanced: the triangles of a shared mesh (Scene::meshes), placed by the
//              instance's transform, each a primitive like a Triangle's, with per-vertex
//              attributes; Unbounded: outside the BVH, tested by every ray)
#pragma once

#define PT_SHAPE_KINDS(X)                                   \
  X(Sphere, sphere, "Sphere", true, false, Analytic)          \
  X(Box, box, "Box", true, true, Analytic)                    \
  X(Plane, plane, "Plane", false, false, Unbounded)           \
  X(Triangle, triangle, "Triangle", true, true, Triangles)    \
  X(Mesh, mesh, "Mesh", false, false, Instanced)              \
  X(Disk, disk, "Disk", true, false, Analytic)

namespace pt {

enum class ShapeKind : int {
#define PT_X(e, g, x, l, r, b) e,
  PT_SHAPE_KINDS(PT_X)
#undef PT_X
};

enum class BvhRole : int { None, Analytic, Triangles, Instanced, Unbounded };

struct KindInfo {
  const char* glsl;  // snippet name and function suffix: shapes/sphere.glsl, intersect_sphere
  const char* xml;   // element name in scene files
  bool samplable;    // shapes: emitters of this kind are light-sampled
  bool per_ray;      // shapes: intersection takes per-ray data from prepare_<glsl>
  BvhRole bvh;       // shapes: how the acceleration structure holds it
};

inline constexpr KindInfo kShapeKinds[] = {
#define PT_X(e, g, x, l, r, b) {#g, x, l, r, BvhRole::b},
    PT_SHAPE_KINDS(PT_X)
#undef PT_X
};
inline constexpr int kNumShapeKinds = int(sizeof(kShapeKinds) / sizeof(kShapeKinds[0]));

inline const KindInfo& info(ShapeKind k) { return kShapeKinds[int(k)]; }

}  // namespace pt
