// Wavefront OBJ meshes: positions, triangulated faces, and vertex normals (vn) and texture
// coordinates (vt) when the faces give them. Read by our own strict reader, in slices;
// triangles and quads are split as tinyobjloader splits them (tested against it), and a
// file with a polygon of more than four corners is triangulated by tinyobjloader's ear
// clipping (Debian's libtinyobjloader-dev, header-only; one step, not sliced).
#pragma once
#include <string>

#include "core/resumable.h"
#include "scene/mesh_json.h"

namespace pt {

MeshData parse_mesh_obj(const std::string& text, const std::string& path);  // reads no other file
// The same, resumable (core/resumable.h; a unit is about a byte of text). `out` must
// outlive it.
Resumable parse_mesh_obj_steps(std::string text, std::string path, MeshData& out);

}  // namespace pt
