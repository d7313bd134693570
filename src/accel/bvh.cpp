#include "accel/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pt {
namespace {

constexpr int kMaxBins = 64;

struct Task {
  int node, begin, end, depth;
};

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin] go left
  float cost = 3.0e38f;
};

class Builder {
 public:
  Builder(const std::vector<Aabb>& boxes, const BvhBuildOptions& o, Bvh& out) : boxes_(boxes), o_(o), out_(out) {
    const size_t n = boxes.size();
    centers_.resize(n);
    out_.order.resize(n);
    for (size_t i = 0; i < n; ++i) {
      centers_[i] = boxes[i].center();
      out_.order[i] = int(i);
    }
    o_.bins = std::clamp(o_.bins, 2, kMaxBins);
    o_.max_leaf = std::clamp(o_.max_leaf, 1, 16);
    o_.single_leaf_max = std::clamp(o_.single_leaf_max, 1, 16);
  }

  void run() {
    if (boxes_.empty()) return;
    out_.nodes.reserve(2 * boxes_.size() / std::min(o_.max_leaf, 2) + 1);
    out_.nodes.emplace_back();
    if (int(boxes_.size()) <= o_.single_leaf_max) {
      for (const Aabb& b : boxes_) out_.nodes[0].box.grow(b);
      out_.nodes[0].first = 0;
      out_.nodes[0].count = int(boxes_.size());
      out_.depth = 1;
      return;
    }
    std::vector<Task> stack{{0, 0, int(boxes_.size()), 1}};
    while (!stack.empty()) {
      const Task t = stack.back();
      stack.pop_back();
      out_.depth = std::max(out_.depth, t.depth);
      Aabb box, cbox;
      for (int i = t.begin; i < t.end; ++i) {
        const int p = out_.order[size_t(i)];
        box.grow(boxes_[size_t(p)]);
        cbox.grow(centers_[size_t(p)]);
      }
      out_.nodes[size_t(t.node)].box = box;
      const int n = t.end - t.begin;
      int mid = -1;
      if (n > o_.max_leaf && t.depth + levels_below(n) >= o_.max_depth) {
        mid = median_split(t, cbox);  // keeps the depth within max_depth
      } else if (n > 1 && t.depth < o_.max_depth) {
        const Split s = best_split(t, box, cbox);
        const float leaf_cost = float(n);
        if (s.axis >= 0 && (n > o_.max_leaf || s.cost < leaf_cost)) {
          mid = partition(t, cbox, s);
        } else if (s.axis < 0 && n > o_.max_leaf) {
          mid = median_split(t, cbox);  // all centroids coincide: any split is as good
        }
      }
      BvhNode& node = out_.nodes[size_t(t.node)];
      if (mid < 0) {
        node.first = t.begin;
        node.count = n;
        continue;
      }
      const int c = int(out_.nodes.size());
      node.first = c;
      node.count = 0;
      out_.nodes.emplace_back();
      out_.nodes.emplace_back();
      stack.push_back({c + 1, mid, t.end, t.depth + 1});  // the left child is built first
      stack.push_back({c, t.begin, mid, t.depth + 1});
    }
  }

 private:
  // Levels a balanced tree needs below a node of n primitives.
  int levels_below(int n) const {
    int levels = 0;
    for (int leaves = (n + o_.max_leaf - 1) / o_.max_leaf; (1 << levels) < leaves;) ++levels;
    return levels;
  }

  int median_split(const Task& t, const Aabb& cbox) {
    const glm::vec3 e = cbox.hi - cbox.lo;
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const int mid = t.begin + (t.end - t.begin) / 2;
    int* base = out_.order.data();
    std::nth_element(base + t.begin, base + mid, base + t.end,
                     [&](int a, int b) { return centers_[size_t(a)][axis] < centers_[size_t(b)][axis]; });
    return mid;
  }

  // NaN-safe: a centroid below the range (it cannot be) or a NaN lands in bin 0.
  int bin_of(float c, float lo, float scale) const {
    const float f = (c - lo) * scale;
    return f > 0.0f ? std::min(o_.bins - 1, int(std::min(f, float(o_.bins)))) : 0;
  }

  Split best_split(const Task& t, const Aabb& box, const Aabb& cbox) const {
    Split best;
    const glm::vec3 extent = cbox.hi - cbox.lo;
    for (int axis = 0; axis < 3; ++axis) {
      const float lo = cbox.lo[axis], scale = float(o_.bins) / extent[axis];
      if (!(extent[axis] > 0.0f) || !std::isfinite(scale)) continue;
      std::array<Aabb, kMaxBins> bin_box;
      std::array<int, kMaxBins> bin_count{};
      for (int i = t.begin; i < t.end; ++i) {
        const int p = out_.order[size_t(i)];
        const int b = bin_of(centers_[size_t(p)][axis], lo, scale);
        bin_box[size_t(b)].grow(boxes_[size_t(p)]);
        ++bin_count[size_t(b)];
      }
      // Right-to-left sweep of areas and counts, then left-to-right evaluation.
      std::array<float, kMaxBins> right_area{};
      std::array<int, kMaxBins> right_count{};
      Aabb acc;
      int cnt = 0;
      for (int b = o_.bins - 1; b > 0; --b) {
        acc.grow(bin_box[size_t(b)]);
        cnt += bin_count[size_t(b)];
        right_area[size_t(b)] = acc.half_area();
        right_count[size_t(b)] = cnt;
      }
      acc = Aabb{};
      cnt = 0;
      for (int b = 0; b < o_.bins - 1; ++b) {
        acc.grow(bin_box[size_t(b)]);
        cnt += bin_count[size_t(b)];
        if (cnt == 0 || right_count[size_t(b) + 1] == 0) continue;
        const float cost = acc.half_area() * float(cnt) + right_area[size_t(b) + 1] * float(right_count[size_t(b) + 1]);
        if (cost < best.cost) best = Split{axis, b, cost};
      }
    }
    if (best.axis >= 0) {
      const float area = box.half_area();
      best.cost = o_.traversal_cost + (area > 0.0f ? best.cost / area : float(t.end - t.begin));
    }
    return best;
  }

  int partition(const Task& t, const Aabb& cbox, const Split& s) {
    const float lo = cbox.lo[s.axis], scale = float(o_.bins) / (cbox.hi[s.axis] - lo);
    auto* first = out_.order.data() + t.begin;
    auto* mid = std::partition(first, out_.order.data() + t.end,
                               [&](int p) { return bin_of(centers_[size_t(p)][s.axis], lo, scale) <= s.bin; });
    return int(mid - out_.order.data());
  }

  const std::vector<Aabb>& boxes_;
  BvhBuildOptions o_;
  Bvh& out_;
  std::vector<glm::vec3> centers_;
};

}  // namespace

Bvh build_bvh(const std::vector<Aabb>& boxes, const BvhBuildOptions& options) {
  Bvh bvh;
  Builder(boxes, options, bvh).run();
  return bvh;
}

double Bvh::sah_cost(const BvhBuildOptions& o) const {
  if (nodes.empty()) return 0.0;
  const double root = nodes[0].box.half_area();
  double cost = 0.0;
  for (const BvhNode& n : nodes) {
    const double p = root > 0.0 ? n.box.half_area() / root : 1.0;
    cost += p * (n.count > 0 ? double(n.count) : double(o.traversal_cost));
  }
  return cost;
}

}  // namespace pt
