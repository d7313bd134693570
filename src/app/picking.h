// Picking: the object under a pixel, by a CPU ray cast through the same scene with the
// same camera math as the shader (render/camera.h, integrator.glsl's main) and the CPU
// twins of the shapes' intersection routines (shapes/<kind>.h beside shapes/<kind>.glsl),
// through the list of kinds.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"
#include "shapes/ray.h"

namespace pt {

// The pinhole ray (the lens centre, time 0) through `pixel`: a position in the image of
// `size` pixels, origin at the bottom-left corner as gl_FragCoord (so (x + 0.5, y + 0.5)
// is the centre of pixel (x, y)).
Ray camera_ray(const Camera& camera, glm::vec2 pixel, glm::ivec2 size);

// The closest hit of the ray with Scene::shapes (brute force for now: the BVH's CPU
// traversal can replace the loop behind this API).
Hit intersect_scene(const Scene& scene, const Ray& r);

// The index in Scene::shapes of the object under `pixel`, or -1 when the ray leaves the scene.
int pick(const Scene& scene, const Camera& camera, glm::vec2 pixel, glm::ivec2 size);

}  // namespace pt
