// What the procedural (solid) textures share: <ChessTexture color1=".." color2=".."
// scale="s"/> and the same attributes for Worley, Perlin, Formula and FormulaPow. Each is
// a Lambertian surface whose albedo varies in space (3D, so no uv mapping is needed): at
// the hit it becomes a Diffuse record of albedo mix(color1, color2, pattern(p / scale))
// (resolve_hit_<kind> in its GLSL, texture_common.glsl), so it shades, light-samples and
// passes the furnace exactly as Diffuse does.
#pragma once
#include "materials/material.h"

namespace pt {

struct SolidTexture {
  glm::vec3 color1{1.0f}, color2{0.0f};
  float scale = 10.0f;  // feature size in scene units

#define PT_SOLID_TEXTURE_FIELDS(F) F(vec3, color2) F(float, scale)
  PT_KIND_RECORD(PT_SOLID_TEXTURE_FIELDS, PT_NO_FIELDS)
  static constexpr unsigned kNeeds = kind_bit(MaterialKind::Diffuse);  // it shades as Diffuse
  static constexpr bool kResolvesAtHit = true;

  // The kind's default colours; colours (with the enclosing tint) must be in [0, 1].
  void parse_texture(MaterialParse& p, glm::vec3 c1, glm::vec3 c2) {
    XmlAttrs& a = p.attrs;
    color1 = a.vec3("color1", c1);
    color2 = a.vec3("color2", c2);
    scale = a.number("scale", 10.0f);
    if (!(scale > 0.0f)) a.fail("'scale' must be positive");
    const glm::vec3 first = p.common.tint * color1;
    const glm::vec3 lo = glm::min(first, color2), hi = glm::max(first, color2);
    if (glm::any(glm::lessThan(lo, glm::vec3(0.0f))) || glm::any(glm::greaterThan(hi, glm::vec3(1.0f))))
      a.fail("colours must be in [0, 1]");
  }
  void pack(MaterialWriter& w) const {
    w.tint *= color1;
    w.set(rec::color2, color2);
    w.set(rec::scale, scale);
  }
  template <class E>
  bool edit(E& e, MaterialCommon&) { return any_changed({e.color("colour", color1), e.color("colour 2", color2)}); }
};

}  // namespace pt
