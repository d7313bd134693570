// SpotLight (extension): <SpotLight position="x y z" direction="x y z" color="r g b"
// intensity="I" innerCone="deg" outerCone="deg" [range="r"]>: a point light whose
// intensity I x color falls off with the angle theta from `direction` as
// KHR_lights_punctual defines it (its README's reference implementation): full inside
// innerCone, zero outside outerCone, and in between the square of the linear ramp
// clamp((cos theta - cos outer) / (cos inner - cos outer), 0, 1); the range window as a
// PointLight's (spot.glsl). Cone angles in degrees, 0 <= innerCone < outerCone <= 90
// (glTF's bounds; glTF gives radians: the glTF reader converts). Flux
// 2 pi I ((1 - cos inner) + (cos inner - cos outer) / 3): the integral of that falloff.
#pragma once
#include "lights/light.h"

namespace pt {

struct SpotLight {
  static constexpr const char* kXml = "SpotLight";
  static constexpr const char* kExample =
      "<SpotLight position=\"0 3 0\" direction=\"0.1 -1 0\" intensity=\"20\" innerCone=\"15\" outerCone=\"30\"/>";
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit: where it points
  glm::vec3 intensity{1.0f};
  float inner = 0.0f;                       // radians
  float outer = kLightPi / 4.0f;            // radians (glTF's default)
  float range = 0.0f;

  void parse(XmlAttrs& a) {
    position = a.vec3("position");
    direction = parse_light_direction(a, "direction");
    intensity = parse_light_color(a);
    const float i = a.number("innerCone", 0.0f), o = a.number("outerCone", 45.0f);
    if (!(i >= 0.0f && i < o && o <= 90.0f)) a.fail("cone angles must satisfy 0 <= innerCone < outerCone <= 90 (degrees)");
    inner = glm::radians(i);
    outer = glm::radians(o);
    range = parse_light_range(a);
  }
  void pack(LightWriter& w) const {
    pack_light_common(w, LightKind::SpotLight, intensity);
    w.b.set(w.record, light_rec::position, position);
    w.b.set(w.record, light_rec::direction, direction);
    w.b.set(w.record, light_rec::range, range);
    w.b.set(w.record, light_rec::cos_inner, std::cos(inner));
    w.b.set(w.record, light_rec::cos_outer, std::cos(outer));
  }
  float power(const LightContext&) const {
    const float ci = std::cos(inner), co = std::cos(outer);
    return 2.0f * kLightPi * light_mean(intensity) * ((1.0f - ci) + (ci - co) / 3.0f);
  }
  glm::vec3 where() const { return position; }
};

}  // namespace pt
