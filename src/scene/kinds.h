// The one list per kind. Every shape and material is named here exactly once; the XML
// loader, the scene model, the texture packing, the shader generator and the tests all
// iterate these lists. Adding a kind = its files (parser, shapes/<name>.glsl or
// materials/<name>.glsl, test) plus one line here.
//
//   Shapes:    X(Enum, glsl_name, "XmlElement", samplable, per_ray, bvh)
//              samplable: an emissive one is light-sampled (its snippet defines
//              sample_light_<name> / pdf_light_<name>); per_ray: its intersection uses
//              data computed once per ray (<Name>Ray prepare_<name>(Ray), passed to
//              intersect_<name> after the ray); bvh: how it enters the acceleration
//              structure (Analytic: one bounded primitive tested through its shape record;
//              Triangles: its triangles are primitives with their vertices inline;
//              Unbounded: outside the BVH, tested by every ray)
//   Materials: X(Enum, glsl_name, "XmlElement")
#pragma once

#define PT_SHAPE_KINDS(X)                                   \
  X(Sphere, sphere, "Sphere", true, false, Analytic)          \
  X(Box, box, "Box", true, true, Analytic)                    \
  X(Plane, plane, "Plane", false, false, Unbounded)           \
  X(Triangle, triangle, "Triangle", true, true, Triangles)    \
  X(Mesh, mesh, "Mesh", false, false, Triangles)

// Material kinds are what a surface does with light. Attenuate is not a kind: it is a
// modifier that multiplies the tint of the material it wraps (any depth of nesting).
// Absorb is the inner half of Emit and has no kind of its own either.
#define PT_MATERIAL_KINDS(X)                          \
  X(Diffuse, diffuse, "Diffuse")                      \
  X(Metal, metal, "Metal")                            \
  X(Transmit, transmit, "Transmit")                   \
  X(SmoothDielectric, smooth_dielectric, "SmoothDielectric") \
  X(Emit, emit, "Emit")                               \
  X(Reflect, reflect, "Reflect")                      \
  X(PhongSpecular, phong_specular, "PhongSpecular")   \
  X(FresnelComposite, fresnel_composite, "FresnelComposite") \
  X(ChessTexture, chess_texture, "ChessTexture")      \
  X(WorleyTexture, worley_texture, "WorleyTexture")   \
  X(PerlinTexture, perlin_texture, "PerlinTexture")   \
  X(FormulaTexture, formula_texture, "FormulaTexture") \
  X(FormulaPowTexture, formula_pow_texture, "FormulaPowTexture") \
  X(Textured, textured, "Textured")

namespace pt {

enum class ShapeKind : int {
#define PT_X(e, g, x, l, r, b) e,
  PT_SHAPE_KINDS(PT_X)
#undef PT_X
};
enum class MaterialKind : int {
#define PT_X(e, g, x) e,
  PT_MATERIAL_KINDS(PT_X)
#undef PT_X
};

enum class BvhRole : int { None, Analytic, Triangles, Unbounded };

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
inline constexpr KindInfo kMaterialKinds[] = {
#define PT_X(e, g, x) {#g, x, false, false, BvhRole::None},
    PT_MATERIAL_KINDS(PT_X)
#undef PT_X
};
inline constexpr int kNumShapeKinds = int(sizeof(kShapeKinds) / sizeof(kShapeKinds[0]));
inline constexpr int kNumMaterialKinds = int(sizeof(kMaterialKinds) / sizeof(kMaterialKinds[0]));

// Solid textures: Lambertian surfaces whose albedo (tint, color2, scale) varies in space.
inline constexpr bool is_procedural_texture(MaterialKind k) {
  return k == MaterialKind::ChessTexture || k == MaterialKind::WorleyTexture || k == MaterialKind::PerlinTexture ||
         k == MaterialKind::FormulaTexture || k == MaterialKind::FormulaPowTexture;
}

inline const KindInfo& info(ShapeKind k) { return kShapeKinds[int(k)]; }
inline const KindInfo& info(MaterialKind k) { return kMaterialKinds[int(k)]; }

}  // namespace pt
