// FormulaTexture: a procedural (solid) texture (solid_texture.h); its pattern and the
// source of the formula in formula_texture.glsl.
// Default colours: color1 white, color2 black.
#pragma once
#include "materials/solid_texture.h"

namespace pt {

struct FormulaTexture : SolidTexture {
  static constexpr const char* kXml = "FormulaTexture";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<FormulaTexture color1=\"1 1 1\" color2=\"0.2 0.3 0.4\" scale=\"0.5\"/>";
  void parse(MaterialParse& p) { parse_texture(p, glm::vec3(1.0f), glm::vec3(0.0f)); }
};

}  // namespace pt
