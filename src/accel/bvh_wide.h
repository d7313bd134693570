// The traversal's hierarchy: the binary SAH BVH (accel/bvh.h) collapsed to 4-wide nodes.
// A wide node is an interior binary node with its children replaced by their own
// children where those are interior (Wald et al., "Getting Rid of Packets", 2008, and the
// n-ary BVHs of GPU ray tracers): up to four boxes tested per traversal step, half the
// steps and pushes of the binary walk, the same leaves and primitive order.
#pragma once
#include <array>
#include <vector>

#include "accel/bvh.h"

namespace pt {

struct WideChild {
  Aabb box;
  int first = 0;   // interior: index of its wide node; leaf: first entry of Bvh::order
  int count = -1;  // -1: empty slot; 0: interior; > 0: primitives in the leaf
};

struct WideNode {
  std::array<WideChild, 4> child;
};

struct WideBvh {
  std::vector<WideNode> nodes;  // nodes[0] is the root; empty for an empty hierarchy
  int depth = 0;       // wide nodes on the longest root-to-leaf path
  int stack_need = 0;  // most entries a nearest-first traversal ever holds on its stack
};

// A binary hierarchy of depth D (BvhNode levels, root = 1) collapses to at most floor(D/2)
// wide levels, and each step pushes at most 3 entries: stack_need <= 3 * floor(D / 2).
WideBvh collapse_to_wide(const Bvh& bvh);

}  // namespace pt
