// glTF 2.0 (.gltf with its buffers, or .glb), read with tinygltf (Debian's
// libtinygltf-dev, used header-only): the default scene's node tree flattened into parts,
// one per mesh primitive per node, each with its node's world transform. A primitive used
// by several nodes is one MeshData shared by all of them (instancing).
#pragma once
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"
#include "core/resumable.h"
#include "lights/all.h"
#include "scene/mesh.h"

namespace pt {

// An image of the file, as decoded code values (core/image.h); `name` is unique per file
// and image ("model.glb#/images/0"): the scene keeps one map per name and decoding.
struct GltfImage {
  std::string name;
  LoadedImage image;
};

// A textureInfo: the image, its uv set, sampler and KHR_texture_transform (what
// materials/gltf_map.h packs).
struct GltfTexture {
  std::shared_ptr<const GltfImage> image;  // null: no map
  int tex_coord = 0;                       // after KHR_texture_transform's texCoord
  int wrap_s = 0, wrap_t = 0;              // 0 REPEAT, 1 CLAMP_TO_EDGE, 2 MIRRORED_REPEAT
  bool nearest = false;                    // magFilter NEAREST
  glm::vec2 offset{0.0f}, scale{1.0f};
  float rotation = 0.0f;
  float strength = 1.0f;  // normalTexture.scale
  explicit operator bool() const { return bool(image); }
};

// The metallic-roughness material of a primitive (docs/gltf.md: what becomes of it).
struct GltfMaterial {
  glm::vec3 base_color{1.0f};
  float alpha = 1.0f;
  float metallic = 1.0f;   // glTF defaults
  float roughness = 1.0f;
  glm::vec3 emissive{0.0f};   // emissiveFactor * KHR_materials_emissive_strength
  float ior = 1.5f;           // KHR_materials_ior (0: Fresnel 1)
  float transmission = 0.0f;  // KHR_materials_transmission (thin-walled unless `volume`)
  bool volume = false;        // KHR_materials_volume with thicknessFactor > 0: not thin-walled
  glm::vec3 attenuation_color{1.0f};  // KHR_materials_volume: what a path keeps of itself over
  float attenuation_distance = INFINITY;  //   attenuationDistance inside (default: no absorption)
  int alpha_mode = 0;         // 0 OPAQUE, 1 MASK, 2 BLEND
  float alpha_cutoff = 0.5f;
  bool double_sided = false;
  GltfTexture base_color_map, metallic_roughness_map, normal_map, emissive_map, occlusion_map;
  // KHR_materials_specular, _clearcoat, _sheen (scene/gltf_materials.cpp; materials/gltf_lobes.h)
  float specular = 1.0f;
  glm::vec3 specular_color{1.0f};
  float clearcoat = 0.0f, clearcoat_roughness = 0.0f;
  glm::vec3 sheen_color{0.0f};
  float sheen_roughness = 0.0f;
  GltfTexture specular_map, specular_color_map, clearcoat_map, clearcoat_roughness_map, clearcoat_normal_map, sheen_color_map,
      sheen_roughness_map, transmission_map;
  bool uses_texcoord(int set) const {
    for (const GltfTexture* t : {&base_color_map, &metallic_roughness_map, &normal_map, &emissive_map, &specular_map, &specular_color_map,
                                 &clearcoat_map, &clearcoat_roughness_map, &clearcoat_normal_map, &sheen_color_map, &sheen_roughness_map, &transmission_map})
      if (*t && t->tex_coord == set) return true;
    return false;
  }
};

// A camera node of the default scene (the one of lowest node index: scene/gltf_scene.h
// makes it the scene's camera). Perspective cameras give yfov; an orthographic one is
// reported as such (a path tracer's camera here is a pinhole or thin lens).
struct GltfCamera {
  int node = -1;              // -1: the default scene has no camera node
  glm::mat4 transform{1.0f};  // the node's world transform (the camera looks down its -z, up +y)
  bool perspective = true;
  float yfov = 0.0f;          // radians, in (0, pi)
  // Also for a scene of the file alone: the default scene's KHR_lights_punctual lights,
  // placed and aimed by their nodes (gltf_nodes.cpp; docs/gltf.md for the units).
  std::vector<PunctualLight> lights;
};

struct GltfPart {
  std::shared_ptr<const MeshData> mesh;
  glm::mat4 transform{1.0f};  // object to the file's world space
  GltfMaterial material;
};

// Every other file a glTF names (a buffer or an image by a URI that is not a data: URI)
// goes through the resolver: given the path relative to the glTF file's folder, it returns the
// path to open, or throws InputError to refuse it (the scene loader records it as a
// dependency; the fuzzer refuses every one). An empty resolver refuses them all.
using GltfResolver = std::function<std::string(const std::string& path)>;

// Throw InputError naming the file and where in it: "file.gltf:12:" (JSON syntax),
// "file.glb: byte 20:" (GLB structure) or "file.gltf: /accessors/3:" (a JSON pointer).
// From memory; binary glTF is told from JSON by its magic ("glTF"), not by the name.
// `warnings` (if given) receives one line per file naming the extensions it uses that are
// not supported (their materials fall back to the core material); an unsupported one in
// extensionsRequired is an error naming it.
std::vector<GltfPart> parse_gltf(const std::string& bytes, const std::string& path, const GltfResolver& resolve,
                                 std::vector<std::string>* warnings = nullptr, GltfCamera* camera = nullptr);
// The same, resumable (core/resumable.h; a unit is an element of an accessor, or 1/4096
// of 256 KB of a buffer file). Buffer files are read in slices and a GLB's BIN chunk is
// read where it lies (tinygltf is given neither); what stays one step is tinygltf's parse
// of the JSON and its decoding of base64 data: URIs. `parts` must outlive it.
// `camera` (if given) receives the default scene's first camera node (GltfCamera).
Resumable parse_gltf_steps(std::string bytes, std::string path, GltfResolver resolve, std::vector<GltfPart>& parts,
                           std::vector<std::string>* warnings = nullptr, GltfCamera* camera = nullptr);

}  // namespace pt
