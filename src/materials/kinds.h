// The one list of material kinds. A kind is one stem: materials/<glsl>.h (its parameters
// with the XML's names, strict parse, record fields, packing, panel fields, the model's
// comment) beside materials/<glsl>.glsl (its BSDF). Adding a kind = its stem + one line
// here + its #include in materials/all.h (+ its test). Everything that depends on kinds
// iterates this list: the XML dispatch, the scene model (a std::variant), the packing,
// the shader generator, the selection panel, the fuzz dictionary and the tests.
//
//   X(Type, glsl_name, "XmlElement")
//
// Attenuate is not a kind: it multiplies the tint of the material it wraps (any depth of
// nesting). Absorb is the inner half of Emit, and Emit around another material only adds
// emission to it; neither has a kind of its own.
#pragma once

#define PT_MATERIAL_KINDS(X)                                 \
  X(Diffuse, diffuse, "Diffuse")                             \
  X(Metal, metal, "Metal")                                   \
  X(Transmit, transmit, "Transmit")                          \
  X(SmoothDielectric, smooth_dielectric, "SmoothDielectric") \
  X(Emit, emit, "Emit")                                      \
  X(Reflect, reflect, "Reflect")                             \
  X(PhongSpecular, phong_specular, "PhongSpecular")          \
  X(FresnelComposite, fresnel_composite, "FresnelComposite") \
  X(ChessTexture, chess_texture, "ChessTexture")             \
  X(WorleyTexture, worley_texture, "WorleyTexture")          \
  X(PerlinTexture, perlin_texture, "PerlinTexture")          \
  X(FormulaTexture, formula_texture, "FormulaTexture")       \
  X(FormulaPowTexture, formula_pow_texture, "FormulaPowTexture") \
  X(Textured, textured, "Textured")                          \
  X(MetallicRoughness, metallic_roughness, "MetallicRoughness") \
  X(GltfPbr, gltf_pbr, "GltfPbr")                            \
  X(RoughDielectric, rough_dielectric, "RoughDielectric")

namespace pt {

enum class MaterialKind : int {
#define PT_X(e, g, x) e,
  PT_MATERIAL_KINDS(PT_X)
#undef PT_X
};

struct MaterialKindInfo {
  const char* glsl;  // snippet and function suffix: materials/metal.glsl, eval_metal
  const char* xml;   // element name in scene files
  const char* type;  // the C++ type, also its GLSL record struct: <Type>Rec
};

inline constexpr MaterialKindInfo kMaterialKinds[] = {
#define PT_X(e, g, x) {#g, x, #e},
    PT_MATERIAL_KINDS(PT_X)
#undef PT_X
};
inline constexpr int kNumMaterialKinds = int(sizeof(kMaterialKinds) / sizeof(kMaterialKinds[0]));

inline constexpr const MaterialKindInfo& info(MaterialKind k) { return kMaterialKinds[int(k)]; }
inline constexpr unsigned kind_bit(MaterialKind k) { return 1u << int(k); }

}  // namespace pt
