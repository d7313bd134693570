#include "core/metrics.h"

#include <algorithm>
#include <cmath>
#include <map>

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

ErrorSums error_terms(double mean, double variance, int samples, double snapshot) {
  ErrorSums e;
  e.count = 1;
  if (samples < 2) return e;
  const double v = std::max(variance, 0.0) / double(samples - 1);
  const double den = mean * mean + 0.01;
  e.iid = v / den;
  e.diff = (mean - snapshot) * (mean - snapshot) / den;
  return e;
}

void ErrorHistory::record(int samples, double diff_mean) {
  if (samples < 4 || !(diff_mean > 0)) return;
  const double x = std::log(double(samples));
  if (!points_.empty() && !(x > points_.back().first)) return;
  points_.push_back({x, std::log(diff_mean)});
}

double ErrorHistory::exponent() const {
  const size_t n = points_.size(), first = n > 5 ? n - 5 : 0;
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

std::vector<ErrorSums> error_tiles(const std::vector<float>& mean, const std::vector<float>& variance,
                                   const std::vector<float>* snapshot, int width, int height, int samples, int tile) {
  const int tx = (width + tile - 1) / tile, ty = (height + tile - 1) / tile;
  std::vector<ErrorSums> tiles(size_t(tx) * ty);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t p = (size_t(y) * width + x) * 4;
      ErrorSums& t = tiles[size_t(y / tile) * tx + x / tile];
      for (int c = 0; c < 3; ++c) t += error_terms(mean[p + c], variance[p + c], samples, snapshot ? (*snapshot)[p + c] : 0.0);
    }
  return tiles;
}

double snapshot_exponent(const std::vector<float>& mean, const std::vector<SnapshotView>& snapshots, int width, int height,
                         const PixelCounts& now, double fallback) {
  // The counts are per tile, so the ratios n / k1 and n / k2 take few distinct values:
  // the differences are summed per pair of ratios, and the bisection evaluates pow() once
  // per pair, not per pixel (per pixel it took seconds at 1920x1080).
  struct Group {
    double d1 = 0, d2 = 0;
  };
  std::map<std::pair<double, double>, Group> groups;
  Group* last = nullptr;
  int last_n = -1, last_k1 = -1, last_k2 = -1;
  size_t pixels = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int n = now.at(x, y);
      int k1 = 0, k2 = 0;
      const std::vector<float>*s1 = nullptr, *s2 = nullptr;
      for (const SnapshotView& v : snapshots) {
        const int k = v.counts.at(x, y);
        if (k > k1 && 2 * k <= n) k1 = k, s1 = v.mean;
      }
      for (const SnapshotView& v : snapshots) {
        const int k = v.counts.at(x, y);
        if (k > k2 && 2 * k <= k1) k2 = k, s2 = v.mean;
      }
      if (!s1 || !s2) continue;
      const size_t p = (size_t(y) * width + x) * 4;
      if (n != last_n || k1 != last_k1 || k2 != last_k2) {  // a run of equal counts shares its group
        last_n = n, last_k1 = k1, last_k2 = k2;
        last = &groups[{double(n) / k1, double(n) / k2}];
      }
      Group& g = *last;
      for (int c = 0; c < 3; ++c) {
        g.d1 += error_terms(mean[p + c], 0.0, n, (*s1)[p + c]).diff;
        g.d2 += error_terms(mean[p + c], 0.0, n, (*s2)[p + c]).diff;
      }
      ++pixels;
    }
  if (pixels * 8 < size_t(width) * height) return fallback;
  auto f = [&](double a) {
    double t1 = 0, t2 = 0;
    for (const auto& [r, g] : groups) {
      t1 += g.d1 / (std::pow(r.first, a) - 1.0);
      t2 += g.d2 / (std::pow(r.second, a) - 1.0);
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

std::vector<ErrorSums> error_tiles(const std::vector<float>& mean, const std::vector<float>& variance,
                                   const std::vector<SnapshotView>& snapshots, int width, int height, const PixelCounts& now,
                                   double exponent, int tile) {
  const int tx = (width + tile - 1) / tile, ty = (height + tile - 1) / tile;
  std::vector<ErrorSums> tiles(size_t(tx) * ty);
  int last_n = -1, last_k = -1;
  double last_scale = 0.0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t p = (size_t(y) * width + x) * 4;
      const int n = now.at(x, y);
      int k = 0;
      const std::vector<float>* snap = nullptr;
      for (const SnapshotView& v : snapshots) {
        const int kv = v.counts.at(x, y);
        if (kv > k && 2 * kv <= n) k = kv, snap = v.mean;
      }
      if (n != last_n || k != last_k) {  // per tile of counts: pow() once per run of equal counts
        last_n = n, last_k = k;
        last_scale = snap ? 1.0 / (std::pow(double(n) / k, exponent) - 1.0) : 0.0;
      }
      const double scale = last_scale;
      ErrorSums& t = tiles[size_t(y / tile) * tx + x / tile];
      for (int c = 0; c < 3; ++c) {
        ErrorSums e = error_terms(mean[p + c], variance[p + c], n, snap ? (*snap)[p + c] : 0.0);
        e.diff = snap ? e.diff * scale : e.iid;
        t += e;
      }
    }
  return tiles;
}

}  // namespace pt
