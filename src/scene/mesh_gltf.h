// glTF 2.0 (.gltf with its buffers, or .glb), read with tinygltf (Debian's
// libtinygltf-dev, used header-only): the default scene's node tree flattened into parts,
// one per mesh primitive per node, each with its node's world transform. A primitive used
// by several nodes is one MeshData shared by all of them (instancing).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh.h"

namespace pt {

// The metallic-roughness material of a primitive, as far as our materials model it.
struct GltfMaterial {
  glm::vec3 base_color{1.0f};
  float metallic = 1.0f;   // glTF defaults
  float roughness = 1.0f;
  glm::vec3 emissive{0.0f};
  float ior = 1.5f;
  float transmission = 0.0f;  // KHR_materials_transmission
};

struct GltfPart {
  std::shared_ptr<const MeshData> mesh;
  glm::mat4 transform{1.0f};  // object to the file's world space
  GltfMaterial material;
};

std::vector<GltfPart> load_gltf(const std::string& path);  // throws InputError naming the file

}  // namespace pt
