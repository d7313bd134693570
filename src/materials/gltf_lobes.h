// The glTF BSDF's extension lobes (docs/gltf.md), shared by MetallicRoughness (uniform) and
// GltfPbr (per texel, which resolves into a MetallicRoughness record at the hit):
//  - KHR_materials_specular: the dielectric's F0 colour min(f0(ior) specularColor, 1) and
//    its weight `specular` (the extension's fresnel_mix: base (1 - specular max(F)),
//    layer specular F, F = F0 + (1 - F0) (1 - v.h)^5); the metal is unchanged;
//  - KHR_materials_clearcoat: a GGX layer of ior 1.5 (f0 0.04) with its own roughness and
//    normal, over the rest: mix(base, coat, clearcoat F_cc(n_c.v)) (the extension's
//    fresnel_coat);
//  - KHR_materials_sheen: the Charlie lobe of colour sheenColor and roughness sheenRoughness
//    over the base, which is scaled by 1 - max(sheenColor) E(cos) (the extension's
//    albedo scaling, E tabulated at build time: tools/gen_sheen_lut.py);
//  - KHR_materials_transmission, thin-walled (no KHR_materials_volume): the dielectric's
//    diffuse base becomes mix(diffuse, specular_btdf, transmission), the BTDF the GGX lobe
//    mirrored through the surface (a thin sheet: no bending), tinted by the base colour.
// Two unit numbers share a record slot (12 bits each: gltf_pack2, exact in a float), so
// all the lobes fit one material record.
#pragma once
#include <cmath>

#include <glm/glm.hpp>

#include "core/xml_attrs.h"
#include "materials/features.h"

namespace pt {

// Two numbers in [0, 1] as one float: 12 bits each, an integer below 2^24 (exact);
// the shader's gltf_unpack2 (metallic_roughness.glsl) inverts it.
inline float gltf_pack2(float a, float b) {
  auto q = [](float v) { return std::floor(glm::clamp(v, 0.0f, 1.0f) * 4095.0f + 0.5f); };
  return q(a) + 4096.0f * q(b);
}

struct GltfLobes {
  float specular = 1.0f;            // KHR_materials_specular: specularFactor
  glm::vec3 specularColor{1.0f};    //   specularColorFactor (may exceed 1; F0 is clamped)
  float clearcoat = 0.0f;           // KHR_materials_clearcoat: clearcoatFactor
  float clearcoatRoughness = 0.0f;  //   clearcoatRoughnessFactor
  glm::vec3 sheenColor{0.0f};       // KHR_materials_sheen: sheenColorFactor
  float sheenRoughness = 0.0f;      //   sheenRoughnessFactor
  float transmission = 0.0f;        // KHR_materials_transmission: transmissionFactor (GltfPbr only)

  // The lobes a material uses (materials/features.h): each is compiled in only then.
  unsigned features(bool specular_map = false) const {
    unsigned f = feature_bit(MaterialFeature::GltfMs);  // every glTF material: the compensation (the renderer may drop it)
    if (transmission > 0.0f) f |= feature_bit(MaterialFeature::GltfTransmission);
    if (specular != 1.0f || specularColor != glm::vec3(1.0f) || specular_map) f |= feature_bit(MaterialFeature::GltfSpecular);
    if (clearcoat > 0.0f) f |= feature_bit(MaterialFeature::GltfClearcoat);
    if (glm::any(glm::greaterThan(sheenColor, glm::vec3(0.0f)))) f |= feature_bit(MaterialFeature::GltfSheen);
    return f;
  }
  // The XML's attributes (MetallicRoughness, GltfPbr): specular="1" specularColor="1 1 1"
  // clearcoat="0" clearcoatRoughness="0" sheenColor="0 0 0" sheenRoughness="0".
  void parse(XmlAttrs& a) {
    auto unit = [&](float v, const char* what) {
      if (!(v >= 0.0f && v <= 1.0f)) a.fail(std::string("'") + what + "' must be in [0, 1]");
      return v;
    };
    specular = unit(a.number("specular", 1.0f), "specular");
    specularColor = a.vec3("specularColor", glm::vec3(1.0f));
    for (int c = 0; c < 3; ++c)
      if (!(specularColor[c] >= 0.0f && specularColor[c] <= 1e3f)) a.fail("'specularColor' must be in [0, 1000]");
    clearcoat = unit(a.number("clearcoat", 0.0f), "clearcoat");
    clearcoatRoughness = unit(a.number("clearcoatRoughness", 0.0f), "clearcoatRoughness");
    sheenColor = a.vec3("sheenColor", glm::vec3(0.0f));
    for (int c = 0; c < 3; ++c) unit(sheenColor[c], "sheenColor");
    sheenRoughness = unit(a.number("sheenRoughness", 0.0f), "sheenRoughness");
  }
  // The dielectric's F0 colour for f0 = ((ior - 1) / (ior + 1))^2 (KHR_materials_specular).
  glm::vec3 f0(float f0_ior) const { return glm::min(f0_ior * specularColor, glm::vec3(1.0f)); }
};

}  // namespace pt
