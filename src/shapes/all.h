// Every shape kind's stem, and what the list of kinds (shapes/kinds.h) makes of them: the
// scene model's parameters (a std::variant in list order, so its index is the ShapeKind),
// the table of what the rest of the program needs to know of each kind without naming
// it, and the calls that dispatch on the kind (intersection, bounds, record, position).
#pragma once
#include <string_view>
#include <type_traits>
#include <variant>

#include "shapes/kinds.h"
// One include per kind, in the list's order.
#include "shapes/sphere.h"
#include "shapes/box.h"
#include "shapes/plane.h"
#include "shapes/triangle.h"
#include "shapes/mesh.h"
#include "shapes/disk.h"

namespace pt {

using ShapeParams = KindVariant<
#define PT_X(e, g, x, l, r, b) e,
    PT_SHAPE_KINDS(PT_X)
#undef PT_X
    ListEnd>;

template <class K, class = void>
struct KindLoadedByLoader : std::false_type {};
template <class K>
struct KindLoadedByLoader<K, std::void_t<decltype(K::kLoadedByLoader)>> : std::bool_constant<K::kLoadedByLoader> {};

template <class K, class = void>
struct KindShadingNormal : std::false_type {};
template <class K>
struct KindShadingNormal<K, std::void_t<decltype(K::kShadingNormal)>> : std::bool_constant<K::kShadingNormal> {};

template <class K, class = void>
struct ShapeKindNeeds : std::integral_constant<unsigned, 0> {};
template <class K>
struct ShapeKindNeeds<K, std::void_t<decltype(K::kNeeds)>> : std::integral_constant<unsigned, K::kNeeds> {};

struct ShapeTraits {
  const char* example;   // the stem's kExample
  const KindField* fields;  // its record fields (PT_KIND_RECORD)
  int num_fields;
  unsigned needs;         // other shape kinds whose GLSL its own calls (kNeeds)
  const char* uv_args;   // what uv_<glsl>(s, ..., p, n) takes besides the record, p and n
  bool loaded_by_loader;  // its element reads files: the loader builds it, not parse()
  bool shading_normal;    // its GLSL defines shading_normal_<glsl> (the surface step's hook)
};

inline constexpr ShapeTraits kShapeTraits[] = {
#define PT_X(e, g, x, l, r, b) \
  {e::kExample, e::kFields, e::kNumFields, ShapeKindNeeds<e>::value, e::kUvArgs, KindLoadedByLoader<e>::value, KindShadingNormal<e>::value},
    PT_SHAPE_KINDS(PT_X)
#undef PT_X
};

#define PT_X(e, g, x, l, r, b)                                                                                       \
  static_assert(std::variant_alternative_t<int(ShapeKind::e), ShapeParams>::kXml == std::string_view(x));              \
  static_assert(stored_width<e>() <= shape_rec::kPayloadSlots, #e ": more record fields than payload slots");          \
  static_assert((BvhRole::b != BvhRole::Analytic && BvhRole::b != BvhRole::Unbounded) ||                              \
                    stored_width<e>() <= prim_rec::kAnalyticSlots,                                                     \
                #e ": an analytic primitive copies at most prim_rec::kAnalyticSlots slots");
PT_SHAPE_KINDS(PT_X)
#undef PT_X

// A ray as every kind's intersection takes it: with the per-ray data of the kinds that
// prepare one (prepare_<glsl>, computed once) and what the kinds may read of the scene.
struct ShapeQuery {
  Ray r;
  BoxRay box;
  TriangleRay triangle;
  ShapeContext ctx;
  ShapeQuery(const Ray& ray, ShapeContext c) : r(ray), box(prepare_box(ray)), triangle(prepare_triangle(ray)), ctx(c) {}
};

// f(kind's params) for the kind `p` holds.
template <class P, class F>
decltype(auto) visit_shape(P& p, F&& f) {
  return std::visit(f, p);
}

inline void intersect(const ShapeParams& p, const ShapeQuery& q, int id, Hit& h) {
  visit_shape(p, [&](const auto& k) { k.intersect(q, id, h); });
}
inline ShapeBounds bounds(const ShapeParams& p, const ShapeContext& ctx) {
  return visit_shape(p, [&](const auto& k) { return k.bounds(ctx); });
}
// Writes the kind's fields into record `i` of `b` over `slots` (the shape record's
// payload, or an analytic primitive's copy of it).
inline void pack_shape(const ShapeParams& p, RecordBuffer& b, int i, PayloadSlots slots) {
  visit_shape(p, [&](const auto& k) {
    ShapeWriter w(b, i, k.kFields, slots);
    k.pack(w);
  });
}
// The vertices of a kind whose primitive is a triangle inline (BvhRole::Triangles).
inline void shape_vertices(const ShapeParams& p, glm::vec3 v[3]) {
  visit_shape(p, [&](const auto& k) {
    if constexpr (requires { k.vertices(v); }) k.vertices(v);
    else v[0] = v[1] = v[2] = glm::vec3(0.0f);
  });
}
inline glm::vec3 position(const ShapeParams& p) {
  return visit_shape(p, [](const auto& k) { return k.position(); });
}
inline void move(ShapeParams& p, glm::vec3 d) {
  visit_shape(p, [&](auto& k) { k.move(d); });
}
// An emitter's surface area, for light selection by power (render/light_select.h): the
// samplable kinds give theirs, the others 0.
inline float area(const ShapeParams& p) {
  return std::visit([](const auto& k) -> float {
    if constexpr (requires { k.area(); }) return k.area();
    else return 0.0f;
  }, p);
}
// Light sealing (render/light_select.h): whether shape p is a closed solid whose inside is
// the box [lo, hi] (the kinds that define solid()), and whether all of shape p but a set
// of zero area lies strictly inside the box [lo, hi] (a kind's inside_box, else its
// bounds strictly inside).
inline bool solid(const ShapeParams& p, glm::vec3& lo, glm::vec3& hi) {
  return std::visit([&](const auto& k) -> bool {
    if constexpr (requires { k.solid(lo, hi); }) return k.solid(lo, hi);
    else return false;
  }, p);
}
inline bool inside_box(const ShapeParams& p, glm::vec3 lo, glm::vec3 hi, const ShapeContext& ctx) {
  return std::visit([&](const auto& k) -> bool {
    if constexpr (requires { k.inside_box(lo, hi, ctx.motion_bound); }) return k.inside_box(lo, hi, ctx.motion_bound);
    else {
      const ShapeBounds b = k.bounds(ctx);
      return glm::all(glm::greaterThan(b.lo, lo)) && glm::all(glm::lessThan(b.hi, hi));
    }
  }, p);
}
// A moving kind's velocity (motion blur), zero for the others.
inline glm::vec3 velocity(const ShapeParams& p) {
  return visit_shape(p, [](const auto& k) {
    if constexpr (requires { k.velocity; }) return glm::vec3(k.velocity);
    else return glm::vec3(0.0f);
  });
}

}  // namespace pt
