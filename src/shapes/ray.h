// CPU twins of common.glsl's Ray and Hit, for the CPU twins of the intersection routines
// (sphere.h beside sphere.glsl, ...): picking casts the very rays the shader casts.
#pragma once
#include <glm/glm.hpp>

namespace pt {

constexpr float T_INF = 3.0e38f;

struct Ray {
  glm::vec3 o, d;
};
// t: distance along the unit direction; id: shape index or -1; n: outward unit normal;
// p: the hit point on the surface.
struct Hit {
  float t = T_INF;
  int id = -1;
  glm::vec3 n{0.0f}, p{0.0f};
};

inline float max3(glm::vec3 v) { return glm::max(glm::max(v.x, v.y), v.z); }

}  // namespace pt
