// A binary bounding volume hierarchy built on the CPU with the surface area heuristic
// (binned, Wald 2007), flattened for the GPU: nodes[0] is the root and the two children
// of an interior node are adjacent (nodes[first], nodes[first + 1]), so one step of the
// traversal fetches both children's boxes together. Leaves hold at most kMaxLeaf
// primitives, stored contiguously in `order` (primitive indices in leaf order).
#pragma once
#include <cstdint>
#include <vector>

#include "accel/aabb.h"

namespace pt {

struct BvhNode {
  Aabb box;
  int first = 0;  // interior: index of the first child; leaf: first entry of `order`
  int count = 0;  // 0: interior; > 0: primitives in the leaf
};

struct BvhBuildOptions {
  int bins = 16;            // candidate split planes per axis
  int max_leaf = 8;         // split nodes larger than this
  // A hierarchy of at most this many primitives is one leaf (a plain loop over them).
  // Measured on the H100 for the reference scenes (10 to 15 primitives): 16 made two of
  // three slower (docs/benchmarks.md), so by default only a lone primitive is. The
  // traversal packs a leaf's count in 4 bits: at most 16.
  int single_leaf_max = 1;
  float traversal_cost = 1.0f;  // SAH cost of one node visit, relative to one primitive test
  int max_depth = 64;       // near this depth, object-median splits take over (a bound for the GPU stack)
};

struct Bvh {
  std::vector<BvhNode> nodes;
  std::vector<int> order;
  int depth = 0;  // the longest root-to-leaf path (1 for a lone leaf)
  double sah_cost(const BvhBuildOptions& o = {}) const;  // expected cost per ray, SAH model
};

// Builds over primitives given by their boxes; centroids are the boxes' centres.
// Empty input gives an empty hierarchy (no nodes).
Bvh build_bvh(const std::vector<Aabb>& boxes, const BvhBuildOptions& options = {});

}  // namespace pt
