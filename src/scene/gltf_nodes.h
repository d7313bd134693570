// The default scene's node tree of a glTF flattened into parts (gltf_nodes.cpp): one per
// mesh primitive per node, with the node's world transform, its MeshData shared by every
// node and primitive that reads the same accessors (instancing).
#pragma once
#include <vector>

#include "core/resumable.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_materials.h"
#include "scene/mesh_gltf.h"

namespace pt::gltf {

// Appends the parts to `parts` (none when the scene has no triangles) and, if `camera` is
// given, sets it to the camera node of lowest index in the tree (its node stays -1 when
// there is none). Resumable (a unit: an element of an accessor); every argument must
// outlive it.
Resumable scene_parts(const tinygltf::Model& model, const Reader& r, Materials& materials, std::vector<GltfPart>& parts,
                      GltfCamera* camera = nullptr);

}  // namespace pt::gltf
