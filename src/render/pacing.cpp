// The draw pacers (render/pacing.h).
#include "render/pacing.h"

#include <algorithm>
#include <chrono>

namespace pt {
namespace {

// FramePacer. Add a draw per frame while frames come faster than kFastFrameMs, scale the
// draws down to the target when a frame took longer than kSlowFrameMs. A draw whose CPU
// time exceeds the budget means the call blocked on the GPU (a full command queue, or a
// blocking driver): stop.
constexpr double kFastFrameMs = 20.0;
constexpr double kSlowFrameMs = 28.0;
constexpr double kTargetFrameMs = 22.0;
constexpr double kCpuBudgetMs = 12.0;
constexpr int kMaxPassesPerFrame = 64;
// When even one draw per frame keeps frames slower than kSlowDrawFrameMs (under 30 UI
// frames/s: the mean of the window below, or two frames in a row twice as slow) the draw
// shrinks: rows first, then columns, down to kMinBandRows x min_band_columns(). It grows back while frames are
// faster than kGrowDrawFrameMs: columns to the whole width, then rows to the whole image,
// then more draws per frame. Growth is gentle unless frames are fast: a software GL spends
// a large fixed time per frame (SwiftShader: about 22 ms for compositing, the panel and
// the display pass at 960x640 on 2 cores, docs/benchmarks.md), so a draw there may have a
// few milliseconds, and the pacer has to settle at the largest such draw, not jump past
// it. A GPU paced by vsync gives frames of 16.7 or 33.3 ms: it grows until frames take two
// intervals and stays there. The threshold (FramePacer::kSlowDrawFrameMs, pacing.h) sits
// just above those 33.3 ms: at 34 ms, frames of 29.4-30/s were left alone (CI's load_test
// saw 29.4/s at whole-row draws).
constexpr double kGrowDrawFrameMs = 28.0;
constexpr int kMinBandColumns = 128;
// Nor are draws smaller than a sweep over this many draws (a bigger canvas, bigger draws):
// at 30 frames/s a sweep then takes at most about 35 s.
constexpr int kMaxDrawsPerSweep = 1024;
// The draw size follows the mean interval of the last kJudgeFrames frames drawn at that
// size (pacing.h; none from before a change: the browser runs a frame or two ahead of the
// GPU). Not one frame nor the shorter of two: a browser catching up after a long frame
// delivers the next at once, so intervals come in pairs like 50 + 5 ms (SwiftShader on 2
// cores, CI's load_test), where the shorter said "fast" and the draw grew while frames
// averaged 28/s. Two frames in a row far too slow (over 2 kSlowDrawFrameMs) shrink the
// draw at once, without waiting for the window.
// How long a floor under the draw size (judge_shrink) holds before shrinking is tried again.
constexpr double kDrawFloorMs = 5000.0;

// A band's rows for a wanted count: a multiple of kBandRowsStep (render/draw_grid.h), at least
// kMinBandRows, or the whole image (h) when the count reaches it.
int align_rows(int rows, int h) {
  if (rows >= h) return h;
  return std::min(h, std::max(kMinBandRows, grid_floor(rows, kBandRowsStep)));
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

void DrawPacer::record(double ms, int rows, int spp) {
  const double cost = ms / double(std::max(1, rows) * std::max(1, spp));
  cost_ = std::max(cost, cost_ * 0.9);  // the worst recent cost, slowly forgotten
}

void DrawPacer::apply(int image_rows, RenderSettings& s) const {
  constexpr int kMaxSpp = 256;
  if (cost_ <= 0.0) return;  // nothing measured yet: keep what the caller chose
  const double budget = target_ms_ / cost_;  // row-samples per draw
  if (budget >= 2.0 * image_rows) {
    s.spp_per_pass = std::clamp(int(budget / image_rows), 1, kMaxSpp);
    s.band_rows = 0;
  } else {
    s.spp_per_pass = 1;
    const int rows = std::clamp(int(budget), std::min(kMinBandRows, image_rows), image_rows);
    s.band_rows = rows >= image_rows ? 0 : align_rows(rows, image_rows);
  }
}

// The narrowest tile of a band of kMinBandRows rows.
int FramePacer::min_band_columns(int w, int h) const {
  const int per_sweep = (double(w) * h) / (double(kMaxDrawsPerSweep) * std::min(kMinBandRows, std::max(1, h))) + 1;
  return std::min(w, std::max(kMinBandColumns, grid_ceil(per_sweep, kTileColumnsStep)));
}

// Scales the draw (band_rows x band_columns) by `factor` in pixels: whole rows down to
// kMinBandRows, then columns down to min_band_columns(); the reverse when growing.
void FramePacer::scale_draw(double factor, int w, int h, RenderSettings& s) {
  const int rows = s.band_rows > 0 ? std::min(s.band_rows, h) : h;
  const int columns = s.band_columns > 0 && rows <= kMinBandRows ? std::min(s.band_columns, w) : w;
  const double now = double(rows) * columns;
  const double pixels = factor > 1.0 ? std::max(now * factor, now + 1.0) : std::min(now * factor, now - 1.0);
  // Whole rows on the row-pair grid (align_rows); a growth or shrink that the grid would
  // round away takes one step of it.
  int new_rows = align_rows(int(pixels / w), h);
  if (factor > 1.0 && new_rows <= rows && columns >= w && rows < h) new_rows = align_rows(rows + kBandRowsStep, h);
  if (factor < 1.0 && new_rows >= rows && rows > kMinBandRows) new_rows = align_rows(rows - 1, h);
  int new_columns = w;
  if (new_rows <= kMinBandRows && pixels < double(kMinBandRows) * w) {  // a tile of the thinnest band
    new_columns = std::clamp(grid_floor(int(pixels / kMinBandRows), kTileColumnsStep), min_band_columns(w, h), w);
    if (factor > 1.0 && new_columns <= columns && columns < w) new_columns = std::min(w, columns + kTileColumnsStep);
    if (factor < 1.0 && new_columns >= columns) new_columns = std::max(min_band_columns(w, h), columns - kTileColumnsStep);
  }
  s.band_rows = new_rows >= h ? 0 : new_rows;
  s.band_columns = new_columns >= w ? 0 : new_columns;
  judged_ = -1;  // the next interval is of a frame queued before the change: not counted
  window_sum_ = 0.0;
  prev_dt_ms_ = 0.0;
}

// Frames still slow after a shrink from shrink_from_pixels_ (frames then
// shrink_from_ms_) to `pixels` (frames now `ms`): the difference prices a pixel. When the
// price says that even the smallest draw would leave frames slower than kSlowDrawFrameMs,
// the fixed cost of a frame may be what makes them slow (a software GL at a large canvas,
// or a loaded machine), and smaller draws would only slow the sweep down. A price from
// two noisy frame intervals is only a guess (on a loaded machine it once held draws of 4
// whole rows at 28 UI frames/s, where a frame without draws took 24 ms: CI, load_test),
// so the smallest draw is measured: the draw jumps there (the probe) and, when frames
// there are still slow, goes back to the size before the shrink and stays at least that
// for kDrawFloorMs. True when it changed the draw.
bool FramePacer::judge_shrink(double pixels, double ms, double now_ms, bool smallest, int w, int h, RenderSettings& s) {
  const double from = probe_from_pixels_ > 0.0 && smallest ? probe_from_pixels_ : shrink_from_pixels_;
  shrink_from_pixels_ = probe_from_pixels_ = 0.0;
  if (from <= pixels) return false;
  if (smallest) {  // measured: still slow at the smallest draw
    floor_pixels_ = from;
    floor_set_ms_ = now_ms;
    scale_draw(from / pixels, w, h, s);
    return true;
  }
  const double per_pixel = std::max(0.0, (shrink_from_ms_ - ms) / (from - pixels));
  const double least = double(std::min(kMinBandRows, h)) * min_band_columns(w, h);
  if (ms - per_pixel * std::max(0.0, pixels - least) <= kSlowDrawFrameMs) return false;
  probe_from_pixels_ = from;
  scale_draw(least / pixels, w, h, s);
  return true;
}

int FramePacer::frame(Renderer& r, RenderSettings& s, double dt_ms, double now_ms, bool busy, double& samples) {
  const int w = r.width(), h = r.height();
  // The interval since the last frame measures the work queued then (and the hidden time
  // of a background tab, after which the count simply grows back).
  const bool whole = (s.band_rows <= 0 || s.band_rows >= h) && (s.band_columns <= 0 || s.band_columns >= w);
  const bool smallest = s.band_rows == std::min(kMinBandRows, h) &&
                        s.band_columns == (min_band_columns(w, h) < w ? min_band_columns(w, h) : 0);
  const double pixels = double(s.band_rows > 0 ? std::min(s.band_rows, h) : h) * (s.band_columns > 0 ? std::min(s.band_columns, w) : w);
  // The window: the intervals of frames at this draw size; frames slowed by a preparation
  // say nothing of the draws, and a sweep that ended (a converged image) none either.
  const bool skipped = judged_ < 0 && !busy && dt_ms > 0.0;  // the frame queued before a change
  if (busy || dt_ms <= 0.0) {
    judged_ = 0;
    window_sum_ = 0.0;
  } else if (skipped) {
    judged_ = 0;
  } else if (judged_ < kJudgeFrames) {
    window_[judged_++] = dt_ms;
    window_sum_ += dt_ms;
  } else {
    window_sum_ += dt_ms - window_[next_];
    window_[next_] = dt_ms;
    next_ = (next_ + 1) % kJudgeFrames;
  }
  if (judged_ < kJudgeFrames) next_ = 0;  // (filling: the ring starts at the oldest)
  const bool settled = judged_ == kJudgeFrames;
  const double mean = settled ? window_sum_ / kJudgeFrames : 0.0;
  const double both = busy ? 0.0 : std::min(dt_ms, prev_dt_ms_);  // the faster of this frame and the last
  prev_dt_ms_ = busy || skipped ? 0.0 : dt_ms;
  if (dt_ms > kSlowFrameMs && !busy && passes_per_frame_ > 1) {  // more draws than one: fewer, at once
    passes_per_frame_ = std::max(1, int(std::min(0.9, kTargetFrameMs / dt_ms) * passes_per_frame_));
  } else if (passes_per_frame_ == 1 && (both > 2.0 * kSlowDrawFrameMs || (settled && mean > 2.0 * kSlowDrawFrameMs))) {
    shrink_from_pixels_ = 0.0;  // far too slow: the draw, surely; shrink at once
    if (!smallest) scale_draw(std::min(0.5, kTargetFrameMs / std::max(both, mean)), w, h, s);
  } else if (settled && passes_per_frame_ == 1) {
    if (mean > kSlowDrawFrameMs && !judge_shrink(pixels, mean, now_ms, smallest, w, h, s) && !smallest && pixels > floor_pixels_) {
      shrink_from_pixels_ = pixels;
      shrink_from_ms_ = mean;
      scale_draw(0.7, w, h, s);
    }
  }
  if (now_ms - floor_set_ms_ > kDrawFloorMs) floor_pixels_ = 0.0;

  const auto t0 = std::chrono::steady_clock::now();
  int done = 0;
  // While a scene is being prepared, one draw per frame: the preparation gets the time
  // (and, with a software GPU, the CPU) that more draws would take.
  const int passes = busy ? 1 : passes_per_frame_;
  const double image_pixels = std::max(1.0, double(w) * h);
  while (done < passes && !r.converged()) {
    r.step();
    // Samples count as they are drawn, in fractions of the image: a sweep of small tiles
    // on a slow GPU may take longer than the rate's window.
    samples += double(r.last_draw_samples()) / image_pixels;
    ++done;
    if (ms_since(t0) > kCpuBudgetMs) break;
  }
  if (done == 0) {  // frames without draws say nothing of them
    judged_ = 0;
    window_sum_ = 0.0;
  }
  // Grow only when this frame used all its passes, else an idle (converged) image would
  // ratchet the count up and the next restart would start with one very long frame.
  if (dt_ms > 0 && done == passes_per_frame_ && !busy) {
    if (!whole && settled && mean < kGrowDrawFrameMs) {
      shrink_from_pixels_ = probe_from_pixels_ = 0.0;  // a shrink (or a probe) that let frames get fast did its job
      scale_draw(mean < kFastFrameMs ? 2.0 : 1.25, w, h, s);
    } else if (whole && dt_ms < kFastFrameMs) {
      passes_per_frame_ = std::min(kMaxPassesPerFrame, passes_per_frame_ + 1);
    }
  }
  return done;
}

}  // namespace pt
