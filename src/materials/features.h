// Parts of the generated program that only some materials of a kind need, beyond the
// kinds themselves (which compile per kind: shadergen/shadergen.h Features::materials).
// A kind's params report the ones a material uses with `unsigned features() const`
// (bits of feature_bit); the generator defines HAS_<NAME> for each present, and includes
// the feature's own GLSL snippet where it has one (a lobe of the glTF BSDF: the program
// of a scene without it has none of its text).
//   X(Enum, "NAME", "snippet.glsl" or nullptr)
#pragma once

#define PT_MATERIAL_FEATURES(X)                                                            \
  X(HitCuts, "HIT_CUTS", nullptr)          /* some hits are not surfaces: alpha, culled back faces */ \
  X(EmissionMaps, "EMISSION_MAPS", nullptr) /* emission read from an image map at the hit */        \
  X(GltfSpecular, "GLTF_SPECULAR", nullptr) /* KHR_materials_specular: coloured F0, F90 weight */   \
  X(GltfClearcoat, "GLTF_CLEARCOAT", "materials/gltf_clearcoat.glsl") /* KHR_materials_clearcoat */ \
  X(GltfSheen, "GLTF_SHEEN", "materials/gltf_sheen.glsl")   /* KHR_materials_sheen */       \
  X(GltfTransmission, "GLTF_TRANSMISSION", nullptr) /* KHR_materials_transmission, thin-walled */ \
  X(GltfMs, "GLTF_MS", "materials/gltf_ms.glsl") /* multiple-scattering compensation (every glTF material; off: --gltf-ms off) */ \
  X(Media, "MEDIA", nullptr) /* an absorbing medium inside a closed surface: the path tracks it (integrator.glsl) */ \
  X(GltfVolume, "GLTF_VOLUME", "ggx_dielectric.glsl") /* KHR_materials_volume: the transmission refracts into a volume */

namespace pt {

enum class MaterialFeature : int {
#define PT_X(e, n, g) e,
  PT_MATERIAL_FEATURES(PT_X)
#undef PT_X
};

inline constexpr const char* kMaterialFeatureNames[] = {
#define PT_X(e, n, g) n,
    PT_MATERIAL_FEATURES(PT_X)
#undef PT_X
};
inline constexpr const char* kMaterialFeatureSnippets[] = {
#define PT_X(e, n, g) g,
    PT_MATERIAL_FEATURES(PT_X)
#undef PT_X
};
inline constexpr int kNumMaterialFeatures = int(sizeof(kMaterialFeatureNames) / sizeof(kMaterialFeatureNames[0]));
inline constexpr unsigned feature_bit(MaterialFeature f) { return 1u << int(f); }

}  // namespace pt
