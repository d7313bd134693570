// Textured: <Textured diffuse="wood.png" specular="wood_spec.png" normal="wood_n.png"
// n="50" uvScale="su sv" uvOffset="ou ov"/>: the seed's image-mapped material
// ("Texturado": diffuse, specular and normal maps). At uv' = uv * uvScale + uvOffset,
// with rho = tint * diffuse(uv') and s = specular(uv'):
//     f = (1 - s) rho / pi  +  s (n + 2) / (2 pi) cos^n(alpha)
// a Lambert lobe and the normalised Phong lobe of PhongSpecular mixed per channel, in
// the shading frame of the normal map (textured.glsl, textured_resolve.glsl). The maps
// are indices in the scene's image list (-1: none), decoded by scene/textured_loader.h:
// colour maps sRGB to linear, normal maps onto [-1, 1].
#pragma once
#include "materials/material.h"

namespace pt {

struct Textured {
  static constexpr const char* kXml = "Textured";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<Textured diffuse=\"wood_diffuse.png\" specular=\"wood_specular.png\" normal=\"wood_normal.png\" n=\"10\"/>";
  int diffuse = -1, specular = -1, normal = -1;
  float n = 50.0f;  // the Phong lobe's exponent
  glm::vec2 uvScale{1.0f}, uvOffset{0.0f};

  // Stored: the maps' layers and the uv transform; at the hit (resolve_hit_textured) the
  // specular weight s of the point.
#define PT_TEXTURED_FIELDS(F) \
  F(int, map_diffuse) F(int, map_specular) F(int, map_normal) F(float, exponent) F(vec2, uv_scale) F(vec2, uv_offset)
#define PT_TEXTURED_HIT_FIELDS(F) F(vec3, spec)
  PT_KIND_RECORD(PT_TEXTURED_FIELDS, PT_TEXTURED_HIT_FIELDS)
  static constexpr unsigned kNeeds = kind_bit(MaterialKind::Diffuse) | kind_bit(MaterialKind::PhongSpecular);  // its lobes
  static constexpr bool kResolvesAtHit = true;
  static constexpr bool kImageMaps = true;

  void parse(MaterialParse& p) {
    XmlAttrs& a = p.attrs;
    diffuse = p.loader.image_map(a, "diffuse", false);
    specular = p.loader.image_map(a, "specular", false);
    normal = p.loader.image_map(a, "normal", true);
    n = a.number("n", 50.0f);
    // As PhongSpecular's n (phong_specular.h says why 1e5).
    if (!(n >= 0.0f) || n > 1e5f) a.fail("'n' must be in [0, 100000]");
    uvScale = a.has("uvScale") ? a.vec2("uvScale") : glm::vec2(1.0f);
    uvOffset = a.has("uvOffset") ? a.vec2("uvOffset") : glm::vec2(0.0f);
  }
  void pack(MaterialWriter& w) const {
    w.set(rec::map_diffuse, diffuse);
    w.set(rec::map_specular, specular);
    w.set(rec::map_normal, normal);
    w.set(rec::exponent, n);
    w.set(rec::uv_scale, uvScale);
    w.set(rec::uv_offset, uvOffset);
  }
  template <class E>
  bool edit(E& e, MaterialCommon& c) { return e.color("colour", c.tint); }
};

}  // namespace pt
