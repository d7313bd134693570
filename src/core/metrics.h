// Error metrics of an image: against a reference (the true error), and estimated from the
// render's own samples (no reference), over RGB of RGBA pixels.
#pragma once
#include <cstddef>
#include <limits>
#include <vector>

namespace pt {

struct ErrorMetrics {
  double rel_mse = 0;  // mean of (x - r)^2 / (r^2 + 0.01) over pixels and channels
  double rmse = 0;     // sqrt of the mean of (x - r)^2
};

// `reference` may hold one pixel (a constant image, e.g. an analytic answer).
ErrorMetrics image_error(const std::vector<float>& image, const std::vector<float>& reference);

// The relMSE above estimated without a reference, from the render's own samples
// (docs/benchmarks.md, "The renderer's own error", measures it against the true relMSE).
//
// Per pixel and channel, the accumulator keeps the mean m of n samples and the samples'
// variance s about it (sum of squared deviations / n). For independent samples
// v = s / (n - 1) is unbiased for Var(m) = E[(m - r)^2] (r: the true value; s alone, the
// variance of the samples about their own mean, is low by (n - 1)/n), so each term of
// relMSE is estimated by v / (m^2 + 0.01) ("iid" below). The denominator: E[m^2] = r^2 +
// Var(m), so m^2 overstates r^2 by the pixel's own relative error (a few per cent once
// relMSE < 0.03), while 1/(m^2 + 0.01) is convex in m and overstates 1/(r^2 + 0.01) by
// about three times as much: the two partly cancel, and max(m^2 - v, 0), which removes the
// first, was measured worse (below 16 spp, a pixel whose few samples include zeros gets
// m^2 - v = 0 and a term a hundred times too large).
//
// Stratified samples (the Owen-scrambled Sobol points of the camera and first bounce)
// converge faster than 1/n where they help, and v then overstates the error (1.5 to 2.7
// times from 16 to 256 spp in the Cornell box at 64x64). So the estimate also measures how
// the image itself changes: with a snapshot m_k of the mean at k <= n/2 samples,
//   E[(m_n - m_k)^2] = T(k) - T(n)   (T: the true squared error; exact for independent
//                                     samples, and for the two halves of a scrambled net at
//                                     k = n/2 when T falls as a power of n),
// so with T(n) = c n^-a, T(n) = D(k, n) / ((n/k)^a - 1), D the sum of (m_n - m_k)^2 / (m^2 +
// 0.01) over a region. The exponent a comes from the image's D(n/2, n) at the powers of
// two n >= ErrorHistory::kFirstPoint (16) so far (D falls as n^-a: a least-squares line
// through the last five below n in log-log; 1 before there are two), and the same a serves every
// tile. Points from n = 4 and 8 were dropped: there D is the first few samples' structure
// and a handful of fireflies, not yet the power law (scene0 at 16 spp: a fitted 1.49 from
// n = 4, 8, 16 and the estimate 0.48 of the truth; from 16 on, 0.87). The estimate of a
// region is the smaller of this and iid's: stratified points are not worse than
// independent ones, while D, one difference per term, reads low-n noise as a slow decay
// (in the closed room of analytic/ it put a at 0.7 for a true 1.0). Without a snapshot
// the estimate is iid's.

// The sums over one region (a tile or the image) that the estimate is made of.
struct ErrorSums {
  double iid = 0;    // sum of v / den
  double diff = 0;   // sum of (m - m_k)^2 / den
  double count = 0;  // terms (pixels x 3)
  ErrorSums& operator+=(const ErrorSums& o) {
    iid += o.iid, diff += o.diff, count += o.count;
    return *this;
  }
};

// The denominator's m, robust to fireflies. A pixel whose mean is carried by one rare
// sample of great value (a caustic found by BSDF sampling, scene0's glass) has m far
// above its true value r, so v / (m^2 + 0.01) reads its error as about 1 where the truth,
// (m - r)^2 / (r^2 + 0.01), is hundreds: in scene0 at 128x128 and 16 spp, 1% of the pixels
// hold 97% of the true error, and the estimate read 0.05 of it (with the true r in the
// denominator instead, the same v gave 1.03 to 1.16 of it from 16 to 256 spp: v is right,
// the denominator is not). So a firefly, a pixel whose luminance L is
//   - above kFireflyRatio times the median of its 3x3 neighbourhood's (not an edge or a
//     texture: half its neighbours would share it), and
//   - at least half of every neighbour's (not the rim of a small bright area, an emitter's,
//     whose brighter neighbours explain it),
// takes the mean of the other pixels within kFireflyRadius whose neighbourhood medians are
// within kGuideTolerance (relative, plus 0.05) of its own: the same surface, over a
// window wide enough that their rare samples average into the expected value r (13x13
// pixels; 0.2-0.8% of scene0's pixels are fireflies), and without its own samples, which
// would put its firefly back in (with them, scene0's estimate read 0.74 of the truth at
// 16 spp, without 0.88). Per channel the smaller of that and m; other pixels keep m.
// docs/benchmarks.md, "The renderer's own error", measures it against the truth.
constexpr float kFireflyRatio = 2.03f, kFireflyNeighbour = 0.47f, kGuideTolerance = 0.25f, kGuideFloor = 0.05f;
constexpr int kFireflyRadius = 6;
// Per pixel: x the median of the 3x3 neighbourhood's luminance (coordinates clamped to the
// image), y the largest luminance of the neighbours inside the image (-1 for none). RG of
// a two-float image, rows bottom to top.
std::vector<float> error_guide(const std::vector<float>& mean, int width, int height);
// The fireflies' m (per channel), in pixel order: the pixels whose m is replaced.
struct FireflyScale {
  size_t pixel;
  float rgb[3];
};
std::vector<FireflyScale> firefly_scales(const std::vector<float>& mean, const std::vector<float>& guide, int width, int height);
// The m each pixel and channel divides by (RGBA, A 0), from `mean` (RGBA) and its guide.
std::vector<float> error_scale(const std::vector<float>& mean, const std::vector<float>& guide, int width, int height);

// The image's D(n/2, n) / terms at powers of two n: the exponent a of the error's decay.
class ErrorHistory {
 public:
  void clear() { points_.clear(); }
  static constexpr int kFirstPoint = 16;
  void record(int samples, double diff_mean);  // ignored below kFirstPoint samples, or if not above the last
  // From the points recorded below `before` samples, clamped to [0.5, 3]. An estimate at n
  // samples scales D(n/2, n) by it, so it leaves out the point of n itself: that point is
  // the same D, and with it in, a D that came out low by chance also steepened the fitted
  // decay, which lowered the scale again (scene0 at 512x512 and 512 spp on the H100: 0.72
  // of the truth with it in; docs/benchmarks.md).
  double exponent(int before = std::numeric_limits<int>::max()) const;
 private:
  std::vector<std::pair<double, double>> points_;  // log n, log D
};

struct ErrorEstimate {
  bool known = false;      // at least 2 samples per pixel: before that there is no estimate
  double rel_mse = 0;      // of the whole image
  double rel_mse_iid = 0;  // the same from the per-pixel variance alone (independent samples)
  double exponent = 1;     // a: the error falls as n^-a
  int tile = 0;            // tiles of tile x tile pixels, the last row and column cut short
  int tiles_x = 0, tiles_y = 0;
  std::vector<double> tiles;  // relMSE per tile, rows bottom to top
};
// The estimate from each tile's sums (rows bottom to top) at n samples, the snapshot taken
// at k <= n/2 samples (0: none: the iid estimate) and the exponent a.
ErrorEstimate combine_error(const std::vector<ErrorSums>& tiles, int tiles_x, int tiles_y, int tile, int samples, int k,
                            double exponent);
// The tiles' sums from images: `mean`, `variance`, `snapshot` RGBA, rows bottom to top.
std::vector<ErrorSums> error_tiles(const std::vector<float>& mean, const std::vector<float>& variance,
                                   const std::vector<float>* snapshot, int width, int height, int samples, int tile = 32);

// Adaptive sampling (render/adaptive.h): each pixel has the count of its tile of counts.
// The same estimate with each pixel's own n, and with a snapshot's own k per pixel: the
// snapshot's term is scaled per pixel, D / ((n/k)^a - 1), where 2k <= n. Of several
// snapshots (taken at the image's mean count 1, 2, 4, ...: a tile sampled at the floor
// doubles its count only when the mean grew several times), each pixel takes the latest
// with 2k <= n; a pixel without one puts its iid term in both sums (it counts as iid's
// estimate). With every count equal and one snapshot this is error_tiles and
// combine_error above, term for term. The exponent a: the caller's (ErrorHistory,
// recorded while the counts were still equal).
struct PixelCounts {
  int tile = 1, tiles_x = 1;
  const std::vector<int>* n = nullptr;  // per tile, rows bottom to top
  int at(int x, int y) const { return (*n)[std::size_t(y / tile) * tiles_x + x / tile]; }
};
struct SnapshotView {
  const std::vector<float>* mean = nullptr;  // RGBA, rows bottom to top
  PixelCounts counts;                        // each pixel's count then
};
std::vector<ErrorSums> error_tiles(const std::vector<float>& mean, const std::vector<float>& variance,
                                   const std::vector<SnapshotView>& snapshots, int width, int height, const PixelCounts& now,
                                   double exponent, int tile = 32);
// The exponent a under adaptive sampling, where the image's D(n/2, n) over time is not one
// curve (each tile doubles at its own pace): from one moment, each pixel's two latest
// snapshots with 2 k1 <= n and 2 k2 <= k1. Under T(n) = c n^-a both
//   T1(a) = sum D1 / ((n/k1)^a - 1)   and   T2(a) = sum D2 / ((n/k2)^a - 1)
// estimate the same T(n); a is where they agree (with every count equal, r1 = 2, r2 = 4:
// 2^a = D2/D1 - 1). T1 - T2 goes from negative to positive as a grows (the nearer
// snapshot's difference is the smaller), so the root is found by bisection in [0.5, 3]
// (clamped there, as ErrorHistory). Returns `fallback` when fewer than 1/8 of the pixels
// have two such snapshots.
double snapshot_exponent(const std::vector<float>& mean, const std::vector<SnapshotView>& snapshots, int width, int height,
                         const PixelCounts& now, double fallback);
// The estimate from sums over blocks (what render/tile_sums.h reduces the images to on
// the GPU, one fragment per block, instead of reading three to six float images back):
// a block of block x block pixels lies inside one tile of counts and one tile of the
// estimate (block divides both), so each pixel's factors above (1/(n - 1), a snapshot's
// scale, which snapshot it takes) are one per block, and the functions above are these
// applied to the blocks' sums.
struct BlockSums {
  static constexpr int kSnapshots = 4;
  double var = 0;                // sum over pixels and channels of max(s, 0) / den (iid: var / (n - 1))
  double diff[kSnapshots] = {};  // sum of (m - m_j)^2 / den, m_j snapshot j's mean
  double pixels = 0;
};
struct BlockGrid {
  int block = 1, blocks_x = 0, blocks_y = 0, width = 0, height = 0;
  std::vector<BlockSums> sums;  // rows bottom to top
  // The grid of a width x height image in blocks of `block` (the last row and column cut
  // short), its sums zero.
  static BlockGrid sized(int width, int height, int block);
};
// The sums on the CPU from images (RGBA, rows bottom to top; at most kSnapshots snapshot
// means, the rest of diff 0): the GPU's reference, and its path where the targets are half floats.
BlockGrid block_sums(const std::vector<float>& mean, const std::vector<float>& variance,
                     const std::vector<const std::vector<float>*>& snapshots, int width, int height, int block);
// error_tiles (uniform: every pixel at `samples`) with snapshot `snapshot` of the grid's
// (-1: none); `tile` a multiple of the block.
std::vector<ErrorSums> error_tiles(const BlockGrid& g, int snapshot, int samples, int tile);
// The adaptive forms: snapshot j's counts are counts[j] (its n null: no snapshot j).
double snapshot_exponent(const BlockGrid& g, const std::vector<PixelCounts>& counts, const PixelCounts& now, double fallback);
std::vector<ErrorSums> error_tiles(const BlockGrid& g, const std::vector<PixelCounts>& counts, const PixelCounts& now,
                                   double exponent, int tile);

// combine_error of those sums (their snapshot terms already scaled): `samples` the mean
// count (known from 2), `snapshot` whether one was used.
ErrorEstimate combine_error_scaled(const std::vector<ErrorSums>& tiles, int tiles_x, int tiles_y, int tile, int samples, bool snapshot,
                                   double exponent);

}  // namespace pt
