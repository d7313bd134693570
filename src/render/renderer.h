// The progressive integrator, a facade over its parts side by side in render/: the program
// cache (one integrator program per feature set), the scene's textures, the accumulator
// (ping-pong running mean, sweeps in bands and tiles) and the display (tone maps). One
// draw = u_spp samples per pixel of a tile. What gets a scene here: render/pipeline.h.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "accel/accel_choice.h"
#include "core/render_mode.h"
#include "core/tonemap.h"
#include "gpu/gl_objects.h"
#include "render/accumulator.h"
#include "render/coarse.h"
#include "render/denoise.h"
#include "render/display.h"
#include "render/error_estimator.h"
#include "render/program_cache.h"
#include "render/scene_textures.h"
#include "render/uniform_tables.h"
#include "scene/scene.h"
#include "shadergen/shadergen.h"

namespace pt {

struct PackedScene;
class StagedScene;

struct RenderSettings {
  int max_bounces = 8;   // scattering events per path (seed: 8, range 1..16)
  int spp_per_pass = 1;  // samples per pixel in one draw (fixed for a whole sweep)
  int band_rows = 0;     // rows per draw: a sweep of the image is several draws; 0 = all
  int band_columns = 0;  // columns per draw: a band is several tiles, left to right; 0 = all
  int sample_limit = 0;  // stop after this many samples per pixel; 0 = never
  bool nee = true;       // next-event estimation with MIS (off: BSDF sampling only)
  RenderMode mode = RenderMode::PathTracer;  // a different program per mode
  int sampler = 3;       // 4D blocks of a path drawn from Owen-scrambled Sobol (0: all independent)
  bool compute = false;  // the compute kernel where the context has one (compute_supported())
  bool aux = false;      // the camera pass also writes the denoiser's first-hit auxiliaries
  float denoise = 0.0f;  // with aux: the denoised image's blend weight in display() (0: raw)
  // The raw mean's estimated relMSE at the current samples (core/metrics.h; < 0: unknown):
  // known, the blend's weight is measured, denoise x min(1, E / D) (Denoiser::run).
  double denoise_estimate = -1.0;
  bool adaptive = false; // per-tile sample counts from the variance (render/adaptive.h); a change restarts
  Accel accel = Accel::Auto;  // BVH or a flat loop (accel/accel_choice.h); auto: by the primitive count
  // The glTF BSDF's multiple-scattering energy compensation (materials/gltf_ms.glsl; on by
  // default); off renders the specification's single-scattering model (for comparisons).
  bool gltf_ms = true;
  // The traversal's work counted per pixel (box tests, primitive tests: RenderCounters) in
  // place of the red and green variance, so the error estimate means nothing then; for
  // operation counts (`render --count-ops`, docs/benchmarks.md), never for images.
  bool count_ops = false;
  // The coarse first image (render/coarse.h): after each restart, sweeps at 1/8, 1/4 and
  // 1/2 of each axis into targets of their own, shown until the first full-resolution
  // sweep is complete. The page's; off for the command line (its output stays the same).
  bool coarse = false;  // (not with adaptive: its program reads tile counts the levels lack)
  ToneMap tonemap = ToneMap::Aces;
  float exposure = 1.0f;
  bool operator==(const RenderSettings&) const = default;
};

class Renderer {
 public:
  Renderer();  // needs a current GL ES 3.0 / WebGL 2 context
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Uploads the scene's data; compiles a program only for a feature set not seen before.
  void set_scene(const Scene& scene);
  // The same with the scene already packed (render/packing.h: a page packs a large scene
  // in slices across frames, then swaps it in here at once), and its record textures
  // uploaded ahead when `staged` is given and done (render/staged_scene.h; taken from it).
  // With `settings`, they are set with the scene, one program chosen for both (a page
  // applying a scene's <Render mode> would otherwise build the old mode's program first).
  void set_scene(const Scene& scene, const PackedScene& packed, StagedScene* staged = nullptr, const RenderSettings* settings = nullptr);
  // An edit of the last scene set that changed values only - materials (emission
  // included), the environment - and no shape's geometry: the shape, material and light
  // records are packed and uploaded again (one per shape, material, light: no BVH), and
  // the estimate restarts. false, changing nothing, when the edit needs set_scene: other
  // kinds, or another set of shapes being lights (an emission turned on or off).
  bool update_values(const Scene& scene);
  // The same for an edit that also moved or resized shapes, refitted into `packed` (the
  // scene's packed data, as set) by refit_shape (render/packing.h): the rows of the
  // primitive and node records it changed are uploaded too.
  bool update_geometry(const Scene& scene, const PackedScene& packed, const std::vector<int>& prims, const std::vector<int>& nodes);
  // Starts building the program for the scene's kinds without waiting for the driver;
  // true when set_scene(scene) will not block on it (always, without
  // KHR_parallel_shader_compile). A page polls this once a frame and keeps drawing.
  bool program_ready(const Scene& scene);
  bool program_ready(const Scene& scene, RenderMode mode);  // the same for that mode
  void set_camera(const Camera& camera);
  void set_settings(const RenderSettings& s);
  void resize(int width, int height);
  void restart() { accum_.restart(); }  // the coarse ladder follows (ladder())

  // One draw: the next tile of the current sweep, unless the sample limit is reached. A
  // sweep is bands of band_rows rows, bottom to top (the whole image when 0); a band is
  // tiles of band_columns columns, left to right (the whole band when 0). A band's rows
  // are fixed when it starts, so band_rows and band_columns may change between any two
  // draws and every pixel is still drawn once per sweep. A sweep adds spp_per_pass
  // samples to every pixel; returns the samples added when this draw completed a sweep,
  // else 0. Tiles keep each draw short (no watchdog, a responsive page); the estimate is
  // the same. With settings().coarse, the draws after a restart are first the coarse
  // ladder's (render/coarse.h: targets of its own, tiles of the same size in pixels); they
  // return 0 and add nothing to the full-resolution mean.
  int step();
  // A sweep is in progress: of the full-resolution mean, or the coarse ladder has started.
  bool mid_sweep() const { return accum_.mid_sweep() || (coarse_on() && accum_.samples() == 0 && ladder().started()); }
  // The divisor of each axis of the image display() shows: 1 (the full-resolution mean),
  // or a coarse level's 8, 4, 2 while no full-resolution sweep is complete.
  int shown_divisor() const;
  // The ladder runs where the settings ask for it, with adaptive sampling too (the coarse
  // levels are adaptive accumulators whose one sweep gives every tile one sample).
  bool coarse_on() const { return settings_.coarse; }
  const CoarseLadder& ladder() const;  // since the last restart
  // The pixel samples the last step() drew: its pixels times the sweep's samples per
  // pixel (0 when it drew nothing); a coarse draw's pixels are its own (fewer).
  long last_draw_samples() const { return last_draw_samples_; }
  // One draw, waited for, then a restart: drivers that compile a program's machine code
  // at its first use (Mesa's llvmpipe does, for compute kernels) do it here, outside a
  // timed render. The estimate is as if it never ran.
  void warm_up() {
    step();
    glFinish();
    restart();
  }
  // Tone-mapped image into the bound draw framebuffer at viewport (x, y, w, h) = size():
  // with settings().aux and denoise > 0 the denoised one (shown()); while shown_divisor()
  // > 1 the coarse level's, upscaled (nearest; render/display.h says why).
  void display(int x, int y) const;
  // What display() and read_display() show: the mean, or with the denoiser on its image,
  // filtered again at 1, 2, 4, ... samples and on a restart (in between the last one).
  const Texture& shown() const;
  // The denoiser's image of the current mean with blend weight w (needs settings().aux),
  // filtered again only when the samples, the image or w changed; the accumulator is only read.
  const Texture& denoised(float weight) const;
  std::vector<float> read_denoised(float weight) const;  // RGB radiance, A 1
  // The page's denoiser, in slices across frames (Denoiser::advance): shown() then shows
  // the raw mean until a filtered image of this image is complete (the last one while the
  // next is made), and advance_denoiser(units), called once a frame, starts a run when one
  // is due (at 1, 2, 4, ... samples of an image, and on a restart) and draws `units` of it.
  // Off (the command line, the tests): shown() filters whole runs when they are due.
  void set_sliced_denoise(bool on) { sliced_ = on; }
  void advance_denoiser(double units);
  // The samples of the filtered image shown() shows (0: the raw mean).
  int denoised_samples() const;
  // The denoiser's cost on the current mean (Denoiser::time: ms of each run, sorted), with
  // its params or, for those runs only, `params`; the output then holds this image at
  // `weight` with its own params (else it is filtered again at its next use).
  std::vector<double> time_denoiser(float weight, int runs = 3, const DenoiseParams* params = nullptr) const;
  Denoiser& denoiser() const { return denoiser_; }
  const Accumulator& accumulator() const { return accum_; }
  GLuint vertex_array() const { return vao_; }  // the fullscreen triangle's (no attributes)

  int samples() const { return accum_.samples(); }
  double paths() const { return accum_.paths(); }  // since the restart, sweeps in progress included
  bool converged() const { return settings_.sample_limit > 0 && samples() >= settings_.sample_limit; }
  int width() const { return accum_.width(); }
  int height() const { return accum_.height(); }
  const RenderSettings& settings() const { return settings_; }
  const Camera& camera() const { return camera_; }
  GLenum accum_format() const { return accum_.format(); }
  // A GL ES 3.1+ context (natively; never WebGL 2) with float images: settings.compute
  // then runs the integrator as a compute kernel over 8x8 pixel groups instead of a
  // fragment pass. Same code, same estimate (tests/compute_kernel_test.cpp).
  bool compute_supported() const { return compute_supported_; }
  bool using_compute() const { return settings_.compute && compute_supported_; }
  // A scene's features with auto's traversal (flat or BVH: accel/accel_choice.h), from its
  // packing when given (else packed here when small): what set_scene compiles for it.
  static Features scene_features(const Scene& scene, const PackedScene* packed = nullptr);
  bool using_flat() const { return with_settings(features_, settings_.mode).flat; }  // the program has no BVH traversal
  // The features of the program `scene` gets with the current settings (no GL work).
  Features program_features(const Scene& scene) const { return features_for(scene, settings_.mode); }
  const ShaderSource& integrator_source() const { return *source_; }
  double compile_ms() const { return integrator_ ? integrator_->compile_ms() : 0.0; }
  GLuint program_id() const { return integrator_ ? integrator_->id() : 0u; }  // the integrator's (tests: its uniform blocks)
  size_t programs_compiled() const { return programs_.size(); }
  // Builds started and not finished (ProgramCache::poll, pending): the page polls every frame.
  void poll_programs() { programs_.poll(); }
  std::vector<std::string> pending_programs() const { return programs_.pending(); }
  // The acceleration structure of the current scene.
  struct BvhStats {
    int primitives = 0, nodes = 0, depth = 0;
    double build_ms = 0.0;
  };
  const BvhStats& bvh_stats() const { return bvh_stats_; }
  // What this context allows (queried in the constructor). Lowering them makes the
  // renderer refuse what a smaller GPU would (tests; nothing else should call it).
  const GlLimits& limits() const { return limits_; }
  void override_limits(const GlLimits& l) { limits_ = l; }

  // Linear radiance (RGB) and a bound on the variance of the samples' luminance (A, as
  // Accumulator::read_radiance), rows bottom to top.
  std::vector<float> read_radiance() const;
  // Per pixel RGB, the variance of its samples about their mean (biased: / samples); A 0.
  std::vector<float> read_variance() const;
  // The estimated relMSE of the current mean, whole image and per tile (reads back three
  // float images; core/metrics.h says how it is estimated).
  ErrorEstimate estimate_error() const { return error_.estimate(accum_); }
  // Tone-mapped 8-bit RGBA as display() shows it (a coarse level upscaled), rows bottom to top.
  std::vector<uint8_t> read_display() const;
  using Counters = RenderCounters;  // totals since the last restart, counted in the shader
  Counters counters() const { return accum_.counters(); }

 private:
  Features features_for(const Scene& scene, RenderMode mode) const;
  Features with_settings(Features f, RenderMode mode) const;
  void select_program();  // the cached (or newly built) program for features_ + settings_.mode
  // One draw of tile t into accumulator a, an image of the full image's frame at 1/divisor
  // of each axis (1: the full-resolution mean).
  void draw_tile(Accumulator& a, const Accumulator::Tile& t, int divisor);
  void coarse_step();  // one draw of the ladder's level in progress
  GlLimits limits_;       // first: the constructor checks them before building anything
  GLuint vao_ = 0;        // the fullscreen triangle's (no attributes)
  int vao_made_in_ = gl_objects::generation();
  Display display_;
  Accumulator accum_;
  Accumulator coarse_[CoarseLadder::kLevels];  // the ladder's levels, with auxiliaries as accum_
  mutable CoarseLadder ladder_;
  mutable int ladder_epoch_ = -1;  // accum_'s epoch the ladder belongs to: a restart restarts it
  ErrorEstimator error_;  // snapshots of accum_'s mean for its error estimate
  mutable Denoiser denoiser_;
  struct Filtered {
    int epoch = -1, samples = -1;
    float weight = -1.0f;
    double estimate = -2.0;  // settings_.denoise_estimate of the run (its weight measured from it)
  };
  mutable Filtered denoised_;  // what denoiser_'s output holds, complete
  mutable Filtered job_;       // the sliced run in progress or last finished (advance_denoiser)
  bool sliced_ = false;
  SceneTextures scene_;
  ProgramCache programs_;
  Features features_;
  bool have_scene_ = false;
  Program* integrator_ = nullptr;
  UniformTables tables_;  // the build's tables as uniform blocks (render/uniform_tables.h)
  const ShaderSource* source_ = nullptr;
  bool compute_supported_ = false;
  long last_draw_samples_ = 0;
  BvhStats bvh_stats_;
  Camera camera_;
  std::vector<glm::vec3> seal_lo_, seal_hi_;  // PackedScene's boxes that seal lights off (u_lights_uniform)
  RenderSettings settings_;
};

}  // namespace pt
