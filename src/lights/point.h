// PointLight (extension): <PointLight position="x y z" color="r g b" intensity="I"
// [range="r"]>: a point that emits the radiant intensity I x color equally in every
// direction (the scene's radiance units x area per steradian: a <Light> sphere of
// radiance L and radius R seen from afar is a point of I = L pi R^2). A surface at
// distance d facing it receives E = I / d^2, times KHR_lights_punctual's range window
// clamp(1 - (d / range)^4, 0, 1) when a range is given (point.glsl). Delta: only
// next-event estimation reaches it. pbrt-v4's PointLight (lights.h); flux 4 pi I.
#pragma once
#include "lights/light.h"

namespace pt {

struct PointLight {
  static constexpr const char* kXml = "PointLight";
  static constexpr const char* kExample = "<PointLight position=\"0.5 2 -0.3\" color=\"1 0.9 0.8\" intensity=\"6\" range=\"20\"/>";
  glm::vec3 position{0.0f};
  glm::vec3 intensity{1.0f};  // colour x intensity
  float range = 0.0f;         // 0: none

  void parse(XmlAttrs& a) {
    position = a.vec3("position");
    intensity = parse_light_color(a);
    range = parse_light_range(a);
  }
  void pack(LightWriter& w) const {
    pack_light_common(w, LightKind::PointLight, intensity);
    w.b.set(w.record, light_rec::position, position);
    w.b.set(w.record, light_rec::range, range);
  }
  float power(const LightContext&) const { return 4.0f * kLightPi * light_mean(intensity); }
  glm::vec3 where() const { return position; }
};

}  // namespace pt
