// PhongSpecular: <PhongSpecular n="100" color="r g b"/>: the normalised modified Phong
// lobe (Lafortune and Willems 1994), f = tint (n + 2) / (2 pi) cos^n(alpha), energy-
// conserving for tint <= 1 (phong_specular.glsl).
#pragma once
#include "materials/material.h"

namespace pt {

struct PhongSpecular {
  static constexpr const char* kXml = "PhongSpecular";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<PhongSpecular n=\"30\"/>";
  float n = 0.0f;  // the lobe's exponent
  glm::vec3 color{1.0f};

#define PT_PHONG_SPECULAR_FIELDS(F) F(float, exponent)
  PT_KIND_RECORD(PT_PHONG_SPECULAR_FIELDS, PT_NO_FIELDS)

  void parse(MaterialParse& p) {
    n = p.attrs.number("n");
    // Above 1e5 the lobe is too narrow for float: cos^n is evaluated at a cosine rounded
    // to steps of 6e-8 near 1, off by a factor up to exp(3e-8 n) (1.4% at 1e5, 12% at 1e6, 159% at
    // 1e7: reliability_test.cpp), which next-event estimation and MIS read.
    if (!(n >= 0.0f) || n > 1e5f) p.attrs.fail("'n' must be in [0, 100000]");
    color = p.attrs.vec3("color", glm::vec3(1.0f));
  }
  void pack(MaterialWriter& w) const {
    w.tint *= color;
    w.set(rec::exponent, n);
  }
  template <class E>
  bool edit(E& e, MaterialCommon&) { return e.color("colour", color); }
};

}  // namespace pt
