#include "app/picking.h"

#include "render/camera.h"

namespace pt {

Ray camera_ray(const Camera& camera, glm::vec2 pixel, glm::ivec2 size) {
  const CameraBasis cb = camera_basis(camera, float(size.x) / float(size.y));
  const glm::vec2 ndc = pixel / glm::vec2(size) * 2.0f - 1.0f;
  return {cb.position, glm::normalize(cb.forward + ndc.x * cb.right + ndc.y * cb.up)};
}

Hit intersect_scene(const Scene& scene, const Ray& r) {
  const ShapeQuery q(r, ShapeContext{&scene.meshes, 1.0f});  // each kind's twin (shapes/<kind>.h)
  Hit h;
  for (size_t i = 0; i < scene.shapes.size(); ++i) intersect(scene.shapes[i].params, q, int(i), h);
  return h;
}

int pick(const Scene& scene, const Camera& camera, glm::vec2 pixel, glm::ivec2 size) {
  if (size.x < 1 || size.y < 1) return -1;
  return intersect_scene(scene, camera_ray(camera, pixel, size)).id;
}

}  // namespace pt
