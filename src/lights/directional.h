// DirectionalLight (extension): <DirectionalLight direction="x y z" color="r g b"
// intensity="E">: light from infinitely far away travelling along `direction` (where it
// points: the sun's rays); a surface facing it receives the irradiance E x color
// everywhere (directional.glsl); shadow rays go to infinity. Flux through the scene:
// pi r^2 E for a sphere of radius r bounding it (pbrt-v4's DistantLight::Phi).
#pragma once
#include "lights/light.h"

namespace pt {

struct DirectionalLight {
  static constexpr const char* kXml = "DirectionalLight";
  static constexpr const char* kExample = "<DirectionalLight direction=\"-0.3 -1 0.2\" color=\"1 0.95 0.9\" intensity=\"2\"/>";
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit
  glm::vec3 intensity{1.0f};               // irradiance x colour

  void parse(XmlAttrs& a) {
    direction = parse_light_direction(a, "direction");
    intensity = parse_light_color(a);
  }
  void pack(LightWriter& w) const {
    pack_light_common(w, LightKind::DirectionalLight, intensity);
    w.b.set(w.record, light_rec::direction, direction);
  }
  float power(const LightContext& ctx) const { return kLightPi * ctx.scene_radius * ctx.scene_radius * light_mean(intensity); }
  glm::vec3 where() const { return glm::vec3(0.0f); }
};

}  // namespace pt
