// Per-tile sample counts (render/adaptive.h).
#include "render/adaptive.h"

#include <algorithm>
#include <cmath>

namespace pt {

std::vector<double> tile_weights(const std::vector<int>& pixels, const std::vector<double>& rel_var, double floor) {
  std::vector<double> w(pixels.size(), 1.0);
  double sum = 0, p = 0;
  for (size_t t = 0; t < pixels.size(); ++t) {
    w[t] = std::sqrt(std::max(rel_var[t], 0.0));
    if (!std::isfinite(w[t])) w[t] = 0.0;
    sum += w[t] * pixels[t];
    p += pixels[t];
  }
  if (!(sum > 0) || !(p > 0)) return std::vector<double>(pixels.size(), 1.0);
  const double least = floor * sum / p;
  for (double& x : w) x = std::max(x, least);
  return w;
}

std::vector<int> allocate_sweep(const std::vector<int>& pixels, const std::vector<int>& counts, const std::vector<double>& weights,
                                double budget, int max_spp, std::vector<double>& credit) {
  const size_t n = pixels.size();
  std::vector<int> spp(n, 0);
  if (!(budget > 0) || n == 0) return spp;
  double have = 0, wsum = 0;
  for (size_t t = 0; t < n; ++t) {
    have += double(pixels[t]) * counts[t];
    wsum += double(pixels[t]) * weights[t];
  }
  // The targets after this sweep, n*_t = w_t (N + B) / sum P w, and what each tile lacks:
  // sum_t P_t (n*_t - n_t) = B, so the positive parts add up to at least the budget.
  std::vector<double> lack(n, 0.0), x(n, 0.0);
  for (size_t t = 0; t < n; ++t) lack[t] = std::max(0.0, weights[t] * (have + budget) / wsum - counts[t]);
  // Share the budget in proportion to the lack; a tile at max_spp gives its excess to the others.
  std::vector<bool> capped(n, false);
  double left = budget;
  for (int round = 0; round < 8 && left > 1e-9 * budget; ++round) {
    double d = 0;
    for (size_t t = 0; t < n; ++t)
      if (!capped[t]) d += pixels[t] * lack[t];
    if (!(d > 0)) {  // nobody lacks anything (rounding): the rest goes uniformly to the uncapped
      for (size_t t = 0; t < n; ++t) lack[t] = capped[t] ? 0.0 : 1.0;
      d = 0;
      for (size_t t = 0; t < n; ++t) d += pixels[t] * lack[t];
      if (!(d > 0)) break;
    }
    const double k = left / d;
    left = 0;
    for (size_t t = 0; t < n; ++t) {
      if (capped[t]) continue;
      x[t] += lack[t] * k;
      if (x[t] >= max_spp) {
        left += (x[t] - max_spp) * pixels[t];
        x[t] = max_spp;
        capped[t] = true;
      }
    }
  }
  for (size_t t = 0; t < n; ++t) {
    const double v = x[t] + credit[t];
    spp[t] = std::clamp(int(std::floor(v)), 0, max_spp);
    credit[t] = v - spp[t];
  }
  return spp;
}

std::vector<int> dispatch_order(const std::vector<int>& plan, int chunks) {
  std::vector<int> order(plan.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return plan[size_t(a)] > plan[size_t(b)]; });
  const size_t k = size_t(std::max(1, chunks));
  if (k == 1) return order;
  std::vector<std::vector<int>> dealt(k);
  for (size_t i = 0; i < order.size(); ++i) {
    const size_t round = i / k, j = i % k;
    dealt[round % 2 ? k - 1 - j : j].push_back(order[i]);
  }
  std::vector<int> out;
  out.reserve(order.size());
  for (const std::vector<int>& d : dealt) out.insert(out.end(), d.begin(), d.end());
  return out;
}

void TileCounts::reset(int width, int height, int tile) {
  tile_ = tile;
  tiles_x_ = (width + tile - 1) / tile;
  tiles_y_ = (height + tile - 1) / tile;
  pixels_.assign(size_t(tiles_x_) * tiles_y_, 0);
  for (int ty = 0; ty < tiles_y_; ++ty)
    for (int tx = 0; tx < tiles_x_; ++tx)
      pixels_[size_t(ty) * tiles_x_ + tx] = (std::min(width, (tx + 1) * tile) - tx * tile) * (std::min(height, (ty + 1) * tile) - ty * tile);
  restart();
}

void TileCounts::restart() {
  counts_.assign(pixels_.size(), 0);
  plan_.assign(pixels_.size(), 0);
  weights_.assign(pixels_.size(), 1.0);
  credit_.assign(pixels_.size(), 0.0);
  total_ = 0;
}

const std::vector<int>& TileCounts::plan(int spp, bool uniform, int max_spp) {
  if (uniform) {
    plan_.assign(pixels_.size(), spp);
  } else {
    double p = 0;
    for (int x : pixels_) p += x;
    plan_ = allocate_sweep(pixels_, counts_, weights_, double(spp) * p, std::max(max_spp, spp), credit_);
  }
  return plan_;
}

void TileCounts::commit() {
  for (size_t t = 0; t < counts_.size(); ++t) {
    counts_[t] += plan_[t];
    total_ += double(plan_[t]) * pixels_[t];
  }
}

bool TileCounts::uniform() const {
  for (int c : counts_)
    if (c != counts_.front()) return false;
  return true;
}

}  // namespace pt
