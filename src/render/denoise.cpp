// The a-trous denoiser's passes (render/denoise.h, shaders/denoise.glsl).
#include "render/denoise.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "render/accumulator.h"
#include "shadergen/shadergen.h"

namespace pt {

float denoise_weight(double e, bool known) {
  if (!known || e >= kFadeHigh) return 1.0f;
  if (!(e > kFadeLow)) return 0.0f;
  return float(std::log(e / kFadeLow) / std::log(kFadeHigh / kFadeLow));
}

namespace {

ShaderSource denoise_source(int kind) {
  return resolve_includes("#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
                          "#define PT_DENOISE_PASS " + std::to_string(kind) + "\n#include \"denoise.glsl\"\n",
                          "<generated denoise>");
}

}  // namespace

DenoiseInputs DenoiseInputs::of(const Accumulator& a) {
  if (!a.aux()) throw GlError("the denoiser needs the first-hit auxiliaries (RenderSettings::aux)");
  return {&a.radiance(), &a.stats(), &a.aux0(), &a.aux1(), a.samples(), a.format()};
}

void Denoiser::pass(int kind, const Texture* input, const Framebuffer& target, const DenoiseInputs& in, GLuint vao, int step,
                    float weight) {
  Program& p = programs_[kind];
  if (!p.id()) p = Program(fullscreen_vertex(), denoise_source(kind));
  p.use();
  p.set("u_radiance", 0);
  p.set("u_stats", 1);
  p.set("u_aux0", 2);
  p.set("u_aux1", 3);
  p.set("u_input", 4);
  p.set("u_samples", in.samples);
  p.set("u_sigma_z", params.sigma_z);
  p.set("u_sigma_n", params.sigma_n);
  p.set("u_sigma_l", params.sigma_l);
  p.set("u_sigma_a", params.sigma_a);
  p.set("u_step", step);
  p.set("u_weight", weight);
  in.radiance->bind(0);
  in.stats->bind(1);
  in.aux0->bind(2);
  in.aux1->bind(3);
  if (input) input->bind(4);
  glBindFramebuffer(GL_FRAMEBUFFER, target.id());
  glViewport(0, 0, width_, height_);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  PT_GL_CHECK("glDrawArrays (denoise)");
}

void Denoiser::run(const DenoiseInputs& in, float weight, GLuint vao) {
  const auto t0 = std::chrono::steady_clock::now();
  const int w = in.radiance->width(), h = in.radiance->height();
  if (w != width_ || h != height_ || in.format != format_) {
    width_ = w;
    height_ = h;
    format_ = in.format;
    for (int i = 0; i < 2; ++i) {
      tex_[i] = Texture(w, h, format_, nullptr);
      fbo_[i] = Framebuffer(tex_[i]);
    }
    out_ = Texture(w, h, format_, nullptr);
    out_fbo_ = Framebuffer(out_);
  }
  pass(0, nullptr, fbo_[0], in, vao);
  int cur = 0;
  for (int i = 0; i < params.iterations; ++i) {
    pass(1, &tex_[cur], fbo_[1 - cur], in, vao, 1 << i);
    cur = 1 - cur;
  }
  pass(2, &tex_[cur], out_fbo_, in, vao, 0, std::clamp(weight, 0.0f, 1.0f));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  last_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<float> Denoiser::read() const { return read_rgba_float(out_fbo_.id(), 0, width_, height_); }

}  // namespace pt
