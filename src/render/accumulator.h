// The running mean of radiance: two float targets in ping-pong (a draw reads one and
// writes the other, which blends its samples into the mean), each with a statistics
// attachment (NaN/Inf samples and rays, counted in the shader); per RGB channel the
// variance of the pixel's samples about their mean, combined pass by pass in the shader
// (camera_pass.glsl; the error estimate reads it, core/metrics.h), lives in the free
// channels: red and green in the statistics' z and w, blue in the mean's alpha. A sweep adds samples to
// every pixel; it may be drawn as bands of rows and a band as tiles of columns, the tile
// copied back into the target it read (a blit), so the pair agrees again without a swap.
#pragma once
#include <vector>

#include "gpu/gl_check.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "render/adaptive.h"
#include "render/tile_sums.h"

namespace pt {

struct RenderSettings;

// Totals since the last restart, counted in the shader.
struct RenderCounters {
  double bad_samples = 0;  // NaN/Inf samples (dropped from the estimate)
  double rays = 0;         // every ray cast: camera, bounce and shadow
  // With RenderSettings::count_ops (else 0): ray-box tests (two per interior node visited,
  // one for the root) and ray-primitive tests, every ray's. Each pixel's sum is a float:
  // exact up to 2^24 tests per pixel.
  double box_tests = 0, prim_tests = 0;
};

class Accumulator {
 public:
  // Float render targets need EXT_color_buffer_float on WebGL 2 / GLES 3.0. Without it
  // half floats are tried (the running mean keeps ~3 significant digits), and otherwise it
  // throws GlError: an 8-bit accumulator cannot hold a converging HDR estimate.
  Accumulator();
  GLenum format() const { return format_; }
  void resize(int width, int height);  // the size was checked against the GPU's limits
  // Two more targets for the denoiser's first-hit auxiliaries (camera_aux.glsl): 2 =
  // (albedo, depth), 3 = (normal, 0); a change re-creates the targets and restarts.
  void set_aux(bool on);
  bool aux() const { return aux_; }
  int width() const { return width_; }
  int height() const { return height_; }
  void restart() {
    samples_ = 0;
    paths_ = 0;
    counts_.restart();
    next_refresh_ = 0;
    ++epoch_;
    next_row_ = next_column_ = 0;
    needs_clear_ = true;
  }
  // Samples per pixel: with adaptive sampling the image's mean count (each sweep adds its
  // samples per pixel on average: render/adaptive.h), else every pixel's.
  int samples() const { return samples_; }
  // Paths traced since the restart (pixels x samples per pixel of every finished tile): the
  // progress of a sweep in progress too, for a throughput figure finer than whole sweeps
  // (the peer benchmark, tools/peers/).
  double paths() const { return paths_; }
  // Adaptive sampling (RenderSettings::adaptive): per-tile counts, a program built with
  // PT_ADAPTIVE reading them (bind_inputs). A change restarts.
  void set_adaptive(bool on);
  bool adaptive() const { return adaptive_; }
  // The statistics' z and w hold the traversal's counts (RenderSettings::count_ops).
  void set_count_ops(bool on) { count_ops_ = on; }
  // With adaptive(): each tile's count (a tile of counts().tile() pixels), null when off.
  const TileCounts* tile_counts() const { return adaptive_ ? &counts_ : nullptr; }
  // The pixel-samples drawn since the restart (every pixel's count, summed).
  double total_samples() const { return adaptive_ ? counts_.total() : double(samples_) * width_ * height_; }
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
  // Adaptive sampling in the compute kernel: a whole sweep is dispatched tile by tile in
  // the order of dispatch_order (render/adaptive.h: the most samples first), one group of
  // 8x8 per (tile / 8)^2 of each tile; the shader maps the linear group index through the
  // counts texture (u_ordered). Else the groups cover the tile's rectangle in raster order.
  bool ordered_dispatch(const Tile& t) const;
#ifndef __EMSCRIPTEN__
  // The compute kernel's outputs: the targets as images 0 (mean), 1 (statistics), and with
  // the auxiliaries 2 and 3.
  void bind_images() const;
#endif
  // After the draw: swap or copy the tile back, move on; the samples per pixel added when
  // the tile completed a sweep, else 0.
  int end_tile(const Tile& t);

  const Texture& radiance() const { return accum_[cur_]; }  // the current mean (display); A: blue's variance
  const Texture& stats() const { return stats_[cur_]; }     // z, w: red's and green's variance
  const Texture& aux0() const { return aux_tex_[0][cur_]; }  // with aux(): albedo, depth
  const Texture& aux1() const { return aux_tex_[1][cur_]; }  // with aux(): shading normal
  std::vector<float> read_aux(int k) const;  // aux0 (k = 0) or aux1 read back, rows bottom to top
  // RGB radiance; A: a bound on the variance of the samples' luminance, (sum over channels
  // of weight x standard deviation)^2, exact when the channels are proportional (the
  // page's test of the mean reads it). Rows bottom to top.
  std::vector<float> read_radiance() const;
  // Per pixel, RGB: the variance of its samples about their mean (sum of squared
  // deviations / samples, the biased sample variance); A: 0. Rows bottom to top.
  std::vector<float> read_variance() const;
  // Both at once (two read-backs instead of four): mean RGB (A as read_radiance) and variance.
  void read_mean_variance(std::vector<float>& mean, std::vector<float>& variance) const;
  RenderCounters counters() const;
  // The error estimate's sums over blocks of `block` pixels against up to four snapshot
  // means, reduced on the GPU (render/tile_sums.h): what the estimate and adaptive
  // sampling's weights read instead of the images.
  BlockGrid block_sums(const std::vector<TileSums::Image>& snapshots, int block) const;
  // The fullscreen triangle's vertex array (the renderer's), for that pass.
  void set_vertex_array(GLuint vao) { vao_ = vao; }

 private:
  Texture accum_[2];
  Texture stats_[2];
  Texture aux_tex_[2][2];  // [which][ping-pong], with aux_ only
  Framebuffer fbo_[2];
  GLenum format_ = GL_RGBA32F;
  int cur_ = 0;
  int samples_ = 0;
  double paths_ = 0;
  int next_row_ = 0;      // first row of the band in progress or the next one; with
  int next_column_ = 0;   // this 0 too, a new sweep starts; else the band's next tile
  int band_end_ = 0;      // the row after the band in progress (fixed while it lasts)
  int sweep_spp_ = 1;     // samples per pixel of the sweep in progress
  int epoch_ = 0;
  bool needs_clear_ = true;
  bool aux_ = false;
  bool adaptive_ = false;
  bool count_ops_ = false;
  AdaptiveParams params_;
  TileCounts counts_;
  Texture counts_tex_;     // per tile (samples so far, this sweep's samples per pixel)
  int next_refresh_ = 0;   // the mean count at which the variance is read back again
  int dispatch_chunks_ = 1;  // the compute scheduler's runs of groups (dispatch_order)
  void plan_sweep();       // adaptive: this sweep's counts, uploaded
  int targets() const { return aux_ ? 4 : 2; }
  int width_ = 0, height_ = 0;
  mutable TileSums sums_;  // its program and small targets, made at the first use
  GLuint vao_ = 0;
};

}  // namespace pt
