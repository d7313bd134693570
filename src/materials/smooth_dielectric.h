// SmoothDielectric: <SmoothDielectric ior="n" color="r g b" attenuationColor="r g b"
// attenuationDistance="d"/>: glass in air; exact Fresnel picks reflection or refraction
// (total internal reflection included), the refracted weight tint / eta^2 (pbrt-v4 9.5.2;
// smooth_dielectric.glsl). Inside, an absorbing medium (materials/medium.h: Beer-Lambert,
// KHR_materials_volume's terms); absent, clear glass. The surface must be closed (a box, a
// sphere, a closed mesh).
#pragma once
#include "materials/material.h"
#include "materials/medium.h"

namespace pt {

struct SmoothDielectric {
  static constexpr const char* kXml = "SmoothDielectric";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<SmoothDielectric ior=\"1.5\"/>";
  static constexpr const char* kFurnace = "<SmoothDielectric ior=\"2.4\"/>";  // much total internal reflection
  static constexpr bool kMedium = true;
  float ior = 1.5f;  // inside; outside is air (1)
  glm::vec3 color{1.0f};
  glm::vec3 sigma{0.0f};  // the medium's absorption per unit length

#define PT_SMOOTH_DIELECTRIC_FIELDS(F) F(float, eta_outer) F(float, eta_inner) F(vec3, sigma)
  PT_KIND_RECORD(PT_SMOOTH_DIELECTRIC_FIELDS, PT_NO_FIELDS)

  unsigned features() const { return medium_features(sigma); }

  void parse(MaterialParse& p) {
    ior = parse_ior(p.attrs, "ior", 1.5f);
    color = p.attrs.vec3("color", glm::vec3(1.0f));
    sigma = parse_medium(p.attrs);
  }
  void pack(MaterialWriter& w) const {
    w.tint *= color;
    w.set(rec::eta_outer, 1.0f);
    w.set(rec::eta_inner, ior);
    w.set(rec::sigma, sigma);
  }
  template <class E>
  bool edit(E& e, MaterialCommon&) { return any_changed({e.color("colour", color), e.slider("ior", ior, 1.0f, 3.0f)}); }
};

}  // namespace pt
