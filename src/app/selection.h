// Editing a picked object: its transform and the values of its material, as plain edits
// of the Scene (the panel calls these, then re-uploads the scene: the kinds do not
// change, so the cached program is reused and nothing recompiles).
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace pt {

// What the panel offers for a material kind.
struct MaterialFields {
  bool tint = false;       // Material::tint (the colour; Emit: the emitted radiance instead)
  bool roughness = false;  // Metal: glossiness 0..1
  bool ior = false;        // Metal, SmoothDielectric: ior.x; Transmit: inner_ior
};
MaterialFields material_fields(MaterialKind k);

// The point the panel shows as the object's position: a sphere's centre, a box's centre,
// a triangle's centroid, a plane's point closest to the origin.
glm::vec3 shape_position(const Shape& s);
// Moves shape `i` so that shape_position() becomes `p` (a light's sphere moves its Light).
void move_shape(Scene& scene, int i, glm::vec3 p);
// A sphere's radius (and its Light's); ignored for other kinds and radius <= 0.
void set_sphere_radius(Scene& scene, int i, float radius);

}  // namespace pt
