// Transmit: <Transmit outerIor="n1" innerIor="n2"/>: the seed's pure refraction with no
// Fresnel reflection (energy-preserving); total internal reflection reflects
// (transmit.glsl).
#pragma once
#include "materials/material.h"

namespace pt {

struct Transmit {
  static constexpr const char* kXml = "Transmit";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<Transmit outerIor=\"1\" innerIor=\"1.5\"/>";
  static constexpr const char* kFurnace = "<Transmit outerIor=\"1\" innerIor=\"1.33\"/>";
  float outerIor = 1.0f;  // the medium the outward normal points into
  float innerIor = 1.5f;

#define PT_TRANSMIT_FIELDS(F) F(float, eta_outer) F(float, eta_inner)
  PT_KIND_RECORD(PT_TRANSMIT_FIELDS, PT_NO_FIELDS)

  void parse(MaterialParse& p) {
    outerIor = parse_ior(p.attrs, "outerIor", 1.0f);
    innerIor = parse_ior(p.attrs, "innerIor", 1.5f);
  }
  void pack(MaterialWriter& w) const {
    w.set(rec::eta_outer, outerIor);
    w.set(rec::eta_inner, innerIor);
  }
  template <class E>
  bool edit(E& e, MaterialCommon& c) { return any_changed({e.color("colour", c.tint), e.slider("ior", innerIor, 1.0f, 3.0f)}); }
};

}  // namespace pt
