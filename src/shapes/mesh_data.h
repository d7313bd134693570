// Triangle meshes as the loaders produce them (object space), shared by every instance
// that places one in the scene (a Mesh shape, shapes/mesh.h, with its own transform).
#pragma once
#include <vector>

#include <glm/glm.hpp>

namespace pt {

struct MeshData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // empty or one per position
  std::vector<glm::vec2> uvs;      // empty or one per position
  std::vector<glm::vec2> uvs1;     // glTF's TEXCOORD_1: empty or one per position
  std::vector<glm::vec4> colors;   // glTF's COLOR_0 (linear RGBA): empty or one per position
  std::vector<glm::uvec3> triangles;
};

}  // namespace pt
