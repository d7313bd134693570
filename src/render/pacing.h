// Draw pacing, the one place that sizes draws: keep every draw under a target time, long
// enough to amortise its fixed cost, short enough that no GPU watchdog fires and a page
// stays responsive. A draw is a tile of a sweep (Renderer::step): spp_per_pass samples
// over band_rows rows (a band) and, in a thin band, band_columns columns. Two clocks
// feed it, one pacer each, sharing the draw's vocabulary and its floor:
// - DrawPacer (the command line): each draw is waited for (glFinish) and timed, so its
//   cost per row-sample is known, and the next draw is sized by prediction;
// - FramePacer (the page): WebGL calls only queue commands, so only the interval between
//   displayed frames says how long the GPU took; the draw grows and shrinks with it.
#pragma once

#include "render/draw_grid.h"
#include "render/renderer.h"

namespace pt {

// Bands keep at least this many rows: SwiftShader hands pairs of pixel rows to its
// threads in turn, so a thinner draw leaves one of two cores idle.
inline constexpr int kMinBandRows = 4;

// The cost of one sample of one image row varies across the image (sky rows are cheap,
// rows of glass are not), so the pacer keeps the worst recent cost per row-sample and
// sizes the next draw by prediction: whole sweeps with several samples when they fit,
// else one sample in bands of rows.
class DrawPacer {
 public:
  explicit DrawPacer(double target_ms) : target_ms_(target_ms) {}
  // The last draw took `ms` for `rows` rows at `spp` samples per pixel.
  void record(double ms, int rows, int spp);
  // Sets spp_per_pass and band_rows for the next draws (spp applies from the next sweep).
  void apply(int image_rows, RenderSettings& s) const;

 private:
  double target_ms_;
  double cost_ = 0.0;  // ms per row-sample
};

// The interval between frames is the feedback: once the GPU falls behind, the browser
// delays the next animation frame until the queued work is done. Draws per frame grow
// while frames are fast and scale down when one is slow; when even one draw per frame
// keeps frames slow, the draw itself shrinks (rows, then columns), and it grows back while
// frames are fast. Rules and figures in pacing.cpp.
// While the page prepares a scene in slices between frames (App::work), whether to draw
// this animation frame: only once the preparation has had kPrepareShare times the time
// the last drawn frame took. With a software GPU a frame costs the page's thread tens of
// milliseconds, which would otherwise leave the preparation a small share of it (2 gave
// about 1.6x the preparation's own time from request to swap with SwiftShader, 4 about
// 1.3-1.5x; docs/benchmarks.md). With a fast GPU every frame is still drawn.
class PreparePacer {
 public:
  static constexpr double kSliceMs = 8.0;  // one slice of scene preparation between frames
  static constexpr double kPrepareShare = 4.0;
  bool draw_now(bool preparing, double now_ms) const { return !preparing || now_ms - last_end_ms_ >= kPrepareShare * last_ms_; }
  void drawn(double start_ms, double end_ms) {
    last_end_ms_ = end_ms;
    last_ms_ = end_ms - start_ms;
  }

 private:
  double last_end_ms_ = 0.0, last_ms_ = 0.0;
};

class FramePacer {
 public:
  // Rows of the first draws, before any frame was measured: the first frame of a heavy
  // scene stays short.
  static constexpr int kFirstBandRows = 32;
  // One displayed frame's draws of `r`: dt_ms is the interval since the last frame (0 for
  // the first), now_ms a monotonic clock; `busy`: a scene is being prepared (one draw per
  // frame, and frames slowed by the preparation say nothing of the draws). Sets the draw
  // size in `s` (band_rows, band_columns; the caller hands `s` to the renderer), adds each
  // draw's samples to `samples`, in fractions of the image, and returns the draws made.
  int frame(Renderer& r, RenderSettings& s, double dt_ms, double now_ms, bool busy, double& samples);
  int passes_per_frame() const { return passes_per_frame_; }
  static constexpr int kJudgeFrames = 6;  // frame intervals averaged per judgement of the draw size (pacing.cpp)
  // A mean frame slower than this shrinks the draw (pacing.cpp): just under 30 frames/s,
  // and above two 60 Hz intervals. The page reports it (ptStats().slowFrameMs).
  static constexpr double kSlowDrawFrameMs = 33.5;

 private:
  int min_band_columns(int w, int h) const;
  void scale_draw(double factor, int w, int h, RenderSettings& s);
  bool judge_shrink(double pixels, double ms, double now_ms, bool smallest, int w, int h, RenderSettings& s);

  int passes_per_frame_ = 1;
  // The intervals of the last frames at the current draw size (pacing.cpp, kJudgeFrames):
  // judged_ of them so far, a ring from next_ once full.
  double window_[kJudgeFrames] = {};
  double window_sum_ = 0.0;
  int judged_ = 0, next_ = 0;
  double prev_dt_ms_ = 0.0;  // the interval before this one (since the last change)
  double shrink_from_pixels_ = 0.0, shrink_from_ms_ = 0.0;  // the last shrink: draw size and frame time before it
  double floor_pixels_ = 0.0, floor_set_ms_ = -1e9;  // no shrink below this, for a while (judge_shrink)
  double probe_from_pixels_ = 0.0;  // at the smallest draw to measure it: the size to go back to (judge_shrink)
};

}  // namespace pt
