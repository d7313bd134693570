// The interactive application: owns the Renderer, the current scene, the Dear ImGui panel
// and the camera controls. The platform creates the GL context and the ImGui backends,
// and calls frame() once per displayed frame between ImGui::NewFrame() and ImGui::Render().
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/env_panel.h"
#include "gpu/texture.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace pt {

struct AppOptions {
  std::string scene_root = "/scenes";                    // searched recursively for *.xml
  std::string scene = "/scenes/reference/scene2.xml";    // first scene shown
  std::string env_root = "/assets/env";                  // the shipped HDR maps (*.hdr)
  int width = 0, height = 0;                             // fixed render size; 0 = framebuffer size
  int sample_limit = 0;                                  // 0 = unlimited
  // A view from a link (URL parameters): the camera pose and main settings, applied
  // after the first scene loads. Unset fields keep the scene's and the defaults.
  std::optional<glm::vec3> camera_position;
  std::optional<glm::vec2> camera_yaw_pitch;           // degrees
  std::optional<int> bounces;
  std::optional<ToneMap> tonemap;
  std::optional<float> exposure;                        // fixed; unset = auto
  std::string gl_renderer;                               // shown in the panel and the stats
  // Hands a finished file to the platform (the page downloads it); unset: no save buttons.
  std::function<void(const std::string& name, const std::vector<uint8_t>& bytes, const char* mime)> save_file;
};

class App {
 public:
  // Needs a current WebGL 2 / GLES 3 context. Throws GlError when the GPU cannot render to
  // float targets (the platform shows that message instead of a blank canvas).
  explicit App(AppOptions options);

  // One displayed frame into the default framebuffer of size fb_w x fb_h (device
  // pixels). now_ms: a monotonic clock. Builds the ImGui panel, does not render ImGui.
  void frame(int fb_w, int fb_h, double now_ms);

  // Test hooks.
  std::string stats_json() const;                        // see web/index.html: ptStats()
  // The current view as URL parameters (scene, cam, bounces, tonemap, exposure): a link
  // with them reproduces it. The page keeps its address up to date with this.
  std::string view_query() const;
  void set_fixed_size(int w, int h);                     // 0, 0: follow the framebuffer
  void set_sample_limit(int n);
  bool load_scene(const std::string& path);              // false: error() says why
  const std::vector<float>& radiance_snapshot();         // RGBA float, rows bottom to top
  const std::vector<uint8_t>& display_snapshot();        // tone-mapped RGBA8, rows bottom to top
  const Renderer& renderer() const { return *renderer_; }

 private:
  void handle_input(double dt_s);
  void draw_panel();
  void draw_scene_controls();
  void render_passes(double now_ms, double dt_ms);
  void present(int fb_w, int fb_h);
  void scan_scenes();

  AppOptions options_;
  std::unique_ptr<Renderer> renderer_;
  Scene scene_;
  RenderSettings settings_;
  std::vector<std::string> scene_files_;  // paths under options_.scene_root
  std::optional<std::string> error_;
  EnvPanel env_panel_;

  // Frame pacing: the number of passes per frame adapts to the interval between frames.
  double last_frame_ms_ = -1.0;
  int passes_per_frame_ = 1;

  // Progress: samples per second over the last few seconds of rendering (frames can be
  // slow: with a software GPU one pass may take most of a second); elapsed time since the
  // restart.
  struct RatePoint {
    double ms;
    long samples;  // samples issued up to and including this frame
  };
  std::vector<RatePoint> rate_history_;
  long total_samples_ = 0;
  double samples_per_second_ = 0.0;
  double restart_ms_ = 0.0, done_ms_ = -1.0;

  // Auto exposure (display only): the log-average luminance of the estimate is mapped to
  // middle grey, re-measured at 4, 8, 16, ... samples (up to every 512) after a restart.
  void update_auto_exposure();
  bool auto_exposure_ = true;
  int next_exposure_at_ = 4;

  // Mouse look: whether the current left-drag started on the canvas (not on the panel).
  bool dragging_ = false;

  // Offscreen target used when the render size differs from the framebuffer size.
  Texture present_tex_;
  Framebuffer present_fbo_;

  std::vector<float> snapshot_;
  std::vector<uint8_t> display_snapshot_;
};

}  // namespace pt
