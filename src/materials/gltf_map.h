// A glTF textureInfo as the shader reads it (GltfPbr's maps, materials/gltf_pbr.h): which
// image layer, which uv set (TEXCOORD_0 or _1), the sampler's wrap modes and filter, the
// KHR_texture_transform as an affine map of uv, and the map's strength (the normal map's
// `scale`). One record per map in the scene's texinfo records (four per material, in
// material order; render/image_maps.h pack_texinfos), laid out like core/records.h's.
#pragma once
#include <cmath>

#include <glm/glm.hpp>

#include "core/records.h"

// row0, row1: u' = dot(row0, (u, v, 1)), v' = dot(row1, (u, v, 1)) in our uv (v up);
// code: -1 without a map, else layer * 64 + nearest * 32 + texCoord * 16 + wrapS * 4 + wrapT.
#define PT_TEXINFO_RECORD(F) \
  F(vec3, row0, 0, 0) F(float, code, 0, 3) \
  F(vec3, row1, 1, 0) F(float, strength, 1, 3)

namespace pt {

// Texinfo records per material (a kind with maps writes its own over them: GltfPbr's
// base colour, metallic-roughness, normal and emissive maps, its extensions' maps and a
// record of their colour factors: materials/gltf_pbr.h), so material m's are at
// m * kTexinfosPerMaterial.
inline constexpr int kTexinfosPerMaterial = 14;

namespace texinfo_rec {
inline constexpr int kTexels = 2;
PT_TEXINFO_RECORD(PT_FIELD_CONST)
}  // namespace texinfo_rec

inline const RecordLayout& texinfo_layout() {
  using namespace texinfo_rec;
#define PT_TEXINFO_FIELD(t, n, tex, comp) n,
  static const RecordLayout l{"texinfo", kTexels, {PT_TEXINFO_RECORD(PT_TEXINFO_FIELD)}, {}};
#undef PT_TEXINFO_FIELD
  return l;
}

// glTF sampler wrap modes, in the order of the shader's codes (gltf_pbr.glsl).
enum GltfWrap : int { kWrapRepeat = 0, kWrapClamp = 1, kWrapMirror = 2 };

struct GltfMap {
  int image = -1;      // index in the scene's image list (its layer); -1: no map
  int tex_coord = 0;   // TEXCOORD_<n> (after KHR_texture_transform's texCoord override)
  int wrap_s = kWrapRepeat, wrap_t = kWrapRepeat;
  bool nearest = false;  // magnification filter NEAREST (else LINEAR)
  // KHR_texture_transform, in glTF's uv (v down): uv' = T(offset) R(rotation) S(scale) uv.
  glm::vec2 offset{0.0f}, scale{1.0f};
  float rotation = 0.0f;
  float strength = 1.0f;  // normalTexture.scale; an extension's scalar factor (gltf_pbr.h)

  // The transform in our uv (v up, v_ours = 1 - v_gltf): flip, transform, flip back.
  void rows(glm::vec3& r0, glm::vec3& r1) const {
    const float c = std::cos(rotation), s = std::sin(rotation);
    // glTF: u' = c sx u - s sy v + ox, v' = s sx u + c sy v + oy (the extension's GLSL).
    const glm::vec3 g0(c * scale.x, -s * scale.y, offset.x), g1(s * scale.x, c * scale.y, offset.y);
    // With v_g = 1 - v: u' = g0.x u - g0.y v + (g0.y + g0.z); v_ours' = 1 - (g1.x u - g1.y v + g1.y + g1.z).
    r0 = glm::vec3(g0.x, -g0.y, g0.y + g0.z);
    r1 = glm::vec3(-g1.x, g1.y, 1.0f - g1.y - g1.z);
  }
  void pack(RecordBuffer& b, int rec) const {
    glm::vec3 r0, r1;
    rows(r0, r1);
    b.set(rec, texinfo_rec::row0, r0);
    b.set(rec, texinfo_rec::row1, r1);
    b.set(rec, texinfo_rec::code, image < 0 ? -1.0f : float(image * 64 + (nearest ? 32 : 0) + tex_coord * 16 + wrap_s * 4 + wrap_t));
    b.set(rec, texinfo_rec::strength, strength);
  }
};

}  // namespace pt
