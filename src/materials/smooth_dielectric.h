// SmoothDielectric: <SmoothDielectric ior="n" color="r g b" attenuationColor="r g b"
// attenuationDistance="d"/>: glass in air; exact Fresnel picks reflection or refraction
// (total internal reflection included), the refracted weight tint / eta^2 (pbrt-v4 9.5.2;
// smooth_dielectric.glsl). Inside, an absorbing medium (KHR_materials_volume's terms): light
// that travels a distance d keeps attenuationColor of itself, so the absorption coefficient
// is sigma = -ln(attenuationColor) / attenuationDistance per unit length and a segment of
// length t keeps exp(-sigma t) (Beer-Lambert; the path tracks the medium it is in,
// shaders/integrator.glsl). Absent, or a colour of 1: clear glass, and the program has no
// medium code (HAS_MEDIA). The surface must be closed (a box, a sphere, a closed mesh).
#pragma once
#include <cmath>

#include "materials/material.h"

namespace pt {

struct SmoothDielectric {
  static constexpr const char* kXml = "SmoothDielectric";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<SmoothDielectric ior=\"1.5\"/>";
  static constexpr const char* kFurnace = "<SmoothDielectric ior=\"2.4\"/>";  // much total internal reflection
  static constexpr bool kMedium = true;
  // The largest absorption coefficient stored (an attenuationColor of 0: nothing gets
  // through any length; finite, so that exp(-sigma t) at t = 0 stays 1).
  static constexpr float kMaxSigma = 1e30f;
  float ior = 1.5f;  // inside; outside is air (1)
  glm::vec3 color{1.0f};
  glm::vec3 sigma{0.0f};  // the medium's absorption per unit length

#define PT_SMOOTH_DIELECTRIC_FIELDS(F) F(float, eta_outer) F(float, eta_inner) F(vec3, sigma)
  PT_KIND_RECORD(PT_SMOOTH_DIELECTRIC_FIELDS, PT_NO_FIELDS)

  unsigned features() const { return glm::any(glm::greaterThan(sigma, glm::vec3(0.0f))) ? feature_bit(MaterialFeature::Media) : 0u; }

  // sigma from KHR_materials_volume's attenuationColor (each in [0, 1]) and
  // attenuationDistance (> 0; infinite: no absorption).
  static glm::vec3 sigma_from(glm::vec3 attenuation_color, float attenuation_distance) {
    glm::vec3 s(0.0f);
    if (!std::isfinite(attenuation_distance)) return s;
    for (int c = 0; c < 3; ++c)
      s[c] = attenuation_color[c] <= 0.0f ? kMaxSigma : std::min(kMaxSigma, -std::log(attenuation_color[c]) / attenuation_distance);
    return glm::max(s, glm::vec3(0.0f));
  }

  void parse(MaterialParse& p) {
    ior = parse_ior(p.attrs, "ior", 1.5f);
    color = p.attrs.vec3("color", glm::vec3(1.0f));
    const glm::vec3 c = p.attrs.vec3("attenuationColor", glm::vec3(1.0f));
    for (int k = 0; k < 3; ++k)
      if (!(c[k] >= 0.0f && c[k] <= 1.0f)) p.attrs.fail("'attenuationColor' components must be in [0, 1]");
    const bool has_distance = p.attrs.has("attenuationDistance");
    const float d = p.attrs.number("attenuationDistance", 1.0f);
    if (!(d > 0.0f && std::isfinite(d))) p.attrs.fail("'attenuationDistance' must be a finite length > 0");
    if (has_distance != p.attrs.has("attenuationColor")) p.attrs.fail("'attenuationColor' and 'attenuationDistance' go together");
    sigma = has_distance ? sigma_from(c, d) : glm::vec3(0.0f);
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
