// PerlinTexture: a procedural (solid) texture (solid_texture.h); its pattern and the
// source of the formula in perlin_texture.glsl.
// Default colours: color1 0.9 grey, color2 0.1 grey.
#pragma once
#include "materials/solid_texture.h"

namespace pt {

struct PerlinTexture : SolidTexture {
  static constexpr const char* kXml = "PerlinTexture";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<PerlinTexture color1=\"1 1 1\" color2=\"0.2 0.3 0.4\" scale=\"0.5\"/>";
  void parse(MaterialParse& p) { parse_texture(p, glm::vec3(0.9f), glm::vec3(0.1f)); }
};

}  // namespace pt
