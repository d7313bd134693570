// An absorbing medium inside a closed surface (the kinds with kMedium: SmoothDielectric,
// RoughDielectric): KHR_materials_volume's terms, attenuationColor (what light keeps of
// itself, each component in [0, 1]) after attenuationDistance (> 0), so the absorption
// coefficient per unit length is sigma = -ln(attenuationColor) / attenuationDistance and a
// segment of length t keeps exp(-sigma t) (Beer-Lambert; shaders/media.glsl tracks the
// medium a path is in). No attenuation: sigma 0, and a scene of such materials only has
// no medium code (HAS_MEDIA).
#pragma once
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "core/xml_attrs.h"
#include "materials/features.h"

namespace pt {

// The largest absorption coefficient stored (an attenuationColor of 0: nothing gets
// through any length; finite, so that exp(-sigma t) at t = 0 stays 1).
inline constexpr float kMaxSigma = 1e30f;

inline glm::vec3 sigma_from(glm::vec3 attenuation_color, float attenuation_distance) {
  glm::vec3 s(0.0f);
  if (!std::isfinite(attenuation_distance)) return s;  // glTF's default: no absorption
  for (int c = 0; c < 3; ++c)
    s[c] = attenuation_color[c] <= 0.0f ? kMaxSigma : std::min(kMaxSigma, -std::log(attenuation_color[c]) / attenuation_distance);
  return glm::max(s, glm::vec3(0.0f));
}

// The XML's attenuationColor="r g b" attenuationDistance="d" (both or neither).
inline glm::vec3 parse_medium(XmlAttrs& a) {
  const glm::vec3 c = a.vec3("attenuationColor", glm::vec3(1.0f));
  for (int k = 0; k < 3; ++k)
    if (!(c[k] >= 0.0f && c[k] <= 1.0f)) a.fail("'attenuationColor' components must be in [0, 1]");
  const bool has_distance = a.has("attenuationDistance");
  const float d = a.number("attenuationDistance", 1.0f);
  if (!(d > 0.0f && std::isfinite(d))) a.fail("'attenuationDistance' must be a finite length > 0");
  if (has_distance != a.has("attenuationColor")) a.fail("'attenuationColor' and 'attenuationDistance' go together");
  return has_distance ? sigma_from(c, d) : glm::vec3(0.0f);
}

inline unsigned medium_features(glm::vec3 sigma) {
  return glm::any(glm::greaterThan(sigma, glm::vec3(0.0f))) ? feature_bit(MaterialFeature::Media) : 0u;
}

}  // namespace pt
