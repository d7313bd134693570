// Scene -> the record buffers of render/records.h, including the BVH over every bounded
// primitive (accel/bvh.h) and the primitives in its leaf order.
#pragma once
#include "accel/bvh.h"
#include "render/records.h"
#include "scene/scene.h"

namespace pt {

struct PackedScene {
  RecordBuffer shapes{shape_rec::kTexels};
  RecordBuffer materials{material_rec::kTexels};
  RecordBuffer lights{light_rec::kTexels};
  RecordBuffer nodes{node_rec::kTexels};
  RecordBuffer prims{prim_rec::kTexels};
  RecordBuffer vertices{vertex_rec::kTexels};
  int unbounded = 0;  // prims [0, unbounded) lie outside the BVH (planes): every ray tests them
  int bvh_depth = 0;
  float motion_bound = 0.0f;  // moving spheres are bounded over times [0, motion_bound]
  double bvh_build_ms = 0.0;
};

// The traversal's stack holds at most depth - 1 entries: hierarchies deeper than this are
// rebuilt with median splits below that depth (see build_bvh's max_depth).
inline constexpr int kBvhStackSize = 48;

PackedScene pack_scene(const Scene& scene);

// World-space vertices of a mesh instance's triangle.
void mesh_triangle(const Scene& scene, const Shape& s, size_t tri, glm::vec3 out[3]);

}  // namespace pt
