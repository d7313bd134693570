#include "scene/mesh_obj.h"

#include <cmath>

#define TINYOBJLOADER_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <tiny_obj_loader.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include "core/error.h"

namespace pt {

MeshData load_mesh_obj(const std::string& path) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    std::string why = reader.Error();
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    throw InputError(path, 0, why.empty() ? "cannot read the OBJ file" : why);
  }
  const tinyobj::attrib_t& a = reader.GetAttrib();
  MeshData m;
  for (size_t i = 0; i + 2 < a.vertices.size(); i += 3) {
    const glm::vec3 p(a.vertices[i], a.vertices[i + 1], a.vertices[i + 2]);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError(path, 0, "vertex " + std::to_string(i / 3 + 1) + " is not finite");
    m.positions.push_back(p);
  }
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& idx = shape.mesh.indices;
    for (size_t f = 0; f + 2 < idx.size(); f += 3) {
      glm::uvec3 tri;
      for (int k = 0; k < 3; ++k) {
        const int v = idx[f + size_t(k)].vertex_index;
        if (v < 0 || size_t(v) >= m.positions.size())
          throw InputError(path, 0, "face " + std::to_string(f / 3 + 1) + " refers to a missing vertex");
        tri[k] = unsigned(v);
      }
      m.triangles.push_back(tri);
    }
  }
  if (m.triangles.empty()) throw InputError(path, 0, "no faces");
  return m;
}

}  // namespace pt
