// Motion blur in the BVH (render/packing.h: sweep_bvh). A moving primitive enters the
// build with its box at time 0. Bottom-up, a node whose primitives all belong to one
// moving shape keeps that box and is marked with the shape: its box moves with it
// (bvh.glsl translates the ray by -velocity * t before testing it, as the primitives are
// tested), so a moving mesh's hierarchy is as tight as a still one's. Any other node's
// box is made to hold its primitives at every time of the shutter: a marked child's box
// swept over [0, motion_bound] (the union of its boxes at the two ends, exact for a
// translation), a still or mixed child's as it is. (pbrt-v4 bounds an animated primitive
// over the whole shutter, AnimatedTransform::MotionBounds; a marked subtree is the
// per-instance ray offset of a two-level hierarchy, without the second level.)
#include "render/packing.h"

namespace pt {

Aabb swept_box(const Aabb& b, glm::vec3 velocity, float motion_bound) {
  Aabb s = b;
  s.grow(Aabb{b.lo + velocity * motion_bound, b.hi + velocity * motion_bound});
  return s;
}

std::vector<int> sweep_bvh(Bvh& bvh, const std::vector<Aabb>& boxes, const std::vector<int>& mover,
                           const std::vector<glm::vec3>& velocity, float motion_bound) {
  constexpr int kMixed = -2;
  std::vector<int> g(bvh.nodes.size(), -1);
  // A box of group gr (-1: still; >= 0: moving shape gr, at time 0) at every time.
  auto all_times = [&](const Aabb& b, int gr) { return gr >= 0 ? swept_box(b, velocity[size_t(gr)], motion_bound) : b; };
  for (size_t n = bvh.nodes.size(); n-- > 0;) {  // children come after their parent
    BvhNode& node = bvh.nodes[n];
    int gn;
    if (node.count > 0) {
      gn = mover[size_t(bvh.order[size_t(node.first)])];
      for (int i = node.first; i < node.first + node.count; ++i)
        if (mover[size_t(bvh.order[size_t(i)])] != gn) gn = kMixed;
      if (gn == kMixed) {
        Aabb b;
        for (int i = node.first; i < node.first + node.count; ++i) {
          const int prim = bvh.order[size_t(i)];
          b.grow(all_times(boxes[size_t(prim)], mover[size_t(prim)]));
        }
        node.box = b;
      }
    } else {
      const int a = g[size_t(node.first)], c = g[size_t(node.first) + 1];
      gn = a == c ? a : kMixed;
      if (gn == kMixed) {
        Aabb b = all_times(bvh.nodes[size_t(node.first)].box, a);
        b.grow(all_times(bvh.nodes[size_t(node.first) + 1].box, c));
        node.box = b;
      }
    }
    g[n] = gn;
  }
  for (int& x : g) x = std::max(x, -1);
  return g;
}

void PackJob::init_motion(size_t prims) {
  for (const Shape& s : scene_.shapes)
    if (info(s.kind()).bvh != BvhRole::Unbounded && velocity(s.params) != glm::vec3(0.0f)) {
      for (const Shape& t : scene_.shapes) velocity_.push_back(velocity(t.params));
      mover_.reserve(prims);
      return;
    }
}

// A bounded primitive's box: with motion, at time 0 for a moving shape the nodes can be
// marked with (sweep_bvh), else over the shutter.
void PackJob::add_box(int shape, const Aabb& at0, const Aabb& all_times) {
  if (velocity_.empty()) return boxes_.push_back(all_times);
  const bool marked = velocity_[size_t(shape)] != glm::vec3(0.0f) && shape <= kMaxMover;
  boxes_.push_back(marked ? at0 : all_times);
  mover_.push_back(marked ? shape : -1);
}

}  // namespace pt
