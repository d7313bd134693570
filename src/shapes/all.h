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

namespace pt {

using ShapeParams = std::variant<
#define PT_X(e, g, x, l, r, b) e,
    PT_SHAPE_KINDS(PT_X)
#undef PT_X
    std::monostate>;  // never held: it ends the list

template <class K, class = void>
struct KindLoadedByLoader : std::false_type {};
template <class K>
struct KindLoadedByLoader<K, std::void_t<decltype(K::kLoadedByLoader)>> : std::bool_constant<K::kLoadedByLoader> {};

template <class K, class = void>
struct KindShadingNormal : std::false_type {};
template <class K>
struct KindShadingNormal<K, std::void_t<decltype(K::kShadingNormal)>> : std::bool_constant<K::kShadingNormal> {};

struct ShapeTraits {
  const char* example;   // the stem's kExample
  const char* uv_args;   // what uv_<glsl>(s, ..., p, n) takes besides the record, p and n
  bool loaded_by_loader;  // its element reads files: the loader builds it, not parse()
  bool shading_normal;    // its GLSL defines shading_normal_<glsl> (the surface step's hook)
};

inline constexpr ShapeTraits kShapeTraits[] = {
#define PT_X(e, g, x, l, r, b) {e::kExample, e::kUvArgs, KindLoadedByLoader<e>::value, KindShadingNormal<e>::value},
    PT_SHAPE_KINDS(PT_X)
#undef PT_X
};

#define PT_X(e, g, x, l, r, b) \
  static_assert(std::variant_alternative_t<int(ShapeKind::e), ShapeParams>::kXml == std::string_view(x));
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
  return std::visit(
      [&](auto& k) -> decltype(auto) {
        if constexpr (std::is_same_v<std::decay_t<decltype(k)>, std::monostate>) return f(std::get<0>(p));  // never held
        else return f(k);
      },
      p);
}

inline void intersect(const ShapeParams& p, const ShapeQuery& q, int id, Hit& h) {
  visit_shape(p, [&](const auto& k) { k.intersect(q, id, h); });
}
inline ShapeBounds bounds(const ShapeParams& p, const ShapeContext& ctx) {
  return visit_shape(p, [&](const auto& k) { return k.bounds(ctx); });
}
inline ShapeRecord record(const ShapeParams& p) {
  return visit_shape(p, [](const auto& k) { return k.record(); });
}
inline glm::vec3 position(const ShapeParams& p) {
  return visit_shape(p, [](const auto& k) { return k.position(); });
}
inline void move(ShapeParams& p, glm::vec3 d) {
  visit_shape(p, [&](auto& k) { k.move(d); });
}
// A moving kind's velocity (motion blur), zero for the others.
inline glm::vec3 velocity(const ShapeParams& p) {
  return visit_shape(p, [](const auto& k) {
    if constexpr (requires { k.velocity; }) return glm::vec3(k.velocity);
    else return glm::vec3(0.0f);
  });
}

}  // namespace pt
