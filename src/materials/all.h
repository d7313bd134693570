// Every material kind's stem, and what the list of kinds (materials/kinds.h) makes of
// them: the scene model's parameters (a std::variant in list order, so its index is the
// MaterialKind) and the tables the loader, the packer and the shader generator read.
#pragma once
#include <string_view>
#include <variant>

#include "materials/kinds.h"
// One include per kind, in the list's order.
#include "materials/diffuse.h"
#include "materials/metal.h"
#include "materials/transmit.h"
#include "materials/smooth_dielectric.h"
#include "materials/emit.h"
#include "materials/reflect.h"
#include "materials/phong_specular.h"
#include "materials/fresnel_composite.h"
#include "materials/chess_texture.h"
#include "materials/worley_texture.h"
#include "materials/perlin_texture.h"
#include "materials/formula_texture.h"
#include "materials/formula_pow_texture.h"
#include "materials/textured.h"
#include "materials/metallic_roughness.h"
#include "materials/gltf_pbr.h"
#include "materials/rough_dielectric.h"

namespace pt {

using MaterialParams = KindVariant<
#define PT_X(e, g, x) e,
    PT_MATERIAL_KINDS(PT_X)
#undef PT_X
    ListEnd>;

// The material features (materials/features.h) a material uses: its kind's features().
inline unsigned material_features(const MaterialParams& p) {
  return std::visit([](const auto& k) -> unsigned {
    if constexpr (requires { k.features(); }) return k.features();
    else return 0u;
  }, p);
}

template <class K>
constexpr bool hit_fields_last() {
  bool hit = false;
  for (int i = 0; i < K::kNumFields; ++i) {
    if (hit && !K::kFields[i].hit) return false;
    hit |= K::kFields[i].hit;
  }
  return true;
}

// What the rest of the program needs to know of each kind without naming it.
struct MaterialTraits {
  const char* example;  // the stem's kExample
  const KindField* fields;
  int num_fields;
  unsigned needs;       // other kinds whose snippets its GLSL calls
  bool resolves_at_hit;  // defines resolve_hit_<glsl>
  bool composite;        // defines choose_<glsl>
  bool has_children;     // its element wraps further elements
  bool image_maps;       // reads the scene's image maps
  bool emission_at_hit;  // defines emission_hit_<glsl>
  bool cuts_hits;        // defines hit_present_<glsl>
  bool medium;           // defines medium_<glsl> (kMedium)
  // An element of the kind that loses no energy: in a white furnace it returns exactly 1
  // (the stem's kFurnace; nullptr for the kinds that absorb or, like single-scattering
  // GGX, lose energy). The furnace test loops over them.
  const char* furnace;
};

inline constexpr MaterialTraits kMaterialTraits[] = {
#define PT_X(e, g, x) {e::kExample, e::kFields, e::kNumFields, KindNeeds<e>::value, KindResolvesAtHit<e>::value, KindComposite<e>::value, KindHasChildren<e>::value, \
   KindImageMaps<e>::value, KindEmissionAtHit<e>::value, KindCutsHits<e>::value, KindMedium<e>::value, KindFurnace<e>::value},
    PT_MATERIAL_KINDS(PT_X)
#undef PT_X
};

#define PT_X(e, g, x)                                                                                     \
  static_assert(std::variant_alternative_t<int(MaterialKind::e), MaterialParams>::kXml == std::string_view(x)); \
  static_assert(stored_width<e>() <= material_rec::kPayloadSlots, #e ": more stored fields than payload slots"); \
  static_assert(kind_slot(e::kFields, e::kNumFields) <= material_rec::kGlslSlots, #e ": more fields than GLSL slots"); \
  static_assert(hit_fields_last<e>(), #e ": hit fields come after the stored ones");
PT_MATERIAL_KINDS(PT_X)
#undef PT_X

}  // namespace pt
