#include "core/metrics.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace pt {

ErrorMetrics image_error(const std::vector<float>& image, const std::vector<float>& reference) {
  const bool constant = reference.size() == 4;
  double rel = 0, sq = 0;
  size_t n = 0;
  for (size_t i = 0; i + 3 < image.size(); i += 4)
    for (size_t c = 0; c < 3; ++c) {
      const double r = constant ? reference[c] : reference[i + c];
      const double d = double(image[i + c]) - r;
      rel += d * d / (r * r + 0.01);
      sq += d * d;
      ++n;
    }
  if (n == 0) return {};
  return {rel / double(n), std::sqrt(sq / double(n))};
}

void ErrorHistory::record(int samples, double diff_mean) {
  if (samples < kFirstPoint || !(diff_mean > 0)) return;
  const double x = std::log(double(samples));
  if (!points_.empty() && !(x > points_.back().first)) return;
  points_.push_back({x, std::log(diff_mean)});
}

double ErrorHistory::exponent(int before) const {
  const double limit = std::log(double(before));
  size_t n = points_.size();
  while (n > 0 && !(points_[n - 1].first < limit)) --n;
  const size_t first = n > 5 ? n - 5 : 0;
  if (n - first < 2) return 1.0;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
  for (size_t i = first; i < n; ++i, ++m) {
    const auto [x, y] = points_[i];
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
  return std::clamp(-slope, 0.5, 3.0);
}

namespace {

ErrorEstimate combine(const std::vector<ErrorSums>& tiles, int tiles_x, int tiles_y, int tile, int samples, bool snap, double exponent,
                      double scale) {
  ErrorEstimate e;
  e.tile = tile;
  e.tiles_x = tiles_x;
  e.tiles_y = tiles_y;
  e.tiles.assign(tiles.size(), 0.0);
  ErrorSums all;
  for (const ErrorSums& t : tiles) all += t;
  if (samples < 2 || all.count <= 0) return e;
  e.known = true;
  e.rel_mse_iid = all.iid / all.count;
  e.exponent = snap ? exponent : 1.0;
  auto of = [&](const ErrorSums& t) { return t.count <= 0 ? 0.0 : (snap ? std::min(t.diff * scale, t.iid) : t.iid) / t.count; };
  e.rel_mse = of(all);
  for (size_t i = 0; i < tiles.size(); ++i) e.tiles[i] = of(tiles[i]);
  return e;
}

}  // namespace

ErrorEstimate combine_error(const std::vector<ErrorSums>& tiles, int tiles_x, int tiles_y, int tile, int samples, int k,
                            double exponent) {
  const bool snap = k > 0 && 2 * k <= samples;
  const double scale = snap ? 1.0 / (std::pow(double(samples) / k, exponent) - 1.0) : 0.0;
  return combine(tiles, tiles_x, tiles_y, tile, samples, snap, exponent, scale);
}

ErrorEstimate combine_error_scaled(const std::vector<ErrorSums>& tiles, int tiles_x, int tiles_y, int tile, int samples, bool snapshot,
                                   double exponent) {
  return combine(tiles, tiles_x, tiles_y, tile, samples, snapshot, exponent, 1.0);
}

BlockGrid BlockGrid::sized(int width, int height, int block) {
  BlockGrid g;
  g.block = block;
  g.width = width;
  g.height = height;
  g.blocks_x = (width + block - 1) / block;
  g.blocks_y = (height + block - 1) / block;
  g.sums.assign(size_t(g.blocks_x) * g.blocks_y, BlockSums{});
  return g;
}

namespace {
float luminance(const float* c) { return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2]; }
}  // namespace

std::vector<float> error_guide(const std::vector<float>& mean, int width, int height) {
  // Luminance in three rolling rows (not a whole image: large fresh allocations cost page
  // faults, which made this the slow part at 1920x1080).
  std::vector<float> guide(size_t(width) * height * 2), rows(size_t(width) * 3);
  auto row_of = [&](int y) { return &rows[size_t((y % 3 + 3) % 3) * width]; };
  auto fill = [&](int y) {
    float* r = row_of(y);
    for (int x = 0; x < width; ++x) r[x] = luminance(&mean[(size_t(y) * width + x) * 4]);
  };
  auto sort2 = [](float& a, float& b) {
    const float lo = std::min(a, b);
    b = std::max(a, b);
    a = lo;
  };
  fill(0);
  if (height > 1) fill(1);
  for (int y = 0; y < height; ++y) {
    if (y + 1 < height && y >= 1) fill(y + 1);
    const float* row[3] = {row_of(std::max(y - 1, 0)), row_of(y), row_of(std::min(y + 1, height - 1))};
    for (int x = 0; x < width; ++x) {
      const int xs[3] = {std::max(x - 1, 0), x, std::min(x + 1, width - 1)};
      float l[9];
      for (int k = 0; k < 9; ++k) l[k] = row[k / 3][xs[k % 3]];
      float most = -1.0f;
      for (int k = 0; k < 9; ++k) {
        const int dx = k % 3 - 1, dy = k / 3 - 1;
        const bool inside = x + dx >= 0 && x + dx < width && y + dy >= 0 && y + dy < height;
        if (k != 4 && inside) most = std::max(most, l[k]);
      }
      // The median of nine, the 19 exchanges of error_guide.glsl (any exact selection agrees).
      sort2(l[1], l[2]), sort2(l[4], l[5]), sort2(l[7], l[8]), sort2(l[0], l[1]), sort2(l[3], l[4]), sort2(l[6], l[7]);
      sort2(l[1], l[2]), sort2(l[4], l[5]), sort2(l[7], l[8]), sort2(l[0], l[3]), sort2(l[5], l[8]), sort2(l[4], l[7]);
      sort2(l[3], l[6]), sort2(l[1], l[4]), sort2(l[2], l[5]), sort2(l[4], l[7]), sort2(l[4], l[2]), sort2(l[6], l[4]);
      sort2(l[4], l[2]);
      guide[(size_t(y) * width + x) * 2] = l[4];
      guide[(size_t(y) * width + x) * 2 + 1] = most;
    }
  }
  return guide;
}

std::vector<FireflyScale> firefly_scales(const std::vector<float>& mean, const std::vector<float>& guide, int width, int height) {
  std::vector<FireflyScale> out;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t p = size_t(y) * width + x;
      const float l = luminance(&mean[p * 4]), g = guide[p * 2];
      if (!(l > kFireflyRatio * g && l >= kFireflyNeighbour * guide[p * 2 + 1])) continue;
      double sum[3] = {0, 0, 0}, n = 0;
      const float tol = kGuideTolerance * (g + kGuideFloor);
      for (int j = std::max(y - kFireflyRadius, 0); j <= std::min(y + kFireflyRadius, height - 1); ++j)
        for (int i = std::max(x - kFireflyRadius, 0); i <= std::min(x + kFireflyRadius, width - 1); ++i) {
          const size_t q = size_t(j) * width + i;
          if (q == p || !(std::abs(guide[q * 2] - g) <= tol)) continue;
          for (int c = 0; c < 3; ++c) sum[c] += mean[q * 4 + c];
          n += 1;
        }
      if (n <= 0) continue;
      FireflyScale f{p, {}};
      for (int c = 0; c < 3; ++c) f.rgb[c] = std::min(mean[p * 4 + c], float(sum[c] / n));
      out.push_back(f);
    }
  return out;
}

std::vector<float> error_scale(const std::vector<float>& mean, const std::vector<float>& guide, int width, int height) {
  std::vector<float> d(mean);
  for (size_t p = 3; p < d.size(); p += 4) d[p] = 0.0f;
  for (const FireflyScale& f : firefly_scales(mean, guide, width, height))
    for (int c = 0; c < 3; ++c) d[f.pixel * 4 + c] = f.rgb[c];
  return d;
}

BlockGrid block_sums(const std::vector<float>& mean, const std::vector<float>& variance,
                     const std::vector<const std::vector<float>*>& snapshots, int width, int height, int block) {
  BlockGrid g = BlockGrid::sized(width, height, block);
  const std::vector<FireflyScale> fireflies = firefly_scales(mean, error_guide(mean, width, height), width, height);
  auto next = fireflies.begin();  // in pixel order, as the loop below
  const size_t ns = std::min(snapshots.size(), size_t(BlockSums::kSnapshots));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t p = (size_t(y) * width + x) * 4;
      BlockSums& b = g.sums[size_t(y / block) * g.blocks_x + x / block];
      const float* scale = &mean[p];
      if (next != fireflies.end() && next->pixel * 4 == p) scale = (next++)->rgb;
      for (int c = 0; c < 3; ++c) {
        const double m = mean[p + c], sc = scale[c], inv = 1.0 / (sc * sc + 0.01);
        b.var += std::max(double(variance[p + c]), 0.0) * inv;
        for (size_t j = 0; j < ns; ++j)
          if (snapshots[j]) {
            const double d = m - (*snapshots[j])[p + c];
            b.diff[j] += d * d * inv;
          }
      }
      b.pixels += 1;
    }
  return g;
}

namespace {

// Each block's tile of `tile` pixels (a multiple of the block) and its lower left pixel.
struct BlockAt {
  int x, y;
  size_t tile;
};
template <class F>
void for_blocks(const BlockGrid& g, int tile, F&& f) {
  const int tx = (g.width + tile - 1) / tile;
  for (int by = 0; by < g.blocks_y; ++by)
    for (int bx = 0; bx < g.blocks_x; ++bx) {
      const int x = bx * g.block, y = by * g.block;
      f(g.sums[size_t(by) * g.blocks_x + bx], BlockAt{x, y, size_t(y / tile) * tx + x / tile});
    }
}

// The latest snapshot with 2 k <= limit at pixel (x, y): its index and k (-1, 0: none).
std::pair<int, int> latest(const std::vector<PixelCounts>& counts, int x, int y, int limit) {
  int j = -1, k = 0;
  for (size_t i = 0; i < counts.size() && i < size_t(BlockSums::kSnapshots); ++i) {
    if (!counts[i].n) continue;
    const int kv = counts[i].at(x, y);
    if (kv > k && 2 * kv <= limit) k = kv, j = int(i);
  }
  return {j, k};
}

int common_block(int a, int b) { return std::gcd(std::max(a, 1), std::max(b, 1)); }

// The per-pixel functions' snapshots as a grid's and their counts.
BlockGrid grid_of(const std::vector<float>& mean, const std::vector<float>* variance, const std::vector<SnapshotView>& views, int width,
                  int height, int block, std::vector<PixelCounts>& counts) {
  std::vector<const std::vector<float>*> images;
  for (const SnapshotView& v : views) {
    images.push_back(v.mean);
    counts.push_back(v.counts);
    block = common_block(block, v.counts.tile);
  }
  const std::vector<float> none(variance ? 0 : mean.size(), 0.0f);
  return block_sums(mean, variance ? *variance : none, images, width, height, block);
}

}  // namespace

std::vector<ErrorSums> error_tiles(const BlockGrid& g, int snapshot, int samples, int tile) {
  const int tx = (g.width + tile - 1) / tile, ty = (g.height + tile - 1) / tile;
  std::vector<ErrorSums> tiles(size_t(tx) * ty);
  for_blocks(g, tile, [&](const BlockSums& b, const BlockAt& at) {
    ErrorSums& t = tiles[at.tile];
    t.count += 3 * b.pixels;
    if (samples < 2) return;
    t.iid += b.var / double(samples - 1);
    if (snapshot >= 0) t.diff += b.diff[snapshot];
  });
  return tiles;
}

double snapshot_exponent(const BlockGrid& g, const std::vector<PixelCounts>& counts, const PixelCounts& now, double fallback) {
  // The counts are per tile, so the ratios n / k1 and n / k2 take few distinct values:
  // the differences are summed per pair of ratios, and the bisection evaluates pow() once
  // per pair, not per pixel (per pixel it took seconds at 1920x1080).
  struct Group {
    double d1 = 0, d2 = 0;
  };
  std::map<std::pair<double, double>, Group> groups;
  double pixels = 0;
  for_blocks(g, g.block, [&](const BlockSums& b, const BlockAt& at) {
    const int n = now.at(at.x, at.y);
    const auto [j1, k1] = latest(counts, at.x, at.y, n);
    if (j1 < 0) return;
    const auto [j2, k2] = latest(counts, at.x, at.y, k1);
    if (j2 < 0) return;
    Group& q = groups[{double(n) / k1, double(n) / k2}];
    q.d1 += b.diff[j1];
    q.d2 += b.diff[j2];
    pixels += b.pixels;
  });
  if (pixels * 8 < double(g.width) * g.height) return fallback;
  auto f = [&](double a) {
    double t1 = 0, t2 = 0;
    for (const auto& [r, q] : groups) {
      t1 += q.d1 / (std::pow(r.first, a) - 1.0);
      t2 += q.d2 / (std::pow(r.second, a) - 1.0);
    }
    return t1 - t2;
  };
  double lo = 0.5, hi = 3.0;
  if (!(f(lo) < 0)) return lo;
  if (!(f(hi) > 0)) return hi;
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

std::vector<ErrorSums> error_tiles(const BlockGrid& g, const std::vector<PixelCounts>& counts, const PixelCounts& now,
                                   double exponent, int tile) {
  const int tx = (g.width + tile - 1) / tile, ty = (g.height + tile - 1) / tile;
  std::vector<ErrorSums> tiles(size_t(tx) * ty);
  for_blocks(g, tile, [&](const BlockSums& b, const BlockAt& at) {
    ErrorSums& t = tiles[at.tile];
    t.count += 3 * b.pixels;
    const int n = now.at(at.x, at.y);
    if (n < 2) return;
    const auto [j, k] = latest(counts, at.x, at.y, n);
    const double iid = b.var / double(n - 1);
    t.iid += iid;
    t.diff += j >= 0 ? b.diff[j] / (std::pow(double(n) / k, exponent) - 1.0) : iid;
  });
  return tiles;
}

std::vector<ErrorSums> error_tiles(const std::vector<float>& mean, const std::vector<float>& variance,
                                   const std::vector<float>* snapshot, int width, int height, int samples, int tile) {
  std::vector<const std::vector<float>*> snaps;
  if (snapshot) snaps.push_back(snapshot);
  return error_tiles(block_sums(mean, variance, snaps, width, height, tile), snapshot ? 0 : -1, samples, tile);
}

double snapshot_exponent(const std::vector<float>& mean, const std::vector<SnapshotView>& snapshots, int width, int height,
                         const PixelCounts& now, double fallback) {
  std::vector<PixelCounts> counts;
  const BlockGrid g = grid_of(mean, nullptr, snapshots, width, height, now.tile, counts);
  return snapshot_exponent(g, counts, now, fallback);
}

std::vector<ErrorSums> error_tiles(const std::vector<float>& mean, const std::vector<float>& variance,
                                   const std::vector<SnapshotView>& snapshots, int width, int height, const PixelCounts& now,
                                   double exponent, int tile) {
  std::vector<PixelCounts> counts;
  const BlockGrid g = grid_of(mean, &variance, snapshots, width, height, common_block(tile, now.tile), counts);
  return error_tiles(g, counts, now, exponent, tile);
}

}  // namespace pt
