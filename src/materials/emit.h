// Emit: <Emit><Absorb intensity="I" color="r g b"/></Emit>: emits radiance I * color from
// its front side and absorbs everything (the path ends there; emit.glsl). The radiance is
// the material's emission (MaterialCommon), which <Emit intensity color> around any other
// material adds to it as well (xml_loader.cpp): so this kind has no fields of its own.
#pragma once
#include <cstring>

#include <tinyxml2.h>

#include "materials/material.h"

namespace pt {

struct Emit {
  static constexpr const char* kXml = "Emit";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<Emit><Absorb intensity=\"0\" color=\"1 1 1\"/></Emit>";
  static constexpr bool kHasChildren = true;  // its <Absorb>
  PT_KIND_RECORD(PT_NO_FIELDS, PT_NO_FIELDS)

  void parse(MaterialParse& p) {
    XmlAttrs& a = p.attrs;
    a.finish();
    const tinyxml2::XMLElement* absorb = p.element->FirstChildElement();
    if (!absorb || std::strcmp(absorb->Name(), "Absorb") != 0 || absorb->NextSiblingElement())
      a.fail("must contain exactly one <Absorb intensity=\"..\" color=\"..\"/>");
    XmlAttrs b(absorb, a.file());
    const float intensity = b.number("intensity");
    const glm::vec3 color = b.vec3("color", glm::vec3(1.0f));
    if (intensity < 0.0f || glm::any(glm::lessThan(color, glm::vec3(0.0f)))) b.fail("intensity and color must be >= 0");
    b.finish();
    if (absorb->FirstChildElement()) b.fail("<Absorb> takes no child elements");
    p.common.emission = color * intensity;
  }
  void pack(MaterialWriter&) const {}
  template <class E>
  bool edit(E& e, MaterialCommon& c) { return e.drag3("emission", c.emission, 0.1f, 0.0f, 1e4f); }
};

}  // namespace pt
