#include "accel/bvh.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace pt {

BvhBuilder::BvhBuilder(const std::vector<Aabb>& boxes, const BvhBuildOptions& o) : boxes_(boxes), o_(o) {
  const size_t n = boxes.size();
  o_.bins = std::clamp(o_.bins, 2, kMaxBins);
  o_.max_leaf = std::clamp(o_.max_leaf, 1, 16);
  o_.single_leaf_max = std::clamp(o_.single_leaf_max, 1, 16);
  // Filled by the sliced set-up: writing them here, in one step, touched 20 MB of fresh
  // pages for a million boxes (100 ms where page faults are slow).
  centers_.reserve(n);
  out_.order.reserve(n);
  if (boxes_.empty()) {
    phase_ = Phase::Done;
    return;
  }
  if (int(n) <= o_.single_leaf_max) {
    out_.nodes.emplace_back();
    for (size_t i = 0; i < n; ++i) {
      out_.order.push_back(int(i));
      out_.nodes[0].box.grow(boxes_[i]);
    }
    out_.nodes[0].first = 0;
    out_.nodes[0].count = int(n);
    out_.depth = 1;
    placed_ = long(n);
    phase_ = Phase::Done;
    return;
  }
  phase_ = Phase::Setup;  // the centroids, in slices too: a million boxes take a while
}
double BvhBuilder::progress() const {
  return boxes_.empty() ? 1.0 : double(placed_) / double(boxes_.size());
}

Bvh BvhBuilder::take() { return std::move(out_); }

bool BvhBuilder::run(long work) {
  // Each loop below stops when the work is spent and resumes where it stood: the order of
  // every grow, swap and push is that of an uninterrupted run.
  auto stop_at = [&](int end) { return i_ + int(std::min<long>(end - i_, work)); };
  const long given = work;
  while (work > 0 && phase_ != Phase::Done) {
    switch (phase_) {
      case Phase::Setup: {
        const int start = i_, stop = stop_at(int(boxes_.size()));
        for (; i_ < stop; ++i_) {
          centers_.push_back(boxes_[size_t(i_)].center());
          out_.order.push_back(i_);
        }
        work -= stop - start;
        if (i_ < int(boxes_.size())) break;
        out_.nodes.reserve(2 * boxes_.size() - 1);  // every binary tree over n leaves-or-fewer: no reallocation (it copied 40 MB in one slice)
        out_.nodes.emplace_back();
        stack_.push_back({0, 0, int(boxes_.size()), 1});
        phase_ = Phase::Next;
        break;
      }
      case Phase::Next: {
        if (stack_.empty()) {
          phase_ = Phase::Done;
          break;
        }
        t_ = stack_.back();
        stack_.pop_back();
        out_.depth = std::max(out_.depth, t_.depth);
        box_ = cbox_ = Aabb{};
        i_ = t_.begin;
        phase_ = Phase::Bounds;
        --work;
        break;
      }
      case Phase::Bounds: {
        const int start = i_, stop = stop_at(t_.end);
        for (; i_ < stop; ++i_) {
          const int p = out_.order[size_t(i_)];
          box_.grow(boxes_[size_t(p)]);
          cbox_.grow(centers_[size_t(p)]);
        }
        work -= stop - start;
        if (i_ == t_.end) after_bounds();
        break;
      }
      case Phase::Bins: {
        // The three axes in one pass over the range; each bin still grows in range order.
        const int start = i_, stop = stop_at(t_.end);
        for (; i_ < stop; ++i_) {
          const int p = out_.order[size_t(i_)];
          for (int axis = 0; axis < 3; ++axis) {
            if (!axis_ok_[axis]) continue;
            const int b = bin_of(centers_[size_t(p)][axis], bin_lo_[axis], bin_scale_[axis]);
            bin_box_[axis][b].grow(boxes_[size_t(p)]);
            ++bin_count_[axis][b];
          }
        }
        work -= stop - start;
        if (i_ == t_.end) after_bins();
        break;
      }
      case Phase::Partition: {
        // std::partition's walk (libstdc++'s, for bidirectional iterators), one step at a
        // time: from the front while the predicate holds, then from the back while it does
        // not, then a swap.
        const float lo = bin_lo_[split_axis_], scale = bin_scale_[split_axis_];
        auto left = [&](int at) {
          return bin_of(centers_[size_t(out_.order[size_t(at)])][split_axis_], lo, scale) <= split_bin_;
        };
        while (work > 0) {
          if (first_ == last_) {
            finish(first_);
            break;
          }
          --work;
          if (scan_front_) {
            if (left(first_)) {
              ++first_;
            } else {
              scan_front_ = false;
              --last_;
              ++work;  // the step to the back end inspects nothing
            }
          } else if (!left(last_)) {
            --last_;
          } else {
            std::swap(out_.order[size_t(first_)], out_.order[size_t(last_)]);
            ++first_;
            scan_front_ = true;
          }
        }
        break;
      }
      case Phase::Done: break;
    }
  }
  work_done_ += given - work;
  return phase_ == Phase::Done;
}

void BvhBuilder::after_bounds() {
  out_.nodes[size_t(t_.node)].box = box_;
  const int n = t_.end - t_.begin;
  if (n > o_.max_leaf && t_.depth + levels_below(n) >= o_.max_depth) return finish(median_split());  // keeps the depth within max_depth
  if (!(n > 1 && t_.depth < o_.max_depth)) return finish(-1);
  const glm::vec3 extent = cbox_.hi - cbox_.lo;
  for (int axis = 0; axis < 3; ++axis) {
    bin_lo_[axis] = cbox_.lo[axis];
    bin_scale_[axis] = float(o_.bins) / extent[axis];
    axis_ok_[axis] = extent[axis] > 0.0f && std::isfinite(bin_scale_[axis]);
    for (int b = 0; b < o_.bins; ++b) {
      bin_box_[axis][b] = Aabb{};
      bin_count_[axis][b] = 0;
    }
  }
  i_ = t_.begin;
  phase_ = Phase::Bins;
}

void BvhBuilder::after_bins() {
  // Per axis, a right-to-left sweep of areas and counts, then left-to-right evaluation.
  float best_cost = 3.0e38f;
  split_axis_ = -1;
  for (int axis = 0; axis < 3; ++axis) {
    if (!axis_ok_[axis]) continue;
    float right_area[kMaxBins] = {};
    int right_count[kMaxBins] = {};
    Aabb acc;
    int cnt = 0;
    for (int b = o_.bins - 1; b > 0; --b) {
      acc.grow(bin_box_[axis][b]);
      cnt += bin_count_[axis][b];
      right_area[b] = acc.half_area();
      right_count[b] = cnt;
    }
    acc = Aabb{};
    cnt = 0;
    for (int b = 0; b < o_.bins - 1; ++b) {
      acc.grow(bin_box_[axis][b]);
      cnt += bin_count_[axis][b];
      if (cnt == 0 || right_count[b + 1] == 0) continue;
      const float cost = acc.half_area() * float(cnt) + right_area[b + 1] * float(right_count[b + 1]);
      if (cost < best_cost) {
        best_cost = cost;
        split_axis_ = axis;
        split_bin_ = b;
      }
    }
  }
  const int n = t_.end - t_.begin;
  if (split_axis_ >= 0) {
    const float area = box_.half_area();
    const float cost = o_.traversal_cost + (area > 0.0f ? best_cost / area : float(n));
    if (n > o_.max_leaf || cost < float(n)) {  // splitting beats a leaf (or the leaf would be too big)
      first_ = t_.begin;
      last_ = t_.end;
      scan_front_ = true;
      phase_ = Phase::Partition;
      return;
    }
    return finish(-1);
  }
  finish(n > o_.max_leaf ? median_split() : -1);  // all centroids coincide: any split is as good
}

void BvhBuilder::finish(int mid) {
  BvhNode& node = out_.nodes[size_t(t_.node)];
  phase_ = Phase::Next;
  if (mid < 0) {
    node.first = t_.begin;
    node.count = t_.end - t_.begin;
    placed_ += node.count;
    return;
  }
  const int c = int(out_.nodes.size());
  node.first = c;
  node.count = 0;
  out_.nodes.emplace_back();
  out_.nodes.emplace_back();
  stack_.push_back({c + 1, mid, t_.end, t_.depth + 1});  // the left child is built first
  stack_.push_back({c, t_.begin, mid, t_.depth + 1});
}

// Levels a balanced tree needs below a node of n primitives.
int BvhBuilder::levels_below(int n) const {
  int levels = 0;
  for (int leaves = (n + o_.max_leaf - 1) / o_.max_leaf; (1 << levels) < leaves;) ++levels;
  return levels;
}

// One step (not sliced): it runs only near the depth bound, where ranges are small, or
// when every centroid of a range coincides.
int BvhBuilder::median_split() {
  const glm::vec3 e = cbox_.hi - cbox_.lo;
  const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
  const int mid = t_.begin + (t_.end - t_.begin) / 2;
  int* base = out_.order.data();
  std::nth_element(base + t_.begin, base + mid, base + t_.end,
                   [&](int a, int b) { return centers_[size_t(a)][axis] < centers_[size_t(b)][axis]; });
  return mid;
}

// NaN-safe: a centroid below the range (it cannot be) or a NaN lands in bin 0.
int BvhBuilder::bin_of(float c, float lo, float scale) const {
  const float f = (c - lo) * scale;
  return f > 0.0f ? std::min(o_.bins - 1, int(std::min(f, float(o_.bins)))) : 0;
}

Bvh build_bvh(const std::vector<Aabb>& boxes, const BvhBuildOptions& options) {
  BvhBuilder b(boxes, options);
  while (!b.run(LONG_MAX)) {  // (long is 32 bits in wasm)
  }
  return b.take();
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
