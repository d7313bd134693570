// Diffuse: <Diffuse/>. Lambertian, albedo = the tint of the enclosing <Attenuate>
// elements (1 without). SceneLevel's dotWeight picks cosine-weighted (true) or uniform
// hemisphere sampling; both exact (diffuse.glsl). The seed's "Difuso".
#pragma once
#include "materials/material.h"

namespace pt {

struct Diffuse {
  static constexpr const char* kXml = "Diffuse";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<Attenuate color=\"0.9 0.8 0.7\"><Diffuse/></Attenuate>";
  static constexpr const char* kFurnace = "<Diffuse/>";  // albedo 1
  PT_KIND_RECORD(PT_NO_FIELDS, PT_NO_FIELDS)
  void parse(MaterialParse&) {}
  void pack(MaterialWriter&) const {}
  template <class E>
  bool edit(E& e, MaterialCommon& c) { return e.color("colour", c.tint); }
};

}  // namespace pt
