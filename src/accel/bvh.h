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
// Empty input gives an empty hierarchy (no nodes). Runs a BvhBuilder to completion.
Bvh build_bvh(const std::vector<Aabb>& boxes, const BvhBuildOptions& options = {});

// The same build, resumable, so that a page can build a large hierarchy a few
// milliseconds per animation frame: run(work) does at most about `work` units (one unit:
// one primitive visited by one of the loops over a node's range) and returns true once
// the hierarchy is complete. An explicit stack of node ranges, and every loop over a
// range (bounds, binning, partition) resumable at any primitive: the result does not
// depend on how the work was sliced (bit for bit, tested). `boxes` must outlive it.
class BvhBuilder {
 public:
  BvhBuilder(const std::vector<Aabb>& boxes, const BvhBuildOptions& options = {});
  BvhBuilder(const BvhBuilder&) = delete;
  BvhBuilder& operator=(const BvhBuilder&) = delete;
  bool run(long work);
  bool done() const { return phase_ == Phase::Done; }
  long work_done() const { return work_done_; }  // units spent so far
  double progress() const;  // the fraction of primitives placed in leaves
  Bvh take();               // once done(): the hierarchy (the builder is then spent)

 private:
  static constexpr int kMaxBins = 64;
  enum class Phase { Setup, Next, Bounds, Bins, Partition, Done };
  struct Task {
    int node, begin, end, depth;
  };
  void after_bounds();
  void after_bins();
  void finish(int mid);  // mid < 0: a leaf; else children [begin, mid) and [mid, end)
  int median_split();
  int levels_below(int n) const;
  int bin_of(float c, float lo, float scale) const;

  const std::vector<Aabb>& boxes_;
  BvhBuildOptions o_;
  Bvh out_;
  std::vector<glm::vec3> centers_;
  std::vector<Task> stack_;
  Phase phase_ = Phase::Setup;
  long placed_ = 0, work_done_ = 0;
  // The node in progress: its range and where each loop stands.
  Task t_{};
  int i_ = 0;          // set-up: the next box; bounds and binning: the next entry of the range
  Aabb box_, cbox_;    // its box, and the box of its primitives' centroids
  bool axis_ok_[3] = {false, false, false};
  float bin_lo_[3] = {0, 0, 0}, bin_scale_[3] = {0, 0, 0};
  Aabb bin_box_[3][kMaxBins];
  int bin_count_[3][kMaxBins] = {};
  int split_axis_ = -1, split_bin_ = 0;
  int first_ = 0, last_ = 0;  // the partition's two ends (std::partition's two-pointer walk)
  bool scan_front_ = true;
};

}  // namespace pt
