// Command-line options shared by `render` and `bench`.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "render/pipeline.h"
#include "render/renderer.h"

namespace pt::cli {

struct Options {
  std::string scene;
  std::string env;      // --env: an HDR map replacing the scene's environment
  int width = 512, height = 512;
  int spp = 64;         // render: samples per pixel
  int per_pass = 0;     // 0: adapt the draw size to the measured time
  std::vector<std::string> outs;  // render: --out may repeat (default out.png)
  bool auto_exposure = false;
  // render: the denoiser (--denoise; --out-denoised implies it): its images, its blend
  // weight (< 0: from the estimated relMSE, render/denoise.h), the auxiliaries' prefix.
  std::vector<std::string> outs_denoised;
  float denoise_weight = -1.0f;
  std::string out_aux;
  std::string out_spp;  // render: each pixel's sample count, .pfm
  std::string out_variance;  // render: each pixel's estimated variance of its mean, .pfm
  DenoiseParams denoise_params;  // --denoise-params ITERATIONS,SIGMA_Z,SIGMA_N,SIGMA_L (tuning)
  RenderSettings settings;
  std::vector<std::string> given;  // the flags given: they win over the scene's <Render>
  // bench
  double seconds = 0;  // bench: duration (default 10); render, watch: optional time limit
  double target_relmse = 0;  // render: stop once the estimated relMSE is at most this (0: off)
  std::string reference;         // .pfm or .hdr
  double reference_value = -1;   // a constant (analytic) reference instead
  std::string csv, label;
};

extern const char* const kUsage;
[[noreturn]] void usage_error(const std::string& msg);
Options parse_options(int argc, char** argv, bool bench);
// The scene file read through the pipeline (render/pipeline.h; its meshes too: no GL is
// needed yet) with the options that change it applied (--env). Throws on bad input.
std::unique_ptr<ScenePipeline> read_scene(const Options& o);
// The settings to render `scene` with: the options, and the scene's <Render> for what no
// flag set (sample_limit: --spp, else the scene's samples when > 0, else the default).
RenderSettings settings_for(const Options& o, const Scene& scene);
// The header line saying which acceleration the program traverses and why (--accel, or
// auto's rule for the scene's primitive count).
std::string accel_line(const Renderer& r, const Scene& scene);

int run_render(const Options& o);
int run_watch(const Options& o);
int run_bench(const Options& o);
int run_plot(int argc, char** argv);

}  // namespace pt::cli
