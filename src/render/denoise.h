// The denoiser (issue 14): an edge-aware a-trous wavelet filter of the displayed image,
// SVGF's spatial part (Schied et al. 2017, after Dammertz et al. 2010), followed by a
// weighted local first-order regression (Moon et al. 2014; Bitterli et al. 2016), in GLSL
// ES 3.00 fragment passes (shaders/denoise.glsl): the radiance is divided by the first-hit
// albedo, filtered in 5 iterations of a 5x5 kernel whose taps stop at depth, normal and
// albedo edges and at luminance differences large against the pixel's standard deviation
// (from the accumulator's per-pixel variance); the first iteration's output is then
// fitted in a 15x15 window as linear in the screen offset, with the same geometric
// weights and range weights from the last iteration's output, and the pixel gets the
// fit's value (a lighting gradient is not flattened, also at edges and borders); then
// multiplied by the albedo again. It needs the camera pass's auxiliaries
// (RenderSettings::aux: albedo, normal, depth; camera_aux.glsl) and reads the
// accumulator, never writes it: the running mean stays unbiased, and the filtered image
// is blended with it by a weight measured from the estimated relMSE and the filter's own
// change (Denoiser::run), so a converged image tends to the raw one. Measured: docs/denoise.md.
#pragma once
#include <vector>

#include "gpu/program.h"
#include "gpu/texture.h"

namespace pt {

class Accumulator;

// What the filter reads, in the accumulator's layout (accumulator.h, camera_aux.glsl):
// radiance = (mean RGB, blue's sample variance), stats = (-, -, red's, green's), aux0 =
// (albedo, depth), aux1 = (normal, -); all the same size, n samples per pixel.
struct DenoiseInputs {
  const Texture* radiance;
  const Texture* stats;
  const Texture* aux0;
  const Texture* aux1;
  int samples;
  GLenum format;  // of the intermediate and output textures
  static DenoiseInputs of(const Accumulator& a);
};

struct DenoiseParams {
  int iterations = 5;     // a-trous steps 1, 2, 4, ...: a footprint of 4 * 2^iterations - 3 pixels
  float sigma_z = 1.0f;   // depth: SVGF's values
  float sigma_n = 128.0f; // normal: the exponent of the cosine
  float sigma_l = 4.0f;   // luminance: standard deviations
  float sigma_a = 0.05f;  // albedo: its relative difference (the light's rim); 0: off
  // The final regression pass (0: none): (2 reg_radius + 1)^2 taps reg_stride apart.
  int reg_radius = 7;
  int reg_stride = 1;
  float reg_rel = 0.2f;    // the guide's tolerance: relative luminance difference
  float reg_sd = 2.0f;     // ... and standard deviations of the guide
  float reg_ridge = 1e-5f; // the slopes' ridge, relative to the sum of weights
  int reg_input = 1;       // what it fits: 0 the unfiltered image, i the output of a-trous iteration i
  // The gate: below this many samples per pixel the albedo term and the regression pass are
  // off (the a-trous iterations alone, main's filter, bit for bit). Fitted on four scenes
  // (docs/denoise.md, in-sample): the smallest measured count (1, 4, 16, 24, 32, 64, 256)
  // from which the two together are nowhere more than 5% worse than the a-trous passes
  // alone (16 spp: the wood scene 1.09x; 24: 1.02x). Below it each is worse somewhere (the
  // regression 2.6x in scene0 and 6x in the Cornell box at 4 spp; the albedo term 1.4x in
  // the wood scene at 4 spp). 0: always on.
  int min_samples = 24;
  bool gated(int samples) const { return samples < min_samples; }
};

// The fixed fade, for a half-float accumulator (Denoiser::run measures the weight
// otherwise): the blend weight of the filtered image given the raw image's estimated
// relMSE (the renderer's own, core/metrics.h; no estimate yet: 1): 1 while the image is noisy, falling
// log-linearly to 0 between kFadeHigh and kFadeLow, where the filter's own error (its
// bias at edges and in the lighting's gradients) is no longer below the raw image's: in
// the Cornell box at 128x128 between 256 and 1024 spp (docs/denoise.md).
constexpr double kFadeHigh = 1e-3, kFadeLow = 1e-4;
float denoise_weight(double estimated_rel_mse, bool known = true);

class Denoiser {
 public:
  DenoiseParams params;
  // Filters the accumulator's current mean (a.aux() must be on) into output(): raw +
  // weight x (filtered - raw); weight 0 gives the raw mean bit for bit. vao: a vertex
  // array for the fullscreen triangle (no attributes). Leaves the default framebuffer bound.
  //
  // With `estimate` >= 0 (the raw mean's estimated relMSE E, core/metrics.h) the weight is
  // measured instead, weight x min(1, E / D), D the mean relative squared change of the
  // weight-1 image, (denoised - raw)^2 / (raw^2 + 0.01), summed on the GPU before the finish
  // (one small read-back a run). With raw = T + n and the denoised image T + b, E[D] = E + B
  // and (1 - w)^2 E + w^2 B is least at w = E / (E + B) = E / D, where it is E B / (E + B),
  // below both: the blend beats the raw and the filtered image alike, and fades to the raw
  // one as E falls below the filter's own error B (docs/denoise.md). A half-float
  // accumulator (no float sums) takes denoise_weight(E) instead.
  void run(const DenoiseInputs& in, float weight, GLuint vao, double estimate = -1.0);
  void run(const Accumulator& a, float weight, GLuint vao, double estimate = -1.0) { run(DenoiseInputs::of(a), weight, vao, estimate); }
  // The same run in slices across frames (the page: at 512x512 a run takes 1.3-3.4 s in
  // SwiftShader, docs/denoise.md, which froze the page that long). start() plans run()'s
  // passes for in.samples (the gate, the variance's scale) and `weight`; advance() draws
  // the next bands of rows, about `units` of work (one unit: a pixel of an a-trous
  // iteration, kUnits), reading `in`'s textures as they are then, and returns true once
  // output() holds the whole image (which it held in part, the last pass's bands, meanwhile).
  // run() is start() and one advance() without a limit: the same draws, whole.
  void start(const DenoiseInputs& in, float weight, double estimate = -1.0);
  bool advance(const DenoiseInputs& in, GLuint vao, double units);
  bool running() const { return next_ < plan_.size(); }
  int next_row() const { return row_; }  // where the pass in progress goes on (on render/draw_grid.h's grid)
  // A pass's work per pixel in units: prepare, an a-trous iteration (25 taps), finish, and
  // the regression ((2 r + 1)^2 taps: 225 at r = 7, 9 units; measured on llvmpipe at
  // 512x512: 5 iterations 250 ms each, the regression 2.0 s, docs/denoise.md).
  double units(int kind) const;
  const Texture& output() const { return out_; }
  float weight() const { return done_weight_; }  // the blend's weight of the last complete run (the image output() shows)
  std::vector<float> read() const;  // RGB the denoised radiance, A 1; rows bottom to top
  double last_ms() const { return last_ms_; }  // CPU time of the last run's calls (not waited for)
  // The filter's cost: `runs` runs on the accumulator's mean after one that builds what
  // they need, each waited for by reading one pixel of the output back (WebGL's finish
  // does not wait); each run's milliseconds, sorted. The CLI's --denoise and the page's
  // ptTimeDenoise print their median.
  std::vector<double> time(const Accumulator& a, float weight, GLuint vao, int runs = 3, double estimate = -1.0);

 private:
  void pass(int kind, const Texture* input, const Framebuffer& target, const DenoiseInputs& in, GLuint vao, int step = 0,
            float weight = 0.0f, const Texture* noisy = nullptr, int row = 0, int rows = 0);
  // A run's passes (start()): kind, the texture read (-1: none), the target (-1: the
  // output), the a-trous step, the regression's fitted image; the next one and its next row.
  struct Pass {
    int kind, input, target, step, noisy;
  };
  std::vector<Pass> plan_;
  size_t next_ = 0;
  int row_ = 0, samples_ = 0;
  float weight_ = 0.0f, done_weight_ = 1.0f;  // the run in progress's, the last complete one's
  double estimate_ = -1.0;  // E for the measured weight (start()); < 0: the weight as given
  static constexpr int kChangeBlock = 16;  // pixels per block side of the change pass's sums
  Program programs_[5];  // prepare, one iteration, finish, regression, change
  Texture change_;        // the change pass's block sums (RGBA32F, R)
  Framebuffer change_fbo_;
  void measure_weight(const DenoiseInputs& in, const Texture& filtered, GLuint vao);
  int reg_built_[2] = {0, 0};  // the regression program's radius and stride
  Texture tex_[3];  // the a-trous ping-pong, and the regression's input (made only once it runs)
  Framebuffer fbo_[3];
  Texture out_;
  Framebuffer out_fbo_;
  int width_ = 0, height_ = 0;
  GLenum format_ = 0;
  double last_ms_ = 0.0;
};

}  // namespace pt
