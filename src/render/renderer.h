// The progressive integrator: ping-pong accumulation of the running mean of radiance in
// float textures, one pass = u_spp samples per pixel. Display applies the tone map.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "gpu/program.h"
#include "gpu/texture.h"
#include "gpu/texture_array.h"
#include "core/render_mode.h"
#include "render/sh.h"
#include "core/tonemap.h"
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
  void restart() {
    samples_ = 0;
    next_row_ = next_column_ = 0;
    needs_clear_ = true;
  }

  // One draw: the next tile of the current sweep, unless the sample limit is reached. A
  // sweep is bands of band_rows rows, bottom to top (the whole image when 0); a band is
  // tiles of band_columns columns, left to right (the whole band when 0). A band's rows
  // are fixed when it starts, so band_rows and band_columns may change between any two
  // draws and every pixel is still drawn once per sweep. A sweep adds spp_per_pass
  // samples to every pixel; returns the samples added when this draw completed a sweep,
  // else 0. Tiles keep each draw short (no watchdog, a responsive page); the estimate is
  // the same.
  int step();
  bool mid_sweep() const { return next_row_ != 0 || next_column_ != 0; }
  // The pixel samples the last step() drew: its pixels times the sweep's samples per
  // pixel (0 when it drew nothing).
  long last_draw_samples() const { return last_draw_samples_; }
  // One draw, waited for, then a restart: drivers that compile a program's machine code
  // at its first use (Mesa's llvmpipe does, for compute kernels) do it here, outside a
  // timed render. The estimate is as if it never ran.
  void warm_up() {
    step();
    glFinish();
    restart();
  }
  // Tone-mapped image into the bound draw framebuffer at viewport (x, y, w, h) = size().
  void display(int x, int y) const;

  int samples() const { return samples_; }
  bool converged() const { return settings_.sample_limit > 0 && samples_ >= settings_.sample_limit; }
  int width() const { return width_; }
  int height() const { return height_; }
  const RenderSettings& settings() const { return settings_; }
  const Camera& camera() const { return camera_; }
  GLenum accum_format() const { return accum_format_; }
  // A GL ES 3.1+ context (natively; never WebGL 2) with float images: settings.compute
  // then runs the integrator as a compute kernel over 8x8 pixel groups instead of a
  // fragment pass. Same code, same estimate (tests/compute_kernel_test.cpp).
  bool compute_supported() const { return compute_supported_; }
  bool using_compute() const { return settings_.compute && compute_supported_; }
  const ShaderSource& integrator_source() const { return *source_; }
  double compile_ms() const { return integrator_ ? integrator_->compile_ms() : 0.0; }
  size_t programs_compiled() const { return cache_.size(); }
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

  // Linear radiance (RGB) and mean squared luminance (A), rows bottom to top.
  std::vector<float> read_radiance() const;
  // Tone-mapped 8-bit RGBA, rows bottom to top.
  std::vector<uint8_t> read_display() const;
  // Totals since the last restart, counted in the shader.
  struct Counters {
    double bad_samples = 0;  // NaN/Inf samples (dropped from the estimate)
    double rays = 0;         // every ray cast: camera, bounce and shadow
  };
  Counters counters() const;

 private:
  struct CachedProgram {
    ShaderSource source;
    Program program;
  };
  bool program_ready_for(const Features& f);
  void select_program();  // the cached (or newly built) program for features_ + settings_.mode
  void update_sh();       // the environment's SH coefficients, when the mode needs them
  void set_environment(const Environment& env);  // its textures (a new map only) and uniforms
  Features features_;
  bool have_scene_ = false;
  Environment env_;       // as last set (for the SH projection)
  ShCoeffs sh_{};
  bool sh_valid_ = false;
  Program* integrator_ = nullptr;
  const ShaderSource* source_ = nullptr;
  std::unordered_map<uint64_t, std::unique_ptr<CachedProgram>> cache_;
  mutable Program display_[kNumToneMaps];  // built on first use, one per tone map
  Texture shape_tex_, material_tex_, light_tex_;
  Texture node_tex_, prim_tex_, vertex_tex_;  // the BVH, its primitives, mesh vertex attributes
  Texture env_tex_, env_cdf_tex_;  // when the scene has an environment map
  glm::ivec2 env_size_{0};
  float env_rotation_ = 0.0f, env_intensity_ = 1.0f, env_integral_ = 0.0f;
  std::shared_ptr<const EnvImage> env_source_;  // the image the textures hold
  TextureArray maps_;  // Textured scenes: the image maps (render/image_maps.h)
  Texture uv_tex_;     // and the Triangle uv records
  Texture accum_[2];
  Texture stats_[2];
  Framebuffer fbo_[2];
  GLenum accum_format_ = GL_RGBA32F;
  bool compute_supported_ = false;
  GLuint vao_ = 0;
  int cur_ = 0;
  int samples_ = 0;
  int next_row_ = 0;      // first row of the band in progress or the next one; with
  int next_column_ = 0;   // this 0 too, a new sweep starts; else the band's next tile
  int band_end_ = 0;      // the row after the band in progress (fixed while it lasts)
  long last_draw_samples_ = 0;
  int sweep_spp_ = 1;     // samples per pixel of the sweep in progress
  bool needs_clear_ = true;
  int width_ = 0, height_ = 0;
  int num_lights_ = 0, num_unbounded_ = 0, num_nodes_ = 0, num_shapes_ = 0, num_prims_ = 0;
  std::vector<int> light_shapes_;  // the shape of each light record (update_values keeps them)
  float motion_bound_ = 1.0f;
  BvhStats bvh_stats_;
  bool dot_weight_ = true;
  glm::vec3 env_color_{0.5f};
  Camera camera_;
  RenderSettings settings_;
  GlLimits limits_;
};

}  // namespace pt
