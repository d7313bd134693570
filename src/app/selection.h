// Editing a picked object: its transform and the values of its material, as plain edits
// of the Scene (the panel calls these, then re-uploads the scene: the kinds do not
// change, so the cached program is reused and nothing recompiles).
#pragma once
#include <type_traits>
#include <variant>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace pt {

// The panel's fields for a material: what its kind's stem offers (materials/<kind>.h:
// edit), shown through editor `e`, which has
//   bool color(const char* label, glm::vec3&);
//   bool slider(const char* label, float&, float lo, float hi);
//   bool drag3(const char* label, glm::vec3&, float speed, float lo, float hi);
// (the panel's is ImGui's; tests record the calls). True when a value changed.
template <class E>
bool edit_material(Material& m, E& e) {
  return std::visit([&](auto& k) -> bool { return k.edit(e, m); }, m.params);
}

// The point the panel shows as the object's position, its kind's (shapes/<kind>.h:
// position): a sphere's centre, a box's centre, a triangle's centroid, a plane's point
// closest to the origin, a mesh instance's origin.
glm::vec3 shape_position(const Shape& s);
// Moves shape `i` so that shape_position() becomes `p` (a light's sphere moves its Light).
void move_shape(Scene& scene, int i, glm::vec3 p);
// After an edit of shape `i`'s parameters: a light's sphere carries its Light along.
void sync_shape_light(Scene& scene, int i);
// A sphere's radius (and its Light's); ignored for other kinds and radius <= 0.
void set_sphere_radius(Scene& scene, int i, float radius);

// The panel's fields for shape `i` besides its position: what its kind's stem offers
// (shapes/<kind>.h: edit; a sphere's radius), through editor `e` as for materials, which
// also has bool drag(const char* label, float&, float speed, float lo, float hi) (speed
// relative to the panel's). True when a value changed (then it moved: a refit).
template <class E>
bool edit_shape(Scene& scene, int i, E& e) {
  const bool changed = visit_shape(scene.shapes[size_t(i)].params, [&](auto& k) { return k.edit(e); });
  if (changed) sync_shape_light(scene, i);
  return changed;
}

}  // namespace pt
