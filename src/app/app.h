// The interactive application: owns the Renderer, the current scene, the Dear ImGui panel
// and the camera controls. The platform creates the GL context and the ImGui backends,
// and calls frame() once per displayed frame between ImGui::NewFrame() and ImGui::Render().
// Its parts: app.cpp (the frame), app_panel.cpp, app_loading.cpp, app_interaction.cpp,
// app_stats.cpp.
#pragma once
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/env_panel.h"
#include "app/touch.h"
#include "gpu/texture.h"
#include "render/packing.h"
#include "render/pacing.h"
#include "render/pipeline.h"
#include "render/renderer.h"
#include "render/scene_render.h"
#include "scene/scene.h"

namespace pt {

struct AppOptions {
  std::string scene_root = "/scenes";                    // searched recursively for *.xml, *.gltf, *.glb
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
  float target_relmse = 0.0f;                            // stop once the estimate is at most this; 0 = none
  bool coarse = true;                                    // the coarse first image after a restart (render/coarse.h)
  Accel accel = Accel::Auto;                             // the traversal (accel/accel_choice.h; the URL's accel=)
  bool gltf_ms = true;                                   // the glTF BSDF's energy compensation (the URL's gltfms=off: the spec's model)
  std::optional<bool> adaptive;                          // adaptive sampling (the URL's adaptive=on|off); unset: App::kAdaptiveByDefault
  std::optional<bool> denoise;                           // the denoiser on the shown image (the URL's denoise=on|off); unset: on
  // The raw pass, a measurement (the URL's raw=ROWS, tools/page_cost.mjs): one draw of this
  // many whole rows per frame, no pacing, no panel, the image shown every kRawShowMs; 0: the page.
  int raw_rows = 0;
  std::string gl_renderer;                               // shown in the panel and the stats
  // Hands a finished file to the platform (the page downloads it); unset: no save buttons.
  std::function<void(const std::string& name, const std::vector<uint8_t>& bytes, const char* mime)> save_file;
  // Fetches a scene chosen in the panel (and the files it references) before it is
  // loaded: the page stages them over HTTP into its file system, then calls load_scene.
  // Unset: the panel loads from the file system directly.
  std::function<void(const std::string& path)> request_scene;
};

class App {
 public:
  // Needs a current WebGL 2 / GLES 3 context. Throws GlError when the GPU cannot render to
  // float targets (the platform shows that message instead of a blank canvas).
  explicit App(AppOptions options);

  // One animation frame: input, the ImGui panel (built, not rendered) and the draws.
  // now_ms: a monotonic clock. The image reaches the default framebuffer (fb_w x fb_h,
  // device pixels) only through present(), which the platform calls when present_due()
  // or the panel changed: an unchanged canvas is not drawn again (the browser keeps
  // showing the last frame), so an idle page costs the GPU nothing.
  void frame(int fb_w, int fb_h, double now_ms);
  // Whether this frame changed the image: another sample count, size or display setting,
  // draws kPartialMs after the last present, or kRefreshMs since it (anything else that shows).
  bool present_due(double now_ms) const;
  // Clears the default framebuffer and draws the image into it (then the platform draws
  // the panel over it).
  void present(int fb_w, int fb_h, double now_ms);
  static constexpr double kRefreshMs = 250.0, kPartialMs = 100.0, kRawShowMs = 1000.0;
  static constexpr double kDenoiseUnits = 16.0;  // the denoiser's work per pixel drawn (render_passes)
  static constexpr bool kAdaptiveByDefault = true;  // the panel's "adaptive" (App::App; the URL's adaptive=off)

  // Test hooks.
  std::string stats_json() const;                        // see web/index.html: ptStats()
  // Samples, scene, error, loads and the loading fields of the stats, without reading the
  // image back: cheap enough to poll every frame (ptLoadStatus()).
  std::string load_status_json() const;
  // The pixels of one draw at the size the pacer chose (bands of rows, tiles of columns).
  double draw_pixels() const;
  // The current view as URL parameters (scene, cam, bounces, tonemap, exposure): a link
  // with them reproduces it. The page keeps its address up to date with this.
  std::string view_query() const;
  void set_fixed_size(int w, int h);                     // 0, 0: follow the framebuffer
  void set_sample_limit(int n);
  void set_denoise(bool on) { denoise_ = on; }           // as the panel's toggle (ptSetDenoise)
  // The denoiser's cost on the current image (ptTimeDenoise): the median of 3 runs in ms
  // (Renderer::time_denoiser), the albedo term and regression forced on or off whatever
  // the sample count (its gate); -1 before the first sample.
  double time_denoise(bool regression);
  // false: error() says why and the current scene stays. keep_camera: a reload of an
  // edited scene keeps the view. The scene is then prepared (packed, its BVH built) in
  // slices of a few milliseconds (work(), and frame()) and its program built in the
  // background where the browser can (KHR_parallel_shader_compile), while the current
  // scene keeps rendering; it replaces the current one, at once, when ready. A failure
  // on the way shows its error and leaves the current scene and its samples.
  bool load_scene(const std::string& path, bool keep_camera = false);
  // A slice of that preparation, of about budget_ms; true while more remains. The page
  // calls it between animation frames (web.cpp), so the build uses the time the frames
  // leave idle; frame() does a slice too.
  bool work(double budget_ms);
  // work() has more to do: reading, packing, or uploading the record textures.
  bool preparing() const { return loading_ && loading_->pipe->preparing(); }
  const Scene& scene() const { return scene_; }
  std::string scene_files_json() const;                  // Scene::files of the current scene
  std::string scene_list_json() const;                   // the panel's scene list (the gallery)
  // The platform: keys move the camera only while the canvas has keyboard focus.
  void set_keyboard_enabled(bool on) { keys_enabled_ = on; }
  // Touch (app_interaction.cpp, issue 16): the platform feeds the recogniser the touches
  // that started on the image, and says each frame how many device pixels a CSS pixel is
  // and whether the screen is a touch screen. Below kCompactWidth CSS pixels of width (or
  // of height on a touch screen: a phone turned sideways) the panel starts collapsed to a
  // one-line bar.
  TouchRecognizer& touch() { return touch_; }
  void set_display(float pixels_per_css, bool touch_screen);
  static constexpr float kCompactWidth = 600.0f;
  std::string ui_json() const;  // the panel's state and rectangles, the touch state (ptUi())
  // The GL context was lost and is back: every GL object is re-created (the scene model,
  // camera and settings are kept) and rendering starts again.
  void context_restored();
  const std::vector<float>& radiance_snapshot();         // RGBA float, rows bottom to top
  const std::vector<uint8_t>& display_snapshot();        // tone-mapped RGBA8, rows bottom to top
  const Renderer& renderer() const { return *renderer_; }

 private:
  void handle_input(double dt_s);
  void draw_panel();
  void draw_scene_controls();
  void render_passes(double now_ms, double dt_ms);
  void scan_scenes();
  // app_loading.cpp: scenes through the pipeline. edit: the shown scene again (an edit, a
  // lost context): the page's settings are kept.
  void start_loading(Scene scene, bool keep_camera, bool edit = false);
  void apply_scene(ScenePipeline& pipe, const std::optional<Camera>& camera);
  void poll_loading();
  void draw_loading();
  // app_interaction.cpp: picking and the selection panel, render size.
  void scene_edited(int moved_shape);  // after a panel changed scene_ (-1: no shape moved)
  void handle_click();
  void pick_at(glm::vec2 pos);  // a click's or a tap's selection (device pixels, y down)
  // The touch gestures of the frame, applied to c (look as the mouse drag at deg_per_pixel,
  // pinch, pan; a tap picks, a double tap resets to the scene's view); true if c changed.
  bool apply_touch(Camera& c, float deg_per_pixel);
  // The compact panel: the one-line bar in place of the collapsed panel (true: drawn, the
  // panel is not), and the expanded panel's button that collapses it again.
  bool draw_panel_bar();
  void draw_panel_collapse();
  void draw_selection_panel(int fb_w);
  void draw_view_controls();
  glm::ivec2 render_size(int fb_w, int fb_h, double now_ms) const;
  glm::vec2 image_pixel(glm::vec2 mouse) const;  // device pixels, y down -> image pixels, y up

  AppOptions options_;
  std::unique_ptr<Renderer> renderer_;
  Scene scene_;
  RenderSettings settings_;
  std::vector<std::string> scene_files_;  // paths under options_.scene_root
  std::optional<std::string> error_;
  EnvPanel env_panel_;

  // Frame pacing: the draws per frame and their size follow the interval between frames.
  double last_frame_ms_ = -1.0;
  // What the last present() showed (present_due()).
  struct Shown {
    int fb_w = -1, fb_h = -1, w = -1, h = -1, samples = -1, denoised = -1;  // denoised: the filtered image's samples
    RenderSettings settings;
    bool operator==(const Shown&) const = default;
  };
  Shown presented_, frame_key_;  // the last presented; this frame's
  bool drew_ = false;           // this frame drew samples
  double presented_ms_ = -1e9;
  long presents_ = 0;  // present() calls (ptLoadStatus().presents: tools/page_cost.mjs)
  FramePacer pacer_;

  // Progress: samples per second over the last few seconds of rendering (frames can be
  // slow: with a software GPU one pass may take most of a second); elapsed time since the
  // restart.
  struct RatePoint {
    double ms;
    double samples;  // samples drawn up to and including this frame (fractions of the image)
  };
  std::vector<RatePoint> rate_history_;
  double total_samples_ = 0;
  double samples_per_second_ = 0.0;
  double restart_ms_ = 0.0, done_ms_ = -1.0;
  // What the panel's live readouts (samples/s, elapsed, time to the target) show: taken
  // kRefreshMs apart, and at once when the sample count or the run's state changes. Taken
  // every frame, they changed the panel every frame, and a changed panel is a whole
  // present (the image's display pass, then the panel: src/platform/web.cpp). What that
  // saves was not measurable against the spread of SwiftShader runs here
  // (docs/benchmarks.md, "The pacer's window").
  struct Readout {
    double ms = -1e30;  // when taken (the frame's clock), and the clock the readouts use
    double samples_per_second = 0.0;
    int samples = -1;
    bool done = false;
  };
  Readout readout_;
  void take_readout();

  // The estimated error (issue 14; app_stats.cpp, the panel's part in app_panel.cpp): the
  // renderer's estimate of the image's relMSE (three float images read back), taken at
  // sweep ends at 2, 4, 8, ... samples and every kEstimateEveryMs, never more often than
  // kEstimateMinMs nor than keeps its cost under 1/kEstimateShare of the time. A due
  // estimate stops the frame's draws at the end of the sweep in progress (render_settings).
  // With a target, rendering stops once an estimate is at most the target.
  RenderSettings render_settings() const;  // settings_ with the target's stop and a due estimate's
  void update_error(double now_ms);        // after the frame's draws
  void draw_error();                       // the panel's readout, plot and target field
  bool error_trend(double& a, double& b) const;  // log10 relMSE = a + b log10 seconds, fitted
  std::string error_fields() const;              // the stats' JSON fields of the estimate
  struct ErrorPoint {
    double seconds;  // since the restart
    double rel_mse;
    int samples;
  };
  std::vector<ErrorPoint> error_history_;  // since the last restart
  float target_relmse_ = 0.0f;             // 0: none
  // The denoiser (render/denoise.h) on the displayed image: the panel's toggle, on by
  // default; its blend weight, measured by the filter from the last estimate (Denoiser::run),
  // falls from 1 as the estimate falls below the filter's own error.
  bool denoise_ = true;
  float denoise_blend() const;
  int target_stop_at_ = 0;                 // the samples at which an estimate reached the target; 0: not reached
  bool estimate_due_ = false;
  int next_estimate_at_ = 2, estimated_samples_ = 0;
  double last_estimate_ms_ = -1e30, estimate_ms_ = 0.0, error_restart_ms_ = -1.0;
  int estimates_ = 0;  // since the page opened (the stats)

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

  // A scene on its way through the pipeline (read, packed, uploaded in slices, then
  // waiting for its program); applied by poll_loading once ready.
  struct Loading {
    std::unique_ptr<ScenePipeline> pipe;
    bool keep_camera = false;      // the view then is kept, else the scene's is shown
    bool edit = false;             // an edit of the shown scene (scene_edited), not a load
    std::chrono::steady_clock::time_point since;  // when it was asked for
    double longest_slice_ms = 0.0;  // the longest slice of any stage, and its stage
    std::string longest_slice_stage;
  };
  // The settings a loaded scene is shown with: the page's, and the scene's <Render> where
  // the page's link did not set them (on the first scene), clamped to the panel's ranges.
  RenderSettings shown_settings(const Scene& scene) const;
  UserSet link_set() const;  // what the page's link set on the first scene: the scene's <Render> leaves it
  ScenePipeline::ModeFor mode_for(bool edit);  // the program mode of a scene on its way
  void begin_loading(Loading l);    // as loading_, replacing one in progress
  void load_failed(std::string path, std::string why);
  std::string load_fields() const;
  std::string load_stage() const;  // of the scene on its way: "reading model.glb", "building the BVH", ...
  double load_progress() const;  // 0..1
  bool shown_ = false;  // the renderer has a scene (not yet after a lost context)
  std::optional<Loading> loading_;
  std::optional<PackedScene> packed_;  // the shown scene's packing (refit_shape), while nothing else is prepared
  int loads_ = 0, context_restores_ = 0;
  // The last preparation, for the stats: wall time from the request to the swap, the
  // packing's slices and their time, and the longest slice.
  double last_load_ms_ = 0.0, last_pack_work_ms_ = 0.0, last_longest_slice_ms_ = 0.0, last_read_ms_ = 0.0;
  int last_slices_ = 0, last_read_slices_ = 0;
  std::string last_longest_slice_stage_;

  // Picking: a left press and release on the image without moving selects.
  int selected_ = -1;
  glm::vec2 press_pos_{0.0f};
  bool press_on_image_ = false;
  bool keys_enabled_ = true;

  // Touch and the small screen's panel (app_interaction.cpp).
  TouchRecognizer touch_;
  float pixels_per_css_ = 1.0f;
  bool touch_screen_ = false;
  bool compact_ = false;                // narrower than kCompactWidth CSS pixels
  std::optional<bool> panel_collapsed_;  // set on the first frame: collapsed when compact
  glm::vec4 bar_rect_{0.0f}, panel_rect_{0.0f}, hide_rect_{0.0f};  // device pixels, y down (x, y, w, h), as last drawn
  float panel_scroll_ = 0.0f;  // the expanded panel's scroll (a drag of its background scrolls it)

  // Resolution: the render size is render_scale_ x the canvas; while the camera moves
  // (until kSettleMs after the last change) it is kMotionScale of that, refined at full
  // size when it stops.
  float render_scale_ = 1.0f;
  double moving_until_ms_ = -1.0;
  int fb_w_ = 1, fb_h_ = 1;
  glm::vec4 image_rect_{0.0f};  // where present() put the image in the framebuffer (x, y, w, h; y up)

  std::vector<float> snapshot_;
  std::vector<uint8_t> display_snapshot_;
};

}  // namespace pt
