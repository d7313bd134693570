// FresnelComposite: <FresnelComposite na="1" nb="1.5"> reflective, transmissive
// </FresnelComposite>: the two child materials mixed by the exact dielectric Fresnel
// reflectance F of the na|nb interface (nb inside). The surface step picks the first child
// with probability F, else the second (choose_fresnel_composite), the one-sample estimator
// of the mixture, so the composite itself never scatters (fresnel_composite.glsl). An
// <Attenuate> around the composite tints both children.
#pragma once
#include <tinyxml2.h>

#include "materials/material.h"

namespace pt {

struct FresnelComposite {
  static constexpr const char* kXml = "FresnelComposite";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<FresnelComposite na=\"1\" nb=\"1.5\"><Reflect/><Diffuse/></FresnelComposite>";
  static constexpr bool kHasChildren = true;
  static constexpr bool kComposite = true;
  float na = 1.0f, nb = 1.5f;
  int reflective = -1, transmissive = -1;  // the children, as indices in the scene's materials

#define PT_FRESNEL_COMPOSITE_FIELDS(F) F(float, eta_outer) F(float, eta_inner) F(int, child_a) F(int, child_b)
  PT_KIND_RECORD(PT_FRESNEL_COMPOSITE_FIELDS, PT_NO_FIELDS)

  void parse(MaterialParse& p) {
    XmlAttrs& a = p.attrs;
    if (p.loader.composite_depth() >= kMaxCompositeDepth) a.fail("nested more than 4 deep (the shader resolves 4 levels)");
    na = parse_ior(a, "na", 1.0f);
    nb = parse_ior(a, "nb", 1.5f);
    const tinyxml2::XMLElement* first = p.element->FirstChildElement();
    const tinyxml2::XMLElement* second = first ? first->NextSiblingElement() : nullptr;
    if (!first || !second || second->NextSiblingElement())
      a.fail("must contain exactly two materials: a reflective one, then a transmissive one");
    reflective = p.loader.child(first, p.common.tint);
    transmissive = p.loader.child(second, p.common.tint);
  }
  void pack(MaterialWriter& w) const {
    w.set(rec::eta_outer, na);
    w.set(rec::eta_inner, nb);
    w.set(rec::child_a, reflective);
    w.set(rec::child_b, transmissive);
  }
  template <class E>
  bool edit(E&, MaterialCommon&) { return false; }  // its children carry the colours
};

}  // namespace pt
