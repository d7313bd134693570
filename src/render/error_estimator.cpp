// Snapshots and readbacks of the error estimate (render/error_estimator.h).
#include "render/error_estimator.h"

#include "render/accumulator.h"

#include <numeric>

namespace pt {


void ErrorEstimator::reset(const Accumulator& a) {
  epoch_ = a.epoch();
  if (a.width() != width_ || a.height() != height_) {
    width_ = a.width();
    height_ = a.height();
    for (Snapshot& s : snaps_) {
      s.mean = Texture(width_, height_, a.format(), nullptr);
      s.fbo = Framebuffer(s.mean);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  for (Snapshot& s : snaps_) s.samples = 0;
  older_ = 0;
  next_ = 1;
  history_.clear();
}

const ErrorEstimator::Snapshot* ErrorEstimator::usable(int samples) const {
  const Snapshot* best = nullptr;
  for (const Snapshot& s : snaps_)
    if (s.samples > 0 && 2 * s.samples <= samples && (!best || s.samples > best->samples)) best = &s;
  return best;
}

std::vector<ErrorSums> ErrorEstimator::sums(const Accumulator& a, const Snapshot* s, double* exponent) const {
  // The images are reduced on the GPU to sums over blocks (render/tile_sums.h), against
  // every snapshot of this image at once; only those are read back.
  const bool current = a.epoch() == epoch_ && a.width() == width_ && a.height() == height_;  // else they are another image's
  std::vector<TileSums::Image> images(kSnapshots);
  std::vector<PixelCounts> counts(kSnapshots);
  const TileCounts* c = a.tile_counts();
  for (int i = 0; i < kSnapshots && current; ++i) {
    const Snapshot& q = snaps_[i];
    if (q.samples <= 0 || (c && q.counts.size() != c->counts().size())) continue;
    images[size_t(i)] = {&q.mean, q.fbo.id()};
    if (c) counts[size_t(i)] = PixelCounts{c->tile(), c->tiles_x(), &q.counts};
  }
  if (c) {
    // Each tile of counts takes the latest snapshot at half its count or less, and the one
    // before it, at half that or less, for the exponent (core/metrics.h).
    const BlockGrid g = a.block_sums(images, std::gcd(std::gcd(kTile, c->tile()), kSumsBlock));
    const PixelCounts now{c->tile(), c->tiles_x(), &c->counts()};
    const double decay = snapshot_exponent(g, counts, now, history_.exponent(a.samples()));
    if (exponent) *exponent = decay;
    return error_tiles(g, counts, now, decay, kTile);
  }
  const int slot = s ? int(s - snaps_) : -1;
  std::vector<TileSums::Image> one(kSnapshots);
  if (s) one[size_t(slot)] = images[size_t(slot)];
  return error_tiles(a.block_sums(one, kSumsBlock), slot, a.samples(), kTile);
}

void ErrorEstimator::sweep_done(const Accumulator& a) {
  if (a.epoch() != epoch_ || a.width() != width_ || a.height() != height_) reset(a);
  const int n = a.samples();
  if (n < next_) return;
  // The change since the half-way snapshot, at a power of two: the decay's next point.
  const Snapshot* half = usable(n);
  // With adaptive sampling only while every tile has the same count (the uniform start):
  // D(n/2, n) of tiles at other ratios is not a point of the same curve.
  const bool equal = !a.tile_counts() || a.tile_counts()->uniform();
  if (half && 2 * half->samples == n && n >= ErrorHistory::kFirstPoint && equal) {
    ErrorSums all;
    for (const ErrorSums& t : sums(a, half)) all += t;
    history_.record(n, all.diff / all.count);
  }
  Snapshot& s = snaps_[older_];
  glBindFramebuffer(GL_READ_FRAMEBUFFER, a.current_fbo());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, s.fbo.id());
  glDisable(GL_SCISSOR_TEST);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  PT_GL_CHECK("glBlitFramebuffer (error snapshot)");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  s.samples = n;
  if (const TileCounts* c = a.tile_counts()) s.counts = c->counts();
  else s.counts.clear();
  older_ = (older_ + 1) % kSnapshots;
  while (next_ <= n) next_ *= 2;
}

ErrorEstimate ErrorEstimator::estimate(const Accumulator& a) const {
  const bool current = a.epoch() == epoch_ && a.width() == width_ && a.height() == height_;
  const Snapshot* s = current ? usable(a.samples()) : nullptr;
  const int tx = (a.width() + kTile - 1) / kTile, ty = (a.height() + kTile - 1) / kTile;
  if (a.tile_counts() && current) {  // the snapshots' terms scaled per pixel (or iid's where none fits)
    double exponent = history_.exponent(a.samples());
    const std::vector<ErrorSums> t = sums(a, s, &exponent);
    return combine_error_scaled(t, tx, ty, kTile, a.samples(), true, exponent);
  }
  return combine_error(sums(a, s), tx, ty, kTile, a.samples(), s ? s->samples : 0, current ? history_.exponent(a.samples()) : 1.0);
}

}  // namespace pt
