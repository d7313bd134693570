// The coarse first image (issue 14): after every restart of the estimate (a load, a camera
// move, a change of settings) the page's first sweeps run at 1/8, then 1/4, then 1/2 of
// each axis, each into a small accumulator of its own, before full-resolution sweeps
// start. The display shows the finest complete coarse level, upscaled, until the first
// full-resolution sweep is complete; then only the full-resolution mean. Coarse samples
// are never blended into the full-resolution accumulation: the full image, its estimated
// error, the denoiser's input and a saved HDR are the same with and without the ladder
// (tests/coarse_test.cpp). three-gpu-pathtracer (its "low resolution" first pass) and
// erichlof's renderers show a low-resolution image while the camera moves in the same way.
// This file is the ladder's logic, without GL (unit-tested natively); Renderer draws it.
#pragma once

namespace pt {

class CoarseLadder {
 public:
  static constexpr int kLevels = 3;
  static constexpr int kDivisors[kLevels] = {8, 4, 2};  // of each axis, coarsest first
  static int divisor(int level) { return kDivisors[level]; }
  // The size of a level's image: ceil(full / divisor), so its pixels cover the full image
  // (the last column and row may reach past it; the camera maps them as the full image's).
  static int level_size(int full, int level) { return (full + kDivisors[level] - 1) / kDivisors[level]; }

  void restart() { next_ = 0, shown_ = -1, started_ = false; }
  // The level the next draw renders, or -1 once every level is complete (full resolution).
  int drawing() const { return next_ < kLevels ? next_ : -1; }
  void drew() { started_ = true; }  // a draw of the level drawing() went out
  void level_done() {  // a sweep of the level drawing() is complete: it is shown, the next starts
    shown_ = next_;
    ++next_;
  }
  bool started() const { return started_; }  // anything drawn since the restart
  int completed() const { return next_; }      // levels complete since the restart
  // The level the display shows, or -1: the full-resolution mean. A coarse level is shown
  // only while no full-resolution sweep is complete (full_samples == 0).
  int shown(int full_samples) const { return full_samples > 0 ? -1 : shown_; }

  // A coarse draw of about as many pixels as the pacer's full-resolution draw (band_rows
  // x band_columns of a w-pixel-wide image, 0 = all): the pacer's feedback (frame times)
  // stays true of the draws it sized. A band of whole rows of the level when that is at
  // least kMinBandRows rows (or the level), else kMinBandRows rows and as many columns;
  // rows and columns on the row-pair grid (render/draw_grid.h) unless the whole level.
  // Sets rows and columns for the level's w x h image (0 = all).
  static void draw_size(int band_rows, int band_columns, int full_w, int full_h, int w, int h, int& rows, int& columns);

 private:
  int next_ = 0;
  int shown_ = -1;
  bool started_ = false;
};

}  // namespace pt
