// The running mean of radiance: two float targets in ping-pong (a draw reads one and
// writes the other, which blends its samples into the mean), each with a statistics
// attachment (NaN/Inf samples and rays, counted in the shader) and a variance attachment
// (per RGB channel, the variance of the pixel's samples about their mean, combined pass by
// pass in the shader: camera_pass.glsl; the error estimate reads it, core/metrics.h). A sweep adds samples to
// every pixel; it may be drawn as bands of rows and a band as tiles of columns, the tile
// copied back into the target it read (a blit), so the pair agrees again without a swap.
#pragma once
#include <vector>

#include "gpu/gl_check.h"
#include "gpu/program.h"
#include "gpu/texture.h"

namespace pt {

struct RenderSettings;

// Totals since the last restart, counted in the shader.
struct RenderCounters {
  double bad_samples = 0;  // NaN/Inf samples (dropped from the estimate)
  double rays = 0;         // every ray cast: camera, bounce and shadow
};

class Accumulator {
 public:
  // Float render targets need EXT_color_buffer_float on WebGL 2 / GLES 3.0. Without it
  // half floats are tried (the running mean keeps ~3 significant digits), and otherwise it
  // throws GlError: an 8-bit accumulator cannot hold a converging HDR estimate.
  Accumulator();
  GLenum format() const { return format_; }
  void resize(int width, int height);  // the size was checked against the GPU's limits
  int width() const { return width_; }
  int height() const { return height_; }
  void restart() {
    samples_ = 0;
    ++epoch_;
    next_row_ = next_column_ = 0;
    needs_clear_ = true;
  }
  int samples() const { return samples_; }
  int epoch() const { return epoch_; }  // counts restarts: an estimate from another image is stale
  bool mid_sweep() const { return next_row_ != 0 || next_column_ != 0; }

  // The pixels and samples per pixel of one draw.
  struct Tile {
    int x0, y0, x1, y1, spp;
    bool whole = false;  // the whole image: the pair swaps instead of copying back
  };
  // The next tile of the sweep in progress, or of a new one (its samples per pixel fixed
  // until it ends, capped by the sample limit); clears both targets after a restart.
  Tile begin_tile(const RenderSettings& s);
  // The program's accumulator inputs (the mean so far, its statistics) and blend.
  void bind_inputs(Program& p, const Tile& t) const;
  GLuint target_fbo() const { return fbo_[1 - cur_].id(); }  // where the draw writes
  GLuint current_fbo() const { return fbo_[cur_].id(); }     // the current mean (attachment 0)
  const Texture& target_radiance() const { return accum_[1 - cur_]; }
  const Texture& target_stats() const { return stats_[1 - cur_]; }
  const Texture& target_variance() const { return var_[1 - cur_]; }
#ifndef __EMSCRIPTEN__
  // The compute kernel's outputs: the targets as images 0 (mean), 1 (statistics), 2 (variance).
  void bind_images() const;
#endif
  // After the draw: swap or copy the tile back, move on; the samples per pixel added when
  // the tile completed a sweep, else 0.
  int end_tile(const Tile& t);

  const Texture& radiance() const { return accum_[cur_]; }  // the current mean (display)
  const Texture& variance() const { return var_[cur_]; }    // the samples' variance about it
  std::vector<float> read_radiance() const;  // RGB radiance, A mean squared luminance; rows bottom to top
  // Per pixel, RGB: the variance of its samples about their mean (sum of squared
  // deviations / samples, the biased sample variance); A: 0. Rows bottom to top.
  std::vector<float> read_variance() const;
  RenderCounters counters() const;

 private:
  Texture accum_[2];
  Texture stats_[2];
  Texture var_[2];
  Framebuffer fbo_[2];
  GLenum format_ = GL_RGBA32F;
  int cur_ = 0;
  int samples_ = 0;
  int next_row_ = 0;      // first row of the band in progress or the next one; with
  int next_column_ = 0;   // this 0 too, a new sweep starts; else the band's next tile
  int band_end_ = 0;      // the row after the band in progress (fixed while it lasts)
  int sweep_spp_ = 1;     // samples per pixel of the sweep in progress
  int epoch_ = 0;
  bool needs_clear_ = true;
  int width_ = 0, height_ = 0;
};

}  // namespace pt
