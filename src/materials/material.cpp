#include "materials/material.h"

#include <cassert>
#include <string>

namespace pt {

float parse_ior(XmlAttrs& a, const char* name, float fallback) {
  const float v = a.number(name, fallback);
  if (!(v > 0.0f) || v > 100.0f) a.fail(std::string("'") + name + "' must be in (0, 100]");
  return v;
}

}  // namespace pt
