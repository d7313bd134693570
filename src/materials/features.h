// Parts of the generated program that only some materials of a kind need, beyond the
// kinds themselves (which compile per kind: shadergen/shadergen.h Features::materials).
// A kind's params report the ones a material uses with `unsigned features() const`
// (bits of feature_bit); the generator defines HAS_<NAME> for each present.
//   X(Enum, "NAME")
#pragma once

#define PT_MATERIAL_FEATURES(X)                                                            \
  X(HitCuts, "HIT_CUTS")          /* some hits are not surfaces: alpha, culled back faces */ \
  X(EmissionMaps, "EMISSION_MAPS") /* emission read from an image map at the hit */

namespace pt {

enum class MaterialFeature : int {
#define PT_X(e, n) e,
  PT_MATERIAL_FEATURES(PT_X)
#undef PT_X
};

inline constexpr const char* kMaterialFeatureNames[] = {
#define PT_X(e, n) n,
    PT_MATERIAL_FEATURES(PT_X)
#undef PT_X
};
inline constexpr int kNumMaterialFeatures = int(sizeof(kMaterialFeatureNames) / sizeof(kMaterialFeatureNames[0]));
inline constexpr unsigned feature_bit(MaterialFeature f) { return 1u << int(f); }

}  // namespace pt
