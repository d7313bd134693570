// What every punctual light kind's stem (lights/<kind>.h) is written against. A punctual
// light is a light record (core/records.h, PT_LIGHT_RECORD) with shape = -1 - its kind:
// `radiance` holds colour x intensity (radiant intensity in the scene's radiance units x
// area per steradian; a directional light's: irradiance), and the kind writes what it
// uses of position, direction (unit, where the light points), range (0: none) and the
// cone's cosines. Its GLSL (lights/<kind>.glsl) defines
//   bool punctual_<kind>(LightRec l, vec3 p, out vec3 wi, out float dist, out vec3 e)
// giving the unit direction from p to the light, the distance (T_INF: at infinity) and
// the irradiance e on a surface at p facing the light (the integrator multiplies by the
// BSDF times cosine); false when it gives none there. Delta lights: next-event estimation
// alone reaches them (no MIS weight; BSDF-sampled rays never hit them).
// A stem declares kXml, kExample (an element the tests loop over), parse(XmlAttrs&)
// (strict), pack(LightWriter&), power(ctx) (the emitted flux, for selection
// proportional to power: pbrt-v4's PowerLightSampler, lightsamplers.h) and position().
#pragma once
#include <cmath>

#include <glm/glm.hpp>

#include "core/records.h"
#include "core/xml_attrs.h"
#include "lights/kinds.h"

namespace pt {

inline constexpr float kLightPi = 3.14159265358979f;

// Writes a punctual light's fields into light record `record`.
struct LightWriter {
  RecordBuffer& b;
  int record;
};

// What power() may need of the scene: the radius of a sphere bounding it (a directional
// light's flux through the scene, pi r^2 E, as pbrt-v4's DistantLight::Phi).
struct LightContext {
  float scene_radius = 1.0f;
};

// colour x intensity (colour: linear RGB, default white; intensity default 1), both >= 0.
inline glm::vec3 parse_light_color(XmlAttrs& a) {
  const glm::vec3 color = a.vec3("color", glm::vec3(1.0f));
  const float intensity = a.number("intensity", 1.0f);
  if (intensity < 0.0f || glm::any(glm::lessThan(color, glm::vec3(0.0f)))) a.fail("'intensity' and 'color' must be >= 0");
  return color * intensity;
}

// A unit direction from attribute `name` (required, not zero).
inline glm::vec3 parse_light_direction(XmlAttrs& a, const char* name) {
  const glm::vec3 d = a.vec3(name);
  if (!(glm::length(d) > 0.0f)) a.fail(std::string("'") + name + "' must not be zero");
  return glm::normalize(d);
}

// range="r" (> 0; absent: no range).
inline float parse_light_range(XmlAttrs& a) {
  const float r = a.number("range", 0.0f);
  if (a.has("range") && !(r > 0.0f)) a.fail("'range' must be positive");
  return r;
}

inline void pack_light_common(LightWriter& w, LightKind kind, glm::vec3 intensity) {
  w.b.set(w.record, light_rec::shape, -1 - int(kind));
  w.b.set(w.record, light_rec::radiance, intensity);
}

// The mean of the three channels: the scalar that power-proportional selection uses.
inline float light_mean(glm::vec3 c) { return (c.x + c.y + c.z) / 3.0f; }

}  // namespace pt
