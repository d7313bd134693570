// The free camera of the seed (learnopengl-style Euler angles), with the convention
// the reference scenes were written for: yaw 180 looks down +x.
#pragma once
#include <cmath>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace pt {

struct CameraBasis {
  glm::vec3 position, forward, right, up;  // right/up scaled by the half-extent of the image plane
};

// camera_forward(c): scene/scene.h (the loader checks the view against 'up' with it).
inline CameraBasis camera_basis(const Camera& c, float aspect) {
  const glm::vec3 f = camera_forward(c);
  const glm::vec3 r = glm::normalize(glm::cross(f, c.up));
  const glm::vec3 u = glm::cross(r, f);
  const float t = std::tan(glm::radians(c.fov_y) * 0.5f);
  return {c.position, f, r * t * aspect, u * t};
}

}  // namespace pt
