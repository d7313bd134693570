// The renderer's estimate of its own error (issue 14): the relMSE of the running mean
// against the image it converges to, for the whole image and per tile, with no reference.
// The per-pixel variance comes from the accumulator (accumulated in the integrator's
// pass, both kernels); this keeps snapshots of the mean at the powers of two of the
// sample count and the decay of the image's change between them; the estimator itself,
// its derivation and its calibration are core/metrics.h's. With adaptive sampling each
// pixel's terms use its tile's own count, now and at the snapshot (PixelCounts), and the
// exponent of the decay is the one fitted while every count was still the same.
#pragma once
#include <vector>

#include "core/metrics.h"
#include "gpu/texture.h"

namespace pt {

class Accumulator;

class ErrorEstimator {
 public:
  static constexpr int kTile = 32;  // pixels per side of the per-tile estimate
  // The GPU sums' blocks (render/tile_sums.h), summed into tiles here: smaller than a tile so
  // that the block grid covers several of llvmpipe's 64x64 bins, which its threads share
  // (blocks of 32 at 1920x1080 are 60x34 fragments: one bin, one thread).
  static constexpr int kSumsBlock = 16;
  // After every completed sweep (Renderer::step): at the first sweep end at or past each
  // power of two it records the change since the last one and keeps a copy of the mean.
  void sweep_done(const Accumulator& a);
  // Reads the mean, variance and snapshot back (three float images: a CLI's end, a
  // page's readout every few seconds; the cost is measured in docs/benchmarks.md).
  ErrorEstimate estimate(const Accumulator& a) const;

 private:
  struct Snapshot {
    Texture mean;
    Framebuffer fbo;
    int samples = 0;
    std::vector<int> counts;  // adaptive sampling: each tile's count then (render/adaptive.h)
  };
  void reset(const Accumulator& a);
  const Snapshot* usable(int samples) const;  // the latest with samples <= n/2
  // The tiles' sums with snapshot s (uniform sampling) or each tile's own (adaptive:
  // then *exponent, if given, is the decay's exponent measured from the snapshots).
  std::vector<ErrorSums> sums(const Accumulator& a, const Snapshot* s, double* exponent = nullptr) const;
  // Snapshots at the last kSnapshots powers of two of the mean count: uniform sampling
  // uses the latest at n/2 or less (one of the last two); adaptive sampling lets each
  // tile of counts take the latest at half its own count or less (core/metrics.h), and a
  // tile held at the floor (render/adaptive.h: a quarter of the mean count) doubles its
  // count only while the mean grows four- to eightfold.
  static constexpr int kSnapshots = 4;
  Snapshot snaps_[kSnapshots];
  int older_ = 0;  // the slot the next snapshot replaces (the oldest)
  int next_ = 1;   // the sample count of the next snapshot
  int epoch_ = -1, width_ = 0, height_ = 0;
  ErrorHistory history_;
};

}  // namespace pt
