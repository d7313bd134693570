// Snapshots and readbacks of the error estimate (render/error_estimator.h).
#include "render/error_estimator.h"

#include "render/accumulator.h"

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
  const int w = a.width(), h = a.height();
  std::vector<float> mean, var;
  a.read_mean_variance(mean, var);
  if (const TileCounts* c = a.tile_counts()) {
    // Each tile of counts takes the latest snapshot at half its count or less: only
    // those snapshots are read back.
    const std::vector<int>& n = c->counts();
    std::vector<bool> used(kSnapshots, false);
    const bool current = a.epoch() == epoch_ && w == width_ && h == height_;  // else they are another image's
    // (and the one before it, at half that or less, for the exponent: snapshot_exponent)
    for (size_t t = 0; t < n.size() && current; ++t) {
      int half = n[t];
      for (int pick = 0; pick < 2; ++pick) {
        int best = -1;
        for (int i = 0; i < kSnapshots; ++i) {
          const Snapshot& q = snaps_[i];
          if (q.samples > 0 && q.counts.size() == n.size() && 2 * q.counts[t] <= half && q.counts[t] > 0 &&
              (best < 0 || q.counts[t] > snaps_[best].counts[t]))
            best = i;
        }
        if (best < 0) break;
        used[size_t(best)] = true;
        half = snaps_[best].counts[t];
      }
    }
    std::vector<std::vector<float>> images(kSnapshots);
    std::vector<SnapshotView> views;
    for (int i = 0; i < kSnapshots; ++i) {
      if (!used[size_t(i)]) continue;
      images[size_t(i)] = read_rgba_float(snaps_[i].fbo.id(), 0, w, h);
      views.push_back({&images[size_t(i)], PixelCounts{c->tile(), c->tiles_x(), &snaps_[i].counts}});
    }
    const PixelCounts now{c->tile(), c->tiles_x(), &n};
    const double decay = snapshot_exponent(mean, views, w, h, now, history_.exponent());
    if (exponent) *exponent = decay;
    return error_tiles(mean, var, views, w, h, now, decay, kTile);
  }
  std::vector<float> snap;
  if (s) snap = read_rgba_float(s->fbo.id(), 0, w, h);
  return error_tiles(mean, var, s ? &snap : nullptr, w, h, a.samples(), kTile);
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
  if (half && 2 * half->samples == n && n >= 4 && equal) {
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
    double exponent = history_.exponent();
    const std::vector<ErrorSums> t = sums(a, s, &exponent);
    return combine_error_scaled(t, tx, ty, kTile, a.samples(), true, exponent);
  }
  return combine_error(sums(a, s), tx, ty, kTile, a.samples(), s ? s->samples : 0, current ? history_.exponent() : 1.0);
}

}  // namespace pt
