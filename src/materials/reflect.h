// Reflect: <Reflect color="r g b"/>: a perfect mirror (the seed's "Reflectivo"), a delta
// lobe of weight tint (reflect.glsl).
#pragma once
#include "materials/material.h"

namespace pt {

struct Reflect {
  static constexpr const char* kXml = "Reflect";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<Reflect/>";
  static constexpr const char* kFurnace = "<Reflect/>";
  glm::vec3 color{1.0f};
  PT_KIND_RECORD(PT_NO_FIELDS, PT_NO_FIELDS)
  void parse(MaterialParse& p) { color = p.attrs.vec3("color", glm::vec3(1.0f)); }
  void pack(MaterialWriter& w) const { w.tint *= color; }
  template <class E>
  bool edit(E& e, MaterialCommon&) { return e.color("colour", color); }
};

}  // namespace pt
