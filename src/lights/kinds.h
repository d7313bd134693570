// The one list of punctual (delta) light kinds, as shapes/kinds.h is for shapes. A kind
// is one stem: lights/<glsl>.h (its parameters with the XML's names, strict parse, what
// it packs into a light record, its power for light selection, the model's comment)
// beside lights/<glsl>.glsl (punctual_<glsl>: the direction towards the light from a
// point, its distance and the irradiance it gives a surface facing it there).
// Adding a kind = its stem + one line here + its #include in lights/all.h (+ its test).
// The XML dispatch, the scene model (lights/all.h: a std::variant), the packing and the
// shader generator iterate this list.
//
//   Lights:    X(Type, glsl_name, "XmlElement")
#pragma once

#define PT_LIGHT_KINDS(X)                          \
  X(PointLight, point, "PointLight")               \
  X(SpotLight, spot, "SpotLight")                  \
  X(DirectionalLight, directional, "DirectionalLight")

namespace pt {

enum class LightKind : int {
#define PT_X(e, g, x) e,
  PT_LIGHT_KINDS(PT_X)
#undef PT_X
};

struct LightKindInfo {
  const char* glsl;  // snippet name and function suffix: lights/point.glsl, punctual_point
  const char* xml;   // element name in scene files
};

inline constexpr LightKindInfo kLightKinds[] = {
#define PT_X(e, g, x) {#g, x},
    PT_LIGHT_KINDS(PT_X)
#undef PT_X
};
inline constexpr int kNumLightKinds = int(sizeof(kLightKinds) / sizeof(kLightKinds[0]));

inline const LightKindInfo& info(LightKind k) { return kLightKinds[int(k)]; }

}  // namespace pt
