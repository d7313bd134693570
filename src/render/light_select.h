// Light selection for next-event estimation (shaders/lights.glsl): one light record per
// sampled emitter (render/packing.h's light_shapes, in that order) and then one per
// punctual light (Scene::punctual), chosen with probability proportional to its power
// (emitted flux: the mean of radiance's channels x area x pi for an emitting shape; a
// punctual kind's power(), lights/<kind>.h), as pbrt-v4's PowerLightSampler
// (lightsamplers.h), through an alias table (Walker 1977, in Vose's 1991 construction:
// O(1) per sample, two record fetches at most). Unbiased whatever the weights, as long
// as every light that can contribute has a weight > 0: the shader divides by the same
// pmf it sampled with, and light_pdf (MIS for BSDF-sampled hits on an emitter) reads it
// too. Uniform selection spent half of scene2's samples on a light sphere hidden inside
// the emitting box (issue 17); by power alone that sphere would get 18.5% of them; being
// sealed (below) it gets none.
//
// Sealed lights: an emitting shape that lies (over the shutter's motion; all of it but a
// set of zero area: shapes/all.h, inside_box) strictly inside a closed solid (a kind
// with solid(): Box) whose material is Emit (Emit+Absorb: every ray that meets it ends there,
// shadow rays included, and no material feature cuts its hits) can light nothing while
// the camera is outside that box: a camera ray, and by induction every later ray of a
// path, starts outside the open box, so it reaches a point inside only by crossing the
// box's surface, where it meets the box first and ends (a shadow ray: is occluded). So
// its weight is 0 (never selected) while the camera - its whole lens disk - is outside
// every such box (PackedScene::seal_lo/hi); when it is inside one, the renderer sets
// u_lights_uniform and the shader selects uniformly among all lights (camera_sealed_off).
// Only solids whose inside is exactly a box are taken as containers; nothing else is assumed.
#pragma once
#include <vector>

#include "core/records.h"
#include "scene/scene.h"

namespace pt {

// An alias table over weights (>= 0, not all 0): pmf[i] = w[i] / sum, and choosing slot
// i uniformly, keeping it with probability keep[i], else taking alias[i], selects i with
// probability pmf[i]. All zero: pmf 0 everywhere (nothing is ever selected).
struct AliasTable {
  std::vector<float> pmf, keep;
  std::vector<int> alias;
};
AliasTable alias_table(const std::vector<double>& weights);

// Each light's selection weight (its power), in record order: `shapes` (the emitting
// shapes sampled as lights), then the scene's punctual lights.
std::vector<double> light_powers(const Scene& scene, const std::vector<int>& shapes);

// For each of `shapes`, whether it is sealed (above), and the boxes that seal them.
struct Sealed {
  std::vector<char> sealed;             // per entry of `shapes`
  std::vector<glm::vec3> lo, hi;        // the sealing boxes
};
Sealed sealed_lights(const Scene& scene, const std::vector<int>& shapes);

// Appends every light record (area lights of `shapes`, then punctual lights) to `lights`
// with its selection table (sealed lights weigh 0); the sealing boxes go to seal_lo/hi.
void pack_lights(const Scene& scene, const std::vector<int>& shapes, RecordBuffer& lights, std::vector<glm::vec3>& seal_lo,
                 std::vector<glm::vec3>& seal_hi);

// Whether the camera's lens disk reaches inside a sealing box (then the shader must
// select lights uniformly: u_lights_uniform).
bool camera_sealed_off(const std::vector<glm::vec3>& seal_lo, const std::vector<glm::vec3>& seal_hi, glm::vec3 position,
                       float aperture);

// The radius of a sphere about the bounded shapes' box (at least 1e-3; with no bounded
// shape, the camera's distance from the origin, at least 1): a directional light's power
// is its flux through it.
float scene_radius(const Scene& scene);

}  // namespace pt
