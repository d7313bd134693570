// The ping-pong accumulation of the running mean (render/accumulator.h).
#include "render/accumulator.h"

#include <algorithm>

#include "render/renderer.h"
#include "render/texture_units.h"

namespace pt {

Accumulator::Accumulator() {
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

void Accumulator::resize(int width, int height) {
  width_ = width;
  height_ = height;
  for (int i = 0; i < 2; ++i) {
    accum_[i] = Texture(width, height, format_, nullptr);
    stats_[i] = Texture(width, height, format_, nullptr);
    var_[i] = Texture(width, height, format_, nullptr);
    fbo_[i] = Framebuffer(accum_[i], stats_[i], var_[i]);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  restart();
}

Accumulator::Tile Accumulator::begin_tile(const RenderSettings& s) {
  if (next_row_ == 0 && next_column_ == 0) {  // a sweep starts: its sample count is fixed until it ends
    sweep_spp_ = s.spp_per_pass < 1 ? 1 : s.spp_per_pass;
    if (s.sample_limit > 0 && samples_ + sweep_spp_ > s.sample_limit) sweep_spp_ = s.sample_limit - samples_;
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
      glClearBufferfv(GL_COLOR, 0, zero);
      glClearBufferfv(GL_COLOR, 1, zero);
      glClearBufferfv(GL_COLOR, 2, zero);
      PT_GL_CHECK("glClearBufferfv");
    }
    needs_clear_ = false;
  }
  return t;
}

void Accumulator::bind_inputs(Program& p, const Tile& t) const {
  p.set("u_accum", int(kAccumUnit));
  p.set("u_stats_in", int(kStatsUnit));
  p.set("u_var_in", int(kVarianceUnit));
  p.set("u_spp", t.spp);
  p.set("u_sample_base", samples_);
  p.set("u_blend", float(t.spp) / float(samples_ + t.spp));
  accum_[cur_].bind(kAccumUnit);
  stats_[cur_].bind(kStatsUnit);
  var_[cur_].bind(kVarianceUnit);
}

#ifndef __EMSCRIPTEN__
void Accumulator::bind_images() const {
  glBindImageTexture(0, accum_[1 - cur_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindImageTexture(1, stats_[1 - cur_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindImageTexture(2, var_[1 - cur_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
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
    for (int a = 0; a < 3; ++a) {
      GLenum bufs[3] = {GL_NONE, GL_NONE, GL_NONE};
      bufs[a] = GLenum(GL_COLOR_ATTACHMENT0 + a);
      glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + a));
      glDrawBuffers(3, bufs);
      glBlitFramebuffer(t.x0, t.y0, t.x1, t.y1, t.x0, t.y0, t.x1, t.y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      PT_GL_CHECK("glBlitFramebuffer (tile copy-back)");
    }
    const GLenum all[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glDrawBuffers(3, all);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (t.x1 < width_) {
    next_column_ = t.x1;
    return 0;
  }
  next_column_ = 0;
  next_row_ = t.y1 == height_ ? 0 : t.y1;
  if (next_row_ != 0) return 0;
  samples_ += t.spp;
  return t.spp;
}

std::vector<float> Accumulator::read_radiance() const { return read_rgba_float(fbo_[cur_].id(), 0, width_, height_); }

std::vector<float> Accumulator::read_variance() const { return read_rgba_float(fbo_[cur_].id(), 2, width_, height_); }

RenderCounters Accumulator::counters() const {
  const std::vector<float> px = read_rgba_float(fbo_[cur_].id(), 1, width_, height_);
  RenderCounters c;
  if (samples_ == 0) return c;
  for (size_t i = 0; i < px.size(); i += 4) {
    c.bad_samples += px[i];
    c.rays += px[i + 1];
  }
  return c;
}

}  // namespace pt
