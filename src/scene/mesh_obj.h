// Wavefront OBJ meshes, read with tinyobjloader (Debian's libtinyobjloader-dev, used
// header-only): positions, triangulated faces, and vertex normals (vn) and texture
// coordinates (vt) when the faces give them.
#pragma once
#include <string>

#include "scene/mesh_json.h"

namespace pt {

MeshData load_mesh_obj(const std::string& path);  // throws InputError naming the file
MeshData parse_mesh_obj(const std::string& text, const std::string& path);  // reads no other file

}  // namespace pt
