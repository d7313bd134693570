// The seed's JSON mesh format: {"vertex": [x, y, z, ...], "normal": [...], "uv": [u, v,
// ...], "indices": [i0, i1, i2, ...]} (see scenes/reference/cube.json). Read strictly:
// errors name the file and line; sizes and indices are checked.
#pragma once
#include <string>
#include <vector>

#include "scene/mesh.h"

namespace pt {

MeshData parse_mesh_json(const std::string& text, const std::string& path);

}  // namespace pt
