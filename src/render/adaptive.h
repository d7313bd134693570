// Adaptive sampling (issue 14): per-tile sample counts from the variance, with a floor.
// Plain C++ (no GL): the accumulator (render/accumulator.h) owns one, uploads its counts
// for the camera pass (PT_ADAPTIVE in camera_pass.glsl) and blends each tile with its own
// count, mean += (x - mean) * spp / (n + spp), so every pixel stays the plain mean of its
// own samples.
//
// The rule. The relMSE of the image (core/metrics.h) is the mean over pixels of
// Var(m) / (m^2 + 0.01) = r / n, r the pixel's relative variance per sample. With a tile's
// r_t, the counts n_t that minimise sum_t P_t r_t / n_t for a total of N pixel-samples are
// n_t = N sqrt(r_t) / sum_s P_s sqrt(r_s) (Lagrange; P_t the tile's pixels): samples in
// proportion to the relative standard deviation, not the variance. Each sweep moves the
// counts towards that target: its budget (the sweep's samples per pixel x pixels) goes to
// the tiles below their target, in proportion to what they lack; the fractions carry over
// to later sweeps (credit), so the budget is spent exactly on average.
//
// The floor. Before `uniform_spp` samples per pixel every tile is sampled alike (the
// variance estimates need samples of their own), and afterwards no tile's target is below
// `floor` x the image's mean count: a tile whose first samples all missed a rare path
// (a caustic, a small light seen through glass) reads as noiseless, and would otherwise
// never get the samples that show it is not.
//
// Bias. The decision for a sweep is taken from the samples of earlier sweeps only (the
// variance read back before the sweep starts), and a sweep's own samples are independent
// of it; but a pixel's mean still includes the earlier samples its count was chosen
// from, so the count is not independent of the estimate: a tile that looked smooth by
// chance gets fewer new samples and keeps its lucky early ones longer. The bias this
// leaves is of the order of the error itself and goes to 0 with the samples, because the
// floor makes every count grow without bound (consistent; the same trade as Cycles'
// adaptive sampling, which stops pixels on an error measured from the samples it keeps,
// and the hierarchical stopping rule of Dammertz et al. 2010 that Cycles follows). The
// renders stay the plain mean of each pixel's own samples (tests/adaptive_test.cpp).
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

namespace pt {

struct AdaptiveParams {
  int tile = 16;          // pixels per side of a tile of one sample count
  int uniform_spp = 8;    // samples per pixel everywhere before counts differ
  double floor = 0.25;    // no tile's target below this x the mean count
  double refresh = 1.25;  // read the variance back again once the mean count grew by this factor
  int max_tile_spp = 64;  // at most this many samples per pixel in one tile in one sweep
};

// The sweep's samples per pixel of each tile: `pixels` and `counts` per tile (samples so
// far), `weights` the target density per tile (sqrt(r_t), floored: tile_weights), a
// budget of `budget` pixel-samples; `credit` carries each tile's fraction of a sample to
// the next sweep (same size as pixels, zeros at a restart). The tiles lacking the most
// relative to their target get the budget; capped at max_spp per tile.
std::vector<int> allocate_sweep(const std::vector<int>& pixels, const std::vector<int>& counts, const std::vector<double>& weights,
                                double budget, int max_spp, std::vector<double>& credit);

// The target density per tile from each tile's relative variance per sample (r_t >= 0):
// sqrt(r_t), at least `floor` x their pixel-weighted mean; all 1 when every r_t is 0.
std::vector<double> tile_weights(const std::vector<int>& pixels, const std::vector<double>& rel_var, double floor);

// The order in which a sweep's tiles are dispatched, for a scheduler that hands the
// dispatch's work groups out one at a time in index order to whichever processor is free
// (chunks = 1: a GPU), or in `chunks` contiguous runs of equal length, one per thread
// (Mesa's llvmpipe: each thread takes groups / threads groups in a row). The tiles, the
// most samples first (ties in raster order), are dealt to the chunks in snake order (1, 2,
// ..., k, k, ..., 2, 1, 1, 2, ...; the chunks' lengths differ by at most one tile), so
// each chunk gets about the same work and starts with its heaviest tiles: the longest
// processing time first (Graham 1969). In raster order the noisy tiles bunch up: on
// llvmpipe (2 threads) adaptive sweeps ran 15-20% slower per ray than uniform ones, and
// on the H200 they drew about half the samples of uniform ones in the same time
// (docs/benchmarks.md).
std::vector<int> dispatch_order(const std::vector<int>& plan, int chunks = 1);

// The tile grid of an image and its counts (the accumulator's).
class TileCounts {
 public:
  void reset(int width, int height, int tile);
  void restart();  // every count and credit 0, weights uniform
  int tile() const { return tile_; }
  int tiles_x() const { return tiles_x_; }
  int tiles_y() const { return tiles_y_; }
  int at(int x, int y) const { return counts_[std::size_t(y / tile_) * tiles_x_ + x / tile_]; }  // a pixel's count
  const std::vector<int>& counts() const { return counts_; }
  const std::vector<int>& pixels() const { return pixels_; }
  const std::vector<double>& weights() const { return weights_; }
  void set_weights(std::vector<double> w) { weights_ = std::move(w); }
  // This sweep's spp per tile: `spp` everywhere while uniform (`uniform`), else allocate_sweep
  // of spp x the image's pixels.
  const std::vector<int>& plan(int spp, bool uniform, int max_spp);
  const std::vector<int>& planned() const { return plan_; }
  void commit();  // the planned sweep was drawn: counts += plan
  double total() const { return total_; }  // pixel-samples drawn since the restart
  bool uniform() const;                    // every tile has the same count

 private:
  int tile_ = 16, tiles_x_ = 0, tiles_y_ = 0;
  std::vector<int> pixels_, counts_, plan_;
  std::vector<double> weights_, credit_;
  double total_ = 0;
};

}  // namespace pt
