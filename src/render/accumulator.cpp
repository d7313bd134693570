// The ping-pong accumulation of the running mean (render/accumulator.h).
#include "render/accumulator.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <thread>

#include "render/renderer.h"
#include "render/texture_units.h"

namespace pt {

namespace {

// How the compute kernel's scheduler hands out a dispatch's groups (dispatch_order in
// render/adaptive.h): Mesa's llvmpipe gives each of its threads one contiguous run
// (LP_NUM_THREADS, else one thread per CPU); a GPU hands them out one by one.
int dispatch_chunks() {
#ifdef __EMSCRIPTEN__
  return 1;
#else
  const char* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!name || !std::strstr(name, "llvmpipe")) return 1;
  if (const char* e = std::getenv("LP_NUM_THREADS")) return std::max(1, std::atoi(e));
  return std::max(1, int(std::thread::hardware_concurrency()));
#endif
}

}  // namespace

Accumulator::Accumulator() : dispatch_chunks_(dispatch_chunks()) {
  for (GLenum fmt : {GLenum(GL_RGBA32F), GLenum(GL_RGBA16F)}) {
    Texture t(4, 4, fmt, nullptr);
    Framebuffer f(t);
    if (f.complete()) {
      format_ = fmt;
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      return;
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  throw GlError("this GPU cannot render to floating-point textures (EXT_color_buffer_float is missing)");
}

void Accumulator::set_aux(bool on) {
  if (on == aux_) return;
  aux_ = on;
  if (width_ > 0) resize(width_, height_);
}

void Accumulator::set_adaptive(bool on) {
  if (on == adaptive_) return;
  adaptive_ = on;
  restart();
}

void Accumulator::resize(int width, int height) {
  width_ = width;
  height_ = height;
  counts_.reset(width, height, params_.tile);
  for (int i = 0; i < 2; ++i) {
    accum_[i] = Texture(width, height, format_, nullptr);
    stats_[i] = Texture(width, height, format_, nullptr);
    fbo_[i] = Framebuffer(accum_[i], stats_[i]);  // leaves it bound
    for (int k = 0; k < 2; ++k) aux_tex_[k][i] = aux_ ? Texture(width, height, format_, nullptr) : Texture();
    if (aux_) {
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, aux_tex_[0][i].id(), 0);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT3, GL_TEXTURE_2D, aux_tex_[1][i].id(), 0);
      const GLenum bufs[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
      glDrawBuffers(4, bufs);
      PT_GL_CHECK("glFramebufferTexture2D (auxiliaries)");
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  restart();
}

Accumulator::Tile Accumulator::begin_tile(const RenderSettings& s) {
  if (next_row_ == 0 && next_column_ == 0) {  // a sweep starts: its sample count is fixed until it ends
    sweep_spp_ = s.spp_per_pass < 1 ? 1 : s.spp_per_pass;
    if (s.sample_limit > 0 && samples_ + sweep_spp_ > s.sample_limit) sweep_spp_ = s.sample_limit - samples_;
    // Sweeps end at every power of two: the error estimate's snapshots and its decay's
    // points are taken there (render/error_estimator.h; a sweep across one skipped the
    // point, and the estimate then depended on how the pacer happened to size the draws).
    // The samples are the same; only their grouping into passes changes, and with it the
    // running mean's rounding (within 3.3e-7 relative at 16 spp in passes of 3; with one
    // sample per pass the images are byte-identical to before).
    if (samples_ > 0 && !adaptive_) {
      int next = 1;
      while (next <= samples_) next *= 2;
      sweep_spp_ = std::min(sweep_spp_, next - samples_);
    }
    if (adaptive_) plan_sweep();
  }
  if (next_column_ == 0) {  // a band starts: its rows hold until its last tile is drawn
    const int rows = s.band_rows > 0 ? std::min(s.band_rows, height_) : height_;
    band_end_ = std::min(height_, next_row_ + rows);
  }
  const int columns = s.band_columns > 0 ? std::min(s.band_columns, width_) : width_;
  Tile t{next_column_, next_row_, std::min(width_, next_column_ + columns), band_end_, sweep_spp_};
  t.whole = t.x0 == 0 && t.y0 == 0 && t.x1 == width_ && t.y1 == height_;
  if (needs_clear_) {  // rows not yet swept show black, not another scene's image
    const float zero[4] = {0, 0, 0, 0};
    for (Framebuffer& f : fbo_) {
      glBindFramebuffer(GL_FRAMEBUFFER, f.id());
      for (int a = 0; a < targets(); ++a) glClearBufferfv(GL_COLOR, a, zero);
      PT_GL_CHECK("glClearBufferfv");
    }
    needs_clear_ = false;
  }
  return t;
}

void Accumulator::plan_sweep() {
  // Until uniform_spp every tile alike; then the weights from the variance so far (read
  // back at uniform_spp and whenever the mean count grew by `refresh`: the decision uses
  // earlier sweeps only, render/adaptive.h), and this sweep's budget shared by them.
  const bool uniform = samples_ < params_.uniform_spp;
  if (!uniform && samples_ >= next_refresh_) {
    // Per tile, the relative variance per sample as core/metrics.h's terms, s n/(n-1) /
    // (m^2 + 0.01), averaged over its pixels and channels: the blocks' var sums (one block
    // per tile) times n/(n-1).
    const BlockGrid g = block_sums({}, counts_.tile());
    std::vector<double> rel(counts_.pixels().size(), 0.0);
    for (size_t t = 0; t < rel.size(); ++t) {
      const int n = counts_.counts()[t];
      rel[t] = g.sums[t].var * n / std::max(n - 1, 1) / 3.0 / counts_.pixels()[t];
    }
    counts_.set_weights(tile_weights(counts_.pixels(), rel, params_.floor));
    next_refresh_ = std::max(samples_ + 1, int(std::ceil(samples_ * params_.refresh)));
  }
  const std::vector<int>& plan = counts_.plan(sweep_spp_, uniform, params_.max_tile_spp);
  // x, y: tile t's count and this sweep's samples per pixel; z, w at index i (raster order
  // of the grid): the tile the compute kernel's i-th tile of groups draws, the most
  // samples first (ordered_dispatch, below).
  std::vector<float> texels(plan.size() * 4, 0.0f);
  for (size_t t = 0; t < plan.size(); ++t) {
    texels[t * 4] = float(counts_.counts()[t]);
    texels[t * 4 + 1] = float(plan[t]);
  }
  const std::vector<int> order = dispatch_order(plan, dispatch_chunks_);
  for (size_t i = 0; i < order.size(); ++i) {
    texels[i * 4 + 2] = float(order[i] % counts_.tiles_x());
    texels[i * 4 + 3] = float(order[i] / counts_.tiles_x());
  }
  // Made once per tile grid, then updated in place each sweep.
  if (counts_tex_.width() != counts_.tiles_x() || counts_tex_.height() != counts_.tiles_y() || !counts_tex_.id())
    counts_tex_ = Texture(counts_.tiles_x(), counts_.tiles_y(), GL_RGBA32F, texels.data());
  else
    counts_tex_.upload(texels.data());
}

bool Accumulator::ordered_dispatch(const Tile& t) const { return adaptive_ && t.whole && counts_.tile() % 8 == 0; }

void Accumulator::bind_inputs(Program& p, const Tile& t) const {
  p.set("u_accum", int(kAccumUnit));
  p.set("u_stats_in", int(kStatsUnit));
  p.set("u_spp", t.spp);
  p.set("u_sample_base", samples_);
  p.set("u_blend", float(t.spp) / float(samples_ + t.spp));
  accum_[cur_].bind(kAccumUnit);
  stats_[cur_].bind(kStatsUnit);
  if (adaptive_) {  // PT_ADAPTIVE: each tile's count and samples from the texture instead
    p.set("u_tile_counts", int(kTileCountsUnit));
    p.set("u_count_tile", counts_.tile());
    counts_tex_.bind(kTileCountsUnit);
  }
  if (aux_) {
    p.set("u_aux0_in", int(kAux0Unit));
    p.set("u_aux1_in", int(kAux1Unit));
    aux_tex_[0][cur_].bind(kAux0Unit);
    aux_tex_[1][cur_].bind(kAux1Unit);
  }
}

#ifndef __EMSCRIPTEN__
void Accumulator::bind_images() const {
  glBindImageTexture(0, accum_[1 - cur_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindImageTexture(1, stats_[1 - cur_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  for (int k = 0; k < 2 && aux_; ++k)
    glBindImageTexture(GLuint(2 + k), aux_tex_[k][1 - cur_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  PT_GL_CHECK("glBindImageTexture (accumulator)");
}
#endif

int Accumulator::end_tile(const Tile& t) {
  if (t.whole) {
    cur_ = 1 - cur_;
  } else {
    // Copy the tile back into the texture it read: the pair agrees again on these pixels,
    // so later tiles and sweeps read consistent data without a swap.
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_[1 - cur_].id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_[cur_].id());
    const int n = targets();
    for (int a = 0; a < n; ++a) {
      GLenum bufs[4] = {GL_NONE, GL_NONE, GL_NONE, GL_NONE};
      bufs[a] = GLenum(GL_COLOR_ATTACHMENT0 + a);
      glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + a));
      glDrawBuffers(n, bufs);
      glBlitFramebuffer(t.x0, t.y0, t.x1, t.y1, t.x0, t.y0, t.x1, t.y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      PT_GL_CHECK("glBlitFramebuffer (tile copy-back)");
    }
    const GLenum all[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
    glDrawBuffers(n, all);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  paths_ += double(t.x1 - t.x0) * double(t.y1 - t.y0) * double(t.spp);
  if (t.x1 < width_) {
    next_column_ = t.x1;
    return 0;
  }
  next_column_ = 0;
  next_row_ = t.y1 == height_ ? 0 : t.y1;
  if (next_row_ != 0) return 0;
  samples_ += t.spp;
  if (adaptive_) counts_.commit();
  return t.spp;
}

BlockGrid Accumulator::block_sums(const std::vector<TileSums::Image>& snapshots, int block) const {
  return sums_.run(radiance(), stats(), current_fbo(), snapshots, width_, height_, block, format_, vao_);
}

void Accumulator::read_mean_variance(std::vector<float>& mean, std::vector<float>& variance) const {
  pt::read_mean_variance(fbo_[cur_].id(), width_, height_, mean, variance);
}

std::vector<float> Accumulator::read_aux(int k) const {
  if (!aux_) return {};
  return read_rgba_float(fbo_[cur_].id(), 2 + k, width_, height_);
}

std::vector<float> Accumulator::read_radiance() const {
  std::vector<float> mean, variance;
  read_mean_variance(mean, variance);
  return mean;
}

std::vector<float> Accumulator::read_variance() const {
  std::vector<float> mean, variance;
  read_mean_variance(mean, variance);
  return variance;
}

RenderCounters Accumulator::counters() const {
  const std::vector<float> px = read_rgba_float(fbo_[cur_].id(), 1, width_, height_);
  RenderCounters c;
  if (samples_ == 0) return c;
  for (size_t i = 0; i < px.size(); i += 4) {
    c.bad_samples += px[i];
    c.rays += px[i + 1];
    if (count_ops_) c.box_tests += px[i + 2], c.prim_tests += px[i + 3];
  }
  return c;
}

}  // namespace pt
