// SmoothDielectric: <SmoothDielectric ior="n" color="r g b"/>: glass in air; exact
// Fresnel picks reflection or refraction (total internal reflection included), the
// refracted weight tint / eta^2 (pbrt-v4 9.5.2; smooth_dielectric.glsl).
#pragma once
#include "materials/material.h"

namespace pt {

struct SmoothDielectric {
  static constexpr const char* kXml = "SmoothDielectric";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<SmoothDielectric ior=\"1.5\"/>";
  static constexpr const char* kFurnace = "<SmoothDielectric ior=\"2.4\"/>";  // much total internal reflection
  float ior = 1.5f;  // inside; outside is air (1)
  glm::vec3 color{1.0f};

#define PT_SMOOTH_DIELECTRIC_FIELDS(F) F(float, eta_outer) F(float, eta_inner)
  PT_KIND_RECORD(PT_SMOOTH_DIELECTRIC_FIELDS, PT_NO_FIELDS)

  void parse(MaterialParse& p) {
    ior = parse_ior(p.attrs, "ior", 1.5f);
    color = p.attrs.vec3("color", glm::vec3(1.0f));
  }
  void pack(MaterialWriter& w) const {
    w.tint *= color;
    w.set(rec::eta_outer, 1.0f);
    w.set(rec::eta_inner, ior);
  }
  template <class E>
  bool edit(E& e, MaterialCommon&) { return any_changed({e.color("colour", color), e.slider("ior", ior, 1.0f, 3.0f)}); }
};

}  // namespace pt
