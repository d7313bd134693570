#include "accel/bvh_wide.h"

#include <algorithm>

namespace pt {

WideBvh collapse_to_wide(const Bvh& bvh) {
  WideBvh w;
  if (bvh.nodes.empty()) return w;
  auto slot_of = [&](int b) {
    WideChild c;
    c.box = bvh.nodes[size_t(b)].box;
    c.first = bvh.nodes[size_t(b)].first;
    c.count = bvh.nodes[size_t(b)].count;
    return c;
  };
  w.nodes.emplace_back();
  if (bvh.nodes[0].count > 0) {  // a lone leaf: one child under the root
    w.nodes[0].child[0] = slot_of(0);
    w.depth = 1;
    return w;
  }
  struct Task {
    int binary, wide, depth, pushed;  // pushed: stack entries held when this node is reached
  };
  std::vector<Task> tasks{{0, 0, 1, 0}};
  while (!tasks.empty()) {
    const Task t = tasks.back();
    tasks.pop_back();
    w.depth = std::max(w.depth, t.depth);
    // The binary node's children, each replaced by its two children when interior.
    std::array<int, 4> src{};
    int k = 0;
    const int first = bvh.nodes[size_t(t.binary)].first;
    for (int c = first; c < first + 2; ++c) {
      const BvhNode& n = bvh.nodes[size_t(c)];
      if (n.count > 0) {
        src[size_t(k++)] = c;
      } else {
        src[size_t(k++)] = n.first;
        src[size_t(k++)] = n.first + 1;
      }
    }
    w.stack_need = std::max(w.stack_need, t.pushed + k - 1);
    for (int i = 0; i < k; ++i) {
      WideChild c = slot_of(src[size_t(i)]);
      if (c.count == 0) {
        c.first = int(w.nodes.size());
        w.nodes.emplace_back();
        tasks.push_back({src[size_t(i)], c.first, t.depth + 1, t.pushed + k - 1});
      }
      w.nodes[size_t(t.wide)].child[size_t(i)] = c;
    }
  }
  return w;
}

}  // namespace pt
