// MetallicRoughness: <MetallicRoughness baseColor="r g b" metallic="m" roughness="r"
// ior="1.5"/>: the glTF 2.0 metallic-roughness BSDF as the specification's Appendix B
// defines it (glTF 2.0, "Appendix B: BRDF Implementation"):
//     material   = mix(dielectric, metal, metallic)
//     metal      = conductor_fresnel(f0 = baseColor, specular(alpha = roughness^2))
//     dielectric = fresnel_mix(ior, base = baseColor / pi, layer = specular(alpha))
// with Schlick's Fresnel F = f0 + (1 - f0)(1 - |v.h|)^5 (dielectric f0 = ((ior - 1) /
// (ior + 1))^2) and the GGX specular lobe D G2 / (4 |n.l| |n.v|), G2 Smith's height-
// correlated masking-shadowing (Heitz 2014; the Khronos sample viewer's V_GGX). Defaults
// are glTF's: metallic 1, roughness 1, ior 1.5. Below roughness 0.03 (alpha < 1e-3) the
// specular lobe is a mirror (a delta lobe). metallic_roughness.glsl has the sampling.
// The extension lobes (materials/gltf_lobes.h: specular, clearcoat, sheen) take the
// attributes specular, specularColor, clearcoat, clearcoatRoughness, sheenColor and
// sheenRoughness; each is compiled into the program only when a material uses it.
#pragma once
#include "materials/gltf_lobes.h"
#include "materials/material.h"

namespace pt {

struct MetallicRoughness {
  static constexpr const char* kXml = "MetallicRoughness";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<MetallicRoughness baseColor=\"0.8 0.6 0.3\" metallic=\"0.5\" roughness=\"0.4\"/>";
  glm::vec3 baseColor{1.0f};
  float metallic = 1.0f, roughness = 1.0f;
  float ior = 1.5f;
  GltfLobes lobes;

  // f0: the dielectric's F0 colour; specular: its weight (F90); coat: clearcoat and its
  // roughness; sheen_rg, sheen_br: the sheen colour and roughness (two per slot:
  // gltf_pack2). Hit field coat_normal: the clearcoat's normal in the shading frame
  // (packed; 0: the shading normal), which GltfPbr sets from its maps; transmission: the
  // KHR_materials_transmission (GltfPbr's; a uniform MetallicRoughness has none), thin-walled
  // unless volume, the index of refraction of KHR_materials_volume's volume, is > 0.
#define PT_METALLIC_ROUGHNESS_FIELDS(F) \
  F(float, metallic) F(float, roughness) F(vec3, f0) F(float, specular) F(float, coat) F(float, sheen_rg) F(float, sheen_br)
#define PT_METALLIC_ROUGHNESS_HIT_FIELDS(F) F(float, coat_normal) F(float, transmission) F(float, volume)
  PT_KIND_RECORD(PT_METALLIC_ROUGHNESS_FIELDS, PT_METALLIC_ROUGHNESS_HIT_FIELDS)

  unsigned features() const { return lobes.features(); }

  void parse(MaterialParse& p) {
    XmlAttrs& a = p.attrs;
    baseColor = a.vec3("baseColor", glm::vec3(1.0f));
    if (glm::any(glm::lessThan(baseColor, glm::vec3(0.0f))) || glm::any(glm::greaterThan(baseColor, glm::vec3(1.0f))))
      a.fail("'baseColor' components must be in [0, 1]");
    metallic = a.number("metallic", 1.0f);
    roughness = a.number("roughness", 1.0f);
    if (metallic < 0.0f || metallic > 1.0f || roughness < 0.0f || roughness > 1.0f) a.fail("'metallic' and 'roughness' must be in [0, 1]");
    ior = parse_ior(a, "ior", 1.5f);
    lobes.parse(a);
  }
  void pack(MaterialWriter& w) const {
    w.tint *= baseColor;
    w.set(rec::metallic, metallic);
    w.set(rec::roughness, roughness);
    const float r = (ior - 1.0f) / (ior + 1.0f);
    w.set(rec::f0, lobes.f0(r * r));
    w.set(rec::specular, lobes.specular);
    w.set(rec::coat, gltf_pack2(lobes.clearcoat, lobes.clearcoatRoughness));
    w.set(rec::sheen_rg, gltf_pack2(lobes.sheenColor.x, lobes.sheenColor.y));
    w.set(rec::sheen_br, gltf_pack2(lobes.sheenColor.z, lobes.sheenRoughness));
  }
  template <class E>
  bool edit(E& e, MaterialCommon&) {
    return any_changed({e.color("base colour", baseColor), e.slider("metallic", metallic, 0.0f, 1.0f),
                        e.slider("roughness", roughness, 0.0f, 1.0f), e.slider("ior", ior, 1.0f, 3.0f)});
  }
};

}  // namespace pt
