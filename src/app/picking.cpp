#include "app/picking.h"

#include "render/camera.h"
#include "render/packing.h"
#include "shapes/box.h"
#include "shapes/plane.h"
#include "shapes/sphere.h"
#include "shapes/triangle.h"

namespace pt {

Ray camera_ray(const Camera& camera, glm::vec2 pixel, glm::ivec2 size) {
  const CameraBasis cb = camera_basis(camera, float(size.x) / float(size.y));
  const glm::vec2 ndc = pixel / glm::vec2(size) * 2.0f - 1.0f;
  return {cb.position, glm::normalize(cb.forward + ndc.x * cb.right + ndc.y * cb.up)};
}

Hit intersect_scene(const Scene& scene, const Ray& r) {
  const BoxRay br = prepare_box(r);
  const TriangleRay tr = prepare_triangle(r);
  Hit h;
  for (size_t i = 0; i < scene.shapes.size(); ++i) {
    const Shape& s = scene.shapes[i];
    switch (s.kind) {  // no default: a new kind must be handled here (-Wswitch)
      case ShapeKind::Sphere: intersect_sphere(s, int(i), r, h); break;
      case ShapeKind::Box: intersect_box(s, int(i), r, br, h); break;
      case ShapeKind::Plane: intersect_plane(s, int(i), r, h); break;
      case ShapeKind::Triangle: intersect_triangle(s, int(i), r, tr, h); break;
      case ShapeKind::Mesh: {  // every triangle (a click is rare; the BVH is the GPU's)
        const size_t n = scene.meshes[size_t(s.mesh)]->triangles.size();
        for (size_t t = 0; t < n; ++t) {
          glm::vec3 v[3];
          mesh_triangle(scene, s, t, v);
          Shape tri;
          tri.kind = ShapeKind::Triangle;
          tri.a = v[0];
          tri.b = v[1];
          tri.c = v[2];
          intersect_triangle(tri, int(i), r, tr, h);
        }
        break;
      }
    }
  }
  return h;
}

int pick(const Scene& scene, const Camera& camera, glm::vec2 pixel, glm::ivec2 size) {
  if (size.x < 1 || size.y < 1) return -1;
  return intersect_scene(scene, camera_ray(camera, pixel, size)).id;
}

}  // namespace pt
