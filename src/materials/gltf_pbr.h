// GltfPbr: a glTF 2.0 metallic-roughness material with its maps (docs/gltf.md). It reads
// its maps at the hit and becomes a MetallicRoughness record there (the glTF BSDF of
// Appendix B, materials/metallic_roughness.h), as Textured becomes Diffuse + Phong:
//     baseColor = baseColorFactor * baseColorTexture (sRGB) * COLOR_0       (rgb; alpha too)
//     roughness = roughnessFactor * metallicRoughnessTexture.g              (linear)
//     metallic  = metallicFactor  * metallicRoughnessTexture.b              (linear)
//     normal    = normalTexture (tangent space, xy times its `scale`)
//     emission  = emissiveFactor * emissiveStrength * emissiveTexture (sRGB)
// Each map has its own uv set (TEXCOORD_0/1), sampler (wrap, filter) and
// KHR_texture_transform (materials/gltf_map.h). alphaMode MASK keeps a hit where alpha >=
// alphaCutoff, BLEND keeps it with probability alpha (a ray passes with probability
// 1 - alpha, shadow rays too); a single-sided material's back faces are culled for every
// ray (docs/gltf.md says why). Both are decided by the traversal (kCutsHits), on mesh
// triangles. The glTF loader fills it (scene/xml_meshes.cpp gltf_material); in XML:
// <GltfPbr baseColor="r g b" alpha="a" metallic="m" roughness="r" ior="1.5"
//  emissive="r g b" baseColorMap="c.png" metallicRoughnessMap="mr.png" normalMap="n.png"
//  normalScale="1" emissiveMap="e.png" alphaMode="OPAQUE|MASK|BLEND" alphaCutoff="0.5"
//  doubleSided="true|false"/> with TEXCOORD_0's maps, repeat and linear filtering, and the
// extension lobes' factors (materials/gltf_lobes.h: specular, specularColor, clearcoat,
// clearcoatRoughness, sheenColor, sheenRoughness; their maps come from glTF files only).
// Extensions (docs/gltf.md): KHR_materials_specular (specularTexture A, specularColorTexture
// RGB sRGB), _clearcoat (clearcoatTexture R, clearcoatRoughnessTexture G, its own
// clearcoatNormalTexture; without it the coat has the surface's normal before the base's
// normal map), _sheen (sheenColorTexture RGB sRGB, sheenRoughnessTexture A),
// _transmission (transmission="t"; transmissionTexture R): thin-walled, or with
// KHR_materials_volume (volume="true"; attenuationColor="r g b" attenuationDistance="d",
// materials/medium.h) the transmission refracts into the volume that the mesh bounds, of
// index `ior` (the BSDF: metallic_roughness.glsl), and a path inside keeps exp(-sigma t).
#pragma once
#include <string>

#include "materials/gltf_lobes.h"
#include "materials/gltf_map.h"
#include "materials/material.h"
#include "materials/medium.h"

namespace pt {

struct GltfPbr {
  static constexpr const char* kXml = "GltfPbr";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample =
      "<GltfPbr baseColor=\"0.8 0.6 0.3\" metallic=\"0.3\" roughness=\"0.5\" baseColorMap=\"wood_diffuse.png\" doubleSided=\"true\"/>";
  enum AlphaMode : int { kOpaque = 0, kMask = 1, kBlend = 2 };
  glm::vec3 baseColor{1.0f};
  float alpha = 1.0f;  // baseColorFactor's alpha
  float metallic = 1.0f, roughness = 1.0f;  // glTF's defaults
  float ior = 1.5f;    // KHR_materials_ior; 0: the Fresnel term is 1 (f0 = 1)
  int alphaMode = kOpaque;
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
  GltfMap base, metal_rough, normal, emissive;  // emission's factor is MaterialCommon's
  GltfLobes lobes;  // the extensions' factors
  GltfMap specular, specular_color, clearcoat, clearcoat_roughness, clearcoat_normal, sheen_color, sheen_roughness, transmission;
  bool volume = false;         // KHR_materials_volume (thicknessFactor > 0): not thin-walled
  glm::vec3 sigma{0.0f};       // its absorption per unit length (materials/medium.h)
  // The texinfo records of a material, from m * kTexinfosPerMaterial (gltf_pbr_resolve.glsl
  // reads them by these offsets); kFactors holds the colour factors (row0: specularColor,
  // row1: sheenColor), the scalar ones are their maps' `strength`; kVolume's row0 is the
  // volume's absorption sigma (no map: thickness is not used, docs/gltf.md).
  enum Texinfo : int { kBase, kMetalRough, kNormal, kEmissive, kSpecular, kSpecularColor, kClearcoat, kClearcoatRoughness,
                       kClearcoatNormal, kSheenColor, kSheenRoughness, kFactors, kTransmission, kVolume, kNumTexinfos };
  static_assert(kNumTexinfos <= kTexinfosPerMaterial);

  // Stored: the first texinfo record, the factors, f0, the alpha cutoff (< 0: BLEND),
  // sidedness and the volume's index of refraction (0: thin-walled); at the hit it becomes a
  // MetallicRoughness record (gltf_pbr.glsl).
#define PT_GLTF_PBR_FIELDS(F) \
  F(int, maps) F(float, metallic) F(float, roughness) F(float, f0) F(float, alpha) F(float, cutoff) F(float, two_sided) F(float, volume)
  PT_KIND_RECORD(PT_GLTF_PBR_FIELDS, PT_NO_FIELDS)
  static constexpr unsigned kNeeds = kind_bit(MaterialKind::MetallicRoughness);  // what it becomes at the hit
  static constexpr bool kResolvesAtHit = true;
  static constexpr bool kImageMaps = true;
  static constexpr bool kEmissionAtHit = true;
  static constexpr bool kCutsHits = true;
  static constexpr bool kMedium = true;  // with a volume (medium_gltf_pbr)

  // The volume's index (0: none): a volume needs transmission, and an ior of at least 1
  // (ior 0, f0 = 1, reflects everything: nothing enters).
  float volume_ior() const { return volume && lobes.transmission > 0.0f && ior >= 1.0f ? ior : 0.0f; }
  unsigned features() const {
    return (alphaMode != kOpaque || !doubleSided ? feature_bit(MaterialFeature::HitCuts) : 0u) |
           (emissive.image >= 0 ? feature_bit(MaterialFeature::EmissionMaps) : 0u) |
           lobes.features(specular.image >= 0 || specular_color.image >= 0) |
           (volume_ior() > 0.0f ? feature_bit(MaterialFeature::GltfVolume) | medium_features(sigma) : 0u);
  }

  void parse(MaterialParse& p) {
    XmlAttrs& a = p.attrs;
    auto unit = [&](float v, const char* what) {
      if (!(v >= 0.0f && v <= 1.0f)) a.fail(std::string("'") + what + "' must be in [0, 1]");
      return v;
    };
    baseColor = a.vec3("baseColor", glm::vec3(1.0f));
    for (int c = 0; c < 3; ++c) unit(baseColor[c], "baseColor");
    alpha = unit(a.number("alpha", 1.0f), "alpha");
    metallic = unit(a.number("metallic", 1.0f), "metallic");
    roughness = unit(a.number("roughness", 1.0f), "roughness");
    ior = a.number("ior", 1.5f);
    if (!(ior == 0.0f || (ior >= 1.0f && ior <= 100.0f))) a.fail("'ior' must be 0 or in [1, 100] (KHR_materials_ior)");
    const glm::vec3 e = a.vec3("emissive", glm::vec3(0.0f));
    if (!(glm::all(glm::greaterThanEqual(e, glm::vec3(0.0f))) && glm::all(glm::lessThanEqual(e, glm::vec3(1e6f)))))
      a.fail("'emissive' must be in [0, 1e6]");
    p.common.emission += e;
    base.image = p.loader.image_map(a, "baseColorMap", false);
    metal_rough.image = p.loader.image_map_linear(a, "metallicRoughnessMap");
    normal.image = p.loader.image_map(a, "normalMap", true);
    normal.strength = a.number("normalScale", 1.0f);
    if (!(std::abs(normal.strength) <= 100.0f)) a.fail("'normalScale' must be in [-100, 100]");
    emissive.image = p.loader.image_map(a, "emissiveMap", false);
    const std::string mode = a.has("alphaMode") ? a.text("alphaMode") : "OPAQUE";
    if (mode == "OPAQUE") alphaMode = kOpaque;
    else if (mode == "MASK") alphaMode = kMask;
    else if (mode == "BLEND") alphaMode = kBlend;
    else a.fail("'alphaMode' must be OPAQUE, MASK or BLEND");
    alphaCutoff = unit(a.number("alphaCutoff", 0.5f), "alphaCutoff");
    doubleSided = a.boolean("doubleSided", false);
    lobes.parse(a);
    lobes.transmission = unit(a.number("transmission", 0.0f), "transmission");
    volume = a.boolean("volume", false);
    sigma = parse_medium(a);
    if (!volume && (a.has("attenuationColor") || a.has("attenuationDistance")))
      a.fail("'attenuationColor' and 'attenuationDistance' need volume=\"true\" (KHR_materials_volume)");
  }
  void pack(MaterialWriter& w) const {
    w.tint *= baseColor;
    w.set(rec::maps, w.record() * kTexinfosPerMaterial);
    w.set(rec::metallic, metallic);
    w.set(rec::roughness, roughness);
    const float r = (ior - 1.0f) / (ior + 1.0f);
    w.set(rec::f0, r * r);
    w.set(rec::alpha, alpha);
    // OPAQUE is a mask that keeps every alpha (>= 0); BLEND is coded as -1.
    w.set(rec::cutoff, alphaMode == kBlend ? -1.0f : alphaMode == kMask ? alphaCutoff : 0.0f);
    w.set(rec::two_sided, doubleSided ? 1.0f : 0.0f);
    w.set(rec::volume, volume_ior());
  }
  // Its texinfo records: material m's are from m * kTexinfosPerMaterial (render/image_maps.h).
  void pack_texinfos(RecordBuffer& b, int first) const {
    base.pack(b, first + kBase);
    metal_rough.pack(b, first + kMetalRough);
    normal.pack(b, first + kNormal);
    emissive.pack(b, first + kEmissive);
    auto with = [](GltfMap m, float factor) {
      m.strength = factor;
      return m;
    };
    with(specular, lobes.specular).pack(b, first + kSpecular);
    specular_color.pack(b, first + kSpecularColor);
    with(clearcoat, lobes.clearcoat).pack(b, first + kClearcoat);
    with(clearcoat_roughness, lobes.clearcoatRoughness).pack(b, first + kClearcoatRoughness);
    clearcoat_normal.pack(b, first + kClearcoatNormal);
    sheen_color.pack(b, first + kSheenColor);
    with(sheen_roughness, lobes.sheenRoughness).pack(b, first + kSheenRoughness);
    b.set(first + kFactors, texinfo_rec::row0, lobes.specularColor);
    b.set(first + kFactors, texinfo_rec::row1, lobes.sheenColor);
    b.set(first + kFactors, texinfo_rec::code, -1.0f);
    with(transmission, lobes.transmission).pack(b, first + kTransmission);
    b.set(first + kVolume, texinfo_rec::row0, sigma);
    b.set(first + kVolume, texinfo_rec::code, -1.0f);
  }
  template <class E>
  bool edit(E& e, MaterialCommon&) {
    return any_changed({e.color("base colour", baseColor), e.slider("metallic", metallic, 0.0f, 1.0f),
                        e.slider("roughness", roughness, 0.0f, 1.0f), e.slider("ior", ior, 1.0f, 3.0f)});
  }
};

}  // namespace pt
