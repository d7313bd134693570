// Procedural meshes, generated at load time instead of read from a file, so that scenes
// (and benchmarks) can hold a million triangles without shipping a large file:
//   <Mesh generate="icosphere" level="8" displace="0.05"> ... </Mesh>
// An icosahedron subdivided `level` times (20 * 4^level triangles: level 8 gives
// 1,310,720), on the unit sphere, pushed along the normal by a deterministic sum of
// waves of relative amplitude `displace`; smooth vertex normals and spherical uv.
#pragma once
#include "core/resumable.h"
#include "scene/mesh.h"

namespace pt {

MeshData generate_icosphere(int level, float displace);
// The same, resumable (core/resumable.h; a unit of work is a triangle or vertex visited);
// `out` must outlive it.
Resumable generate_icosphere_steps(int level, float displace, MeshData& out);

}  // namespace pt
