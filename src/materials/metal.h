// Metal: <Metal iorComplex="n k" | ior="n" glossiness="g" montecarlo="m" color="r g b"/>.
// A GGX microfacet conductor (Walter et al. 2007) with alpha = glossiness^2, the exact
// conductor Fresnel of n + ik and Smith height-correlated masking (Heitz 2014); glossiness
// 0 is a perfect mirror. montecarlo picks the sampling, both exact: 1 = GGX visible
// normals (Heitz 2018), 0 = cosine-weighted hemisphere (metal.glsl).
#pragma once
#include "materials/material.h"

namespace pt {

struct Metal {
  static constexpr const char* kXml = "Metal";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<Metal iorComplex=\"0.2 3.9\" glossiness=\"0.4\"/>";
  glm::vec2 iorComplex{1.5f, 0.0f};  // n, k; ior="n" gives k = 0
  float glossiness = 0.0f;           // 0 mirror .. 1 rough
  float montecarlo = 1.0f;           // >= 0.5: visible-normal sampling, else cosine
  glm::vec3 color{1.0f};

#define PT_METAL_FIELDS(F) F(float, roughness) F(float, sampling) F(float, ior_n) F(float, ior_k)
  PT_KIND_RECORD(PT_METAL_FIELDS, PT_NO_FIELDS)

  void parse(MaterialParse& p) {
    XmlAttrs& a = p.attrs;
    if (a.has("iorComplex") && a.has("ior")) a.fail("give either 'iorComplex' or 'ior', not both");
    if (a.has("iorComplex")) {
      iorComplex = a.vec2("iorComplex");
      if (!(iorComplex.x > 0.0f) || iorComplex.y < 0.0f) a.fail("'iorComplex' needs n > 0 and k >= 0");
    } else {
      iorComplex = glm::vec2(parse_ior(a, "ior", 1.5f), 0.0f);
    }
    glossiness = a.number("glossiness", 0.0f);
    if (glossiness < 0.0f || glossiness > 1.0f) a.fail("'glossiness' must be in [0, 1]");
    montecarlo = a.number("montecarlo", 1.0f);
    if (montecarlo < 0.0f || montecarlo > 1.0f) a.fail("'montecarlo' must be in [0, 1]");
    color = a.vec3("color", glm::vec3(1.0f));
  }
  void pack(MaterialWriter& w) const {
    w.tint *= color;
    w.set(rec::roughness, glossiness);
    w.set(rec::sampling, montecarlo);
    w.set(rec::ior_n, iorComplex.x);
    w.set(rec::ior_k, iorComplex.y);
  }
  template <class E>
  bool edit(E& e, MaterialCommon&) {
    return any_changed({e.color("colour", color), e.slider("roughness", glossiness, 0.0f, 1.0f), e.slider("ior", iorComplex.x, 1.0f, 3.0f)});
  }
};

}  // namespace pt
