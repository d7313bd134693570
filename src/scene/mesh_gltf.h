// glTF 2.0 (.gltf with its buffers, or .glb), read with tinygltf (Debian's
// libtinygltf-dev, used header-only): the default scene's node tree flattened into parts,
// one per mesh primitive per node, each with its node's world transform. A primitive used
// by several nodes is one MeshData shared by all of them (instancing).
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"
#include "core/resumable.h"
#include "scene/mesh.h"

namespace pt {

// An image of the file, as decoded code values (core/image.h); `name` is unique per file
// and image ("model.glb#/images/0"): the scene keeps one map per name and decoding.
struct GltfImage {
  std::string name;
  LoadedImage image;
};

// The metallic-roughness material of a primitive, as far as our materials model it.
// The maps are those of TEXCOORD_0 (docs/scene-format.md says what becomes of them).
struct GltfMaterial {
  glm::vec3 base_color{1.0f};
  float metallic = 1.0f;   // glTF defaults
  float roughness = 1.0f;
  glm::vec3 emissive{0.0f};
  float ior = 1.5f;
  float transmission = 0.0f;  // KHR_materials_transmission
  std::shared_ptr<const GltfImage> base_color_map, metallic_roughness_map, normal_map;
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
std::vector<GltfPart> parse_gltf(const std::string& bytes, const std::string& path, const GltfResolver& resolve);
// The same, resumable (core/resumable.h; a unit is an element of an accessor, or 1/4096
// of 256 KB of a buffer file). Buffer files are read in slices and a GLB's BIN chunk is
// read where it lies (tinygltf is given neither); what stays one step is tinygltf's parse
// of the JSON and its decoding of base64 data: URIs. `parts` must outlive it.
Resumable parse_gltf_steps(std::string bytes, std::string path, GltfResolver resolve, std::vector<GltfPart>& parts);

}  // namespace pt
