// The seed's JSON mesh format: {"vertex": [x, y, z, ...], "normal": [...], "uv": [u, v,
// ...], "indices": [i0, i1, i2, ...]} (see scenes/reference/cube.json). Read strictly:
// errors name the file and line; sizes and indices are checked.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace pt {

struct MeshData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // empty or one per position
  std::vector<glm::vec2> uvs;      // empty or one per position
  std::vector<glm::uvec3> triangles;
};

MeshData parse_mesh_json(const std::string& text, const std::string& path);
MeshData load_mesh_json(const std::string& path);  // throws InputError

}  // namespace pt
