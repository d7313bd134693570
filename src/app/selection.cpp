#include "app/selection.h"

namespace pt {

glm::vec3 shape_position(const Shape& s) { return position(s.params); }

void move_shape(Scene& scene, int i, glm::vec3 p) {
  Shape& s = scene.shapes[size_t(i)];
  move(s.params, p - shape_position(s));
  sync_shape_light(scene, i);
}

void sync_shape_light(Scene& scene, int i) {
  const Shape& s = scene.shapes[size_t(i)];
  if (s.light < 0) return;
  const Sphere& sphere = *s.as<Sphere>();  // a light is a sphere
  Light& l = scene.lights[size_t(s.light)];
  l.position = sphere.center;
  l.radius = sphere.radius;
  sync_light(scene, s.light);
}

void set_sphere_radius(Scene& scene, int i, float radius) {
  Sphere* s = scene.shapes[size_t(i)].as<Sphere>();
  if (!s || !(radius > 0.0f)) return;
  s->radius = radius;
  sync_shape_light(scene, i);
}

}  // namespace pt
