// The a-trous denoiser's passes (render/denoise.h, shaders/denoise.glsl).
#include "render/denoise.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "render/accumulator.h"
#include "render/draw_grid.h"
#include "shadergen/shadergen.h"

namespace pt {

float denoise_weight(double e, bool known) {
  if (!known || e >= kFadeHigh) return 1.0f;
  if (!(e > kFadeLow)) return 0.0f;
  return float(std::log(e / kFadeLow) / std::log(kFadeHigh / kFadeLow));
}

namespace {

ShaderSource denoise_source(int kind, const DenoiseParams& params) {
  return resolve_includes("#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
                          "#define PT_DENOISE_PASS " + std::to_string(kind) + "\n#define PT_REG_RADIUS " +
                              std::to_string(params.reg_radius) + "\n#define PT_REG_STRIDE " + std::to_string(params.reg_stride) +
                              "\n#include \"denoise.glsl\"\n",
                          "<generated denoise>");
}

}  // namespace

DenoiseInputs DenoiseInputs::of(const Accumulator& a) {
  if (!a.aux()) throw GlError("the denoiser needs the first-hit auxiliaries (RenderSettings::aux)");
  return {&a.radiance(), &a.stats(), &a.aux0(), &a.aux1(), a.samples(), a.format()};
}

void Denoiser::pass(int kind, const Texture* input, const Framebuffer& target, const DenoiseInputs& in, GLuint vao, int step,
                    float weight, const Texture* noisy, int row, int rows) {
  Program& p = programs_[kind];
  if (kind == 3 && (reg_built_[0] != params.reg_radius || reg_built_[1] != params.reg_stride)) {
    p = Program();
    reg_built_[0] = params.reg_radius;
    reg_built_[1] = params.reg_stride;
  }
  if (!p.id()) p = Program(fullscreen_vertex(), denoise_source(kind, params));
  p.use();
  p.set("u_radiance", 0);
  p.set("u_stats", 1);
  p.set("u_aux0", 2);
  p.set("u_aux1", 3);
  p.set("u_input", 4);
  p.set("u_noisy", 5);
  p.set("u_reg_rel", params.reg_rel);
  p.set("u_reg_sd", params.reg_sd);
  p.set("u_reg_ridge", params.reg_ridge);
  p.set("u_samples", in.samples);
  p.set("u_sigma_z", params.sigma_z);
  p.set("u_sigma_n", params.sigma_n);
  p.set("u_sigma_l", params.sigma_l);
  p.set("u_sigma_a", params.gated(in.samples) ? 0.0f : params.sigma_a);
  p.set("u_step", step);
  p.set("u_weight", weight);
  p.set("u_block", kChangeBlock);
  in.radiance->bind(0);
  in.stats->bind(1);
  in.aux0->bind(2);
  in.aux1->bind(3);
  if (input) input->bind(4);
  if (noisy) noisy->bind(5);
  glBindFramebuffer(GL_FRAMEBUFFER, target.id());
  if (kind == 4) glViewport(0, 0, change_.width(), change_.height());
  else glViewport(0, 0, width_, height_);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  const bool band = rows > 0 && (row > 0 || rows < height_);
  if (band) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, row, width_, rows);
  } else {
    glDisable(GL_SCISSOR_TEST);
  }
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  PT_GL_CHECK("glDrawArrays (denoise)");
  if (band) glDisable(GL_SCISSOR_TEST);
}

double Denoiser::units(int kind) const {
  if (kind == 1) return 1.0;
  if (kind == 3) return double((2 * params.reg_radius + 1) * (2 * params.reg_radius + 1)) / 25.0;
  return 0.2;
}

void Denoiser::run(const DenoiseInputs& in, float weight, GLuint vao, double estimate) {
  const auto t0 = std::chrono::steady_clock::now();
  start(in, weight, estimate);
  advance(in, vao, std::numeric_limits<double>::infinity());
  last_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void Denoiser::start(const DenoiseInputs& in, float weight, double estimate) {
  const int w = in.radiance->width(), h = in.radiance->height();
  if (w != width_ || h != height_ || in.format != format_) {
    width_ = w;
    height_ = h;
    format_ = in.format;
    for (int i = 0; i < 2; ++i) {
      tex_[i] = Texture(w, h, format_, nullptr);
      fbo_[i] = Framebuffer(tex_[i]);
    }
    fbo_[2] = Framebuffer();  // the regression's third texture: made when first needed
    tex_[2] = Texture();
    out_ = Texture(w, h, format_, nullptr);
    out_fbo_ = Framebuffer(out_);
  }
  const bool regress = params.reg_radius > 0 && !params.gated(in.samples);
  if (regress && !tex_[2].id()) {  // below the gate (the page's first seconds, a moving camera) never
    tex_[2] = Texture(w, h, format_, nullptr);
    fbo_[2] = Framebuffer(tex_[2]);
  }
  // With the regression, the image it fits (the prepare pass's output, or that of a-trous
  // iteration reg_input) is kept aside; the other iterations ping-pong between the two
  // other textures.
  plan_.clear();
  int cur = 0, keep = -1;
  plan_.push_back({0, -1, cur, 0, -1});
  auto other = [&](int a, int b) { return a != 0 && b != 0 ? 0 : a != 1 && b != 1 ? 1 : 2; };
  for (int i = 0; i <= params.iterations; ++i) {
    if (regress && i == std::min(params.reg_input, params.iterations)) keep = cur;
    if (i == params.iterations) break;
    const int next = other(cur, keep);
    plan_.push_back({1, cur, next, 1 << i, -1});
    cur = next;
  }
  if (regress) {
    const int next = other(cur, keep);
    plan_.push_back({3, cur, next, 0, keep});
    cur = next;
  }
  if (estimate >= 0.0 && format_ == GL_RGBA32F && weight > 0.0f) plan_.push_back({4, cur, -1, 0, -1});
  plan_.push_back({2, cur, -1, 0, -1});
  next_ = 0;
  row_ = 0;
  samples_ = in.samples;
  weight_ = std::clamp(weight, 0.0f, 1.0f);
  estimate_ = estimate;
  if (estimate >= 0.0 && format_ != GL_RGBA32F) weight_ *= denoise_weight(estimate);  // no float sums: the fixed fade
}

void Denoiser::measure_weight(const DenoiseInputs& in, const Texture& filtered, GLuint vao) {
  const int bw = (width_ + kChangeBlock - 1) / kChangeBlock, bh = (height_ + kChangeBlock - 1) / kChangeBlock;
  if (change_.width() != bw || change_.height() != bh) {
    change_ = Texture(bw, bh, GL_RGBA32F, nullptr);
    change_fbo_ = Framebuffer(change_);
  }
  pass(4, &filtered, change_fbo_, in, vao);
  const std::vector<float> sums = read_rgba_float(change_fbo_.id(), 0, bw, bh);
  double d = 0.0;
  for (size_t i = 0; i < sums.size(); i += 4) d += sums[i];
  d /= 3.0 * width_ * height_;  // per pixel and channel
  // The filter changed nothing (D = 0): any weight gives the same image; keep the given one.
  if (d > 0.0) weight_ *= float(std::min(1.0, estimate_ / d));
}

bool Denoiser::advance(const DenoiseInputs& inputs, GLuint vao, double budget) {
  DenoiseInputs in = inputs;
  in.samples = samples_;  // as planned (the gate; the accumulator may have more by now)
  for (bool drew = false; next_ < plan_.size() && budget > 0.0; drew = true) {
    const Pass& p = plan_[next_];
    if (p.kind == 4) {  // whole (a small target), then the weight for the finish
      measure_weight(in, tex_[p.input], vao);
      budget -= double(width_) * height_ * units(p.kind);
      ++next_;
      continue;
    }
    const double per_row = double(width_) * units(p.kind);
    // At least one slice a call (kBandRowsStep rows, or the rest), else within the budget.
    if (drew && budget < per_row * std::min(kBandRowsStep, height_ - row_)) break;
    // Slices on the row-pair grid (render/draw_grid.h): a multiple of kBandRowsStep rows, or
    // the rest (also when the budget is unlimited, run(): no int of an infinite quotient).
    int rows = height_ - row_;
    if (budget < per_row * rows) rows = std::min(rows, std::max(kBandRowsStep, grid_floor(int(budget / per_row), kBandRowsStep)));
    pass(p.kind, p.input >= 0 ? &tex_[p.input] : nullptr, p.target >= 0 ? fbo_[p.target] : out_fbo_, in, vao, p.step,
         p.kind == 2 ? weight_ : 0.0f, p.noisy >= 0 ? &tex_[p.noisy] : nullptr, row_, rows);
    budget -= per_row * rows;
    row_ += rows;
    if (row_ >= height_) {
      ++next_;
      row_ = 0;
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (next_ < plan_.size()) return false;
  done_weight_ = weight_;
  return true;
}

std::vector<double> Denoiser::time(const Accumulator& a, float weight, GLuint vao, int runs, double estimate) {
  float pixel[4];
  const auto wait = [&] {
    glBindFramebuffer(GL_FRAMEBUFFER, out_fbo_.id());
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, pixel);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  };
  run(a, weight, vao, estimate);
  wait();
  std::vector<double> ms;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    run(a, weight, vao, estimate);
    wait();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms;
}

std::vector<float> Denoiser::read() const { return read_rgba_float(out_fbo_.id(), 0, width_, height_); }

}  // namespace pt
