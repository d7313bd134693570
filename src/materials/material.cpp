#include "materials/material.h"

#include <cassert>
#include <string>

namespace pt {

void MaterialWriter::slot(int field, int width, float v, int comp) {
  assert(fields_[field].width == width && !fields_[field].hit);
  (void)width;
  const int s = kind_slot(fields_, field) + comp;
  assert(s < material_rec::kPayloadSlots);
  b_.set(i_, *material_rec::kPayload[s], v);
}

float parse_ior(XmlAttrs& a, const char* name, float fallback) {
  const float v = a.number(name, fallback);
  if (!(v > 0.0f) || v > 100.0f) a.fail(std::string("'") + name + "' must be in (0, 100]");
  return v;
}

}  // namespace pt
