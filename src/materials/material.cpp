#include "materials/material.h"

#include <cassert>
#include <string>

namespace pt {

// An IOR at or below 0 is meaningless; any positive one is a material (120.5 is the 2016
// program's near-perfect mirror). The lower bound is the reciprocal of the scene's
// magnitude bound: the shader divides one IOR by another and squares the ratio, which
// between 1e-9 and 1e9 stays a normal float (1e-36..1e36), so no ratio turns 0 or inf.
float parse_ior(XmlAttrs& a, const char* name, float fallback) {
  const float v = a.number(name, fallback);
  if (!(v > 0.0f)) a.fail(std::string("'") + name + "' must be positive");
  if (v < kMinIor) a.fail(std::string("'") + name + "' must be at least 1e-9 (the ratio of two IORs, squared, must stay a float)");
  return v;
}

}  // namespace pt
