#include "app/selection.h"

namespace pt {

glm::vec3 shape_position(const Shape& s) {
  switch (s.kind) {
    case ShapeKind::Sphere: return s.a;
    case ShapeKind::Box: return 0.5f * (s.a + s.b);
    case ShapeKind::Plane: return s.a * s.radius;
    case ShapeKind::Triangle: return (s.a + s.b + s.c) / 3.0f;
    case ShapeKind::Mesh: return glm::vec3(s.transform[3]);  // the instance's origin
  }
  return s.a;
}

void move_shape(Scene& scene, int i, glm::vec3 p) {
  Shape& s = scene.shapes[size_t(i)];
  const glm::vec3 d = p - shape_position(s);
  switch (s.kind) {
    case ShapeKind::Sphere: s.a += d; break;
    case ShapeKind::Box: s.a += d, s.b += d; break;
    case ShapeKind::Plane: s.radius += glm::dot(s.a, d); break;  // only the offset along the normal moves it
    case ShapeKind::Triangle: s.a += d, s.b += d, s.c += d; break;
    case ShapeKind::Mesh: s.transform[3] += glm::vec4(d, 0.0f); break;  // the whole instance
  }
  if (s.light >= 0) {
    scene.lights[size_t(s.light)].position = s.a;
    sync_light(scene, s.light);
  }
}

void set_sphere_radius(Scene& scene, int i, float radius) {
  Shape& s = scene.shapes[size_t(i)];
  if (s.kind != ShapeKind::Sphere || !(radius > 0.0f)) return;
  s.radius = radius;
  if (s.light >= 0) {
    scene.lights[size_t(s.light)].radius = radius;
    sync_light(scene, s.light);
  }
}

}  // namespace pt
