// Wavefront OBJ meshes, read with tinyobjloader (Debian's libtinyobjloader-dev, used
// header-only): positions, triangulated faces, and vertex normals (vn) and texture
// coordinates (vt) when the faces give them.
#pragma once
#include <string>

#include "core/resumable.h"
#include "scene/mesh_json.h"

namespace pt {

MeshData load_mesh_obj(const std::string& path);  // throws InputError naming the file
MeshData parse_mesh_obj(const std::string& text, const std::string& path);  // reads no other file
// The same, resumable (core/resumable.h; a unit is about a byte of text). Our strict
// check of the text and the conversion to MeshData are sliced; tinyobjloader's parse
// between them is one step. `out` must outlive it.
Resumable parse_mesh_obj_steps(std::string text, std::string path, MeshData& out);

}  // namespace pt
