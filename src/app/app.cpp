#include "app/app.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <GLFW/glfw3.h>  // key codes only: the ImGui GLFW backend indexes io.KeysDown by them
#include <imgui.h>

#include "core/image.h"
#include "render/camera.h"
#include "scene/xml_loader.h"

namespace pt {
namespace {

// Frame pacing. WebGL calls only queue commands, so the CPU time of step() says little
// about the GPU; but once the GPU falls behind, the browser delays the next animation
// frame until the queued work is done. The interval between frames is the feedback: add a
// pass while frames come faster than kFastFrameMs, scale the passes down to the target
// when a frame took longer than kSlowFrameMs. A step whose CPU time exceeds the budget
// means the call blocked on the GPU (a full command queue, or a blocking driver): stop.
constexpr double kFastFrameMs = 20.0;
constexpr double kSlowFrameMs = 28.0;
constexpr double kTargetFrameMs = 22.0;
constexpr double kCpuBudgetMs = 12.0;
constexpr int kMaxPassesPerFrame = 64;
// A draw is a tile of a sweep (Renderer::step): a band of rows or, at kMinBandRows
// rows, part of such a band. When even one draw per frame keeps frames slower than
// kSlowDrawFrameMs (under 30 UI frames/s: two frames in a row, or one twice as slow)
// the draw shrinks: rows first, then columns, down to kMinBandRows x min_band_columns().
// It grows back while frames are faster than kGrowDrawFrameMs: columns to the whole
// width, then rows to the whole image, then more draws per frame. Growth is gentle
// unless frames are fast: a software GL spends a large fixed time per frame (SwiftShader:
// about 22 ms for compositing, the panel and the display pass at 960x640 on 2 cores,
// docs/benchmarks.md), so a draw there may have a few milliseconds, and the pacer has to
// settle at the largest such draw, not jump past it. A GPU paced by vsync gives frames
// of 16.7 or 33.3 ms: it grows until frames take two intervals and stays there. Bands
// keep at least 4 rows: SwiftShader hands pairs of pixel rows to its threads in turn,
// so a thinner draw leaves one of two cores idle.
constexpr int kFirstBandRows = 32;
constexpr double kSlowDrawFrameMs = 34.0;
constexpr double kGrowDrawFrameMs = 28.0;
constexpr int kMinBandRows = 4;
constexpr int kMinBandColumns = 128;
// Nor are draws smaller than a sweep over this many draws (a bigger canvas, bigger draws):
// at 30 frames/s a sweep then takes at most about 35 s.
constexpr int kMaxDrawsPerSweep = 1024;
// The interval between frames answers a change of the draw size a frame or two late
// (the browser runs that far ahead of the GPU): no second change before then.
constexpr int kDrawSettleFrames = 2;
// How long a floor under the draw size (judge_shrink) holds before shrinking is tried again.
constexpr double kDrawFloorMs = 5000.0;
constexpr double kRateWindowMs = 3000.0;

constexpr float kLookDegPerPixel = 0.2f;
constexpr double kSettleMs = 200.0;  // the camera counts as moving until this long after its last change
constexpr float kTurnDegPerSecond = 90.0f;

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

// Also used by app_interaction.cpp.
std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}


App::App(AppOptions options) : options_(std::move(options)), renderer_(std::make_unique<Renderer>()) {
  settings_.sample_limit = options_.sample_limit;
  settings_.band_rows = kFirstBandRows;  // the first frame of a heavy scene stays short
  renderer_->set_settings(settings_);
  scan_scenes();
  env_panel_.scan(options_.env_root);
  if (!load_scene(options_.scene)) {
    // Nothing rendered yet, so there is no previous scene to keep: fall back to the
    // default one, but keep showing why the requested scene failed.
    const std::string why = error_.value_or("");
    const std::string fallback = AppOptions{}.scene;
    if (options_.scene != fallback && load_scene(fallback)) error_ = why;
  }
  // A view from a link: its camera is applied when the first scene is (apply_scene).
  if (options_.bounces) settings_.max_bounces = std::clamp(*options_.bounces, 1, 16);
  if (options_.tonemap) settings_.tonemap = *options_.tonemap;
  if (options_.exposure) {
    settings_.exposure = *options_.exposure;
    auto_exposure_ = false;
  }
  renderer_->set_settings(settings_);
}

std::string App::view_query() const {
  const Camera& c = renderer_->camera();
  std::string scene = scene_.path;
  if (scene.rfind(options_.scene_root + "/", 0) == 0) scene = scene.substr(options_.scene_root.size() + 1);
  char cam[160];
  std::snprintf(cam, sizeof cam, "%.4g,%.4g,%.4g,%.4g,%.4g", double(c.position.x), double(c.position.y), double(c.position.z),
                double(c.yaw), double(c.pitch));
  std::string q = "scene=" + scene + "&cam=" + cam + "&bounces=" + std::to_string(settings_.max_bounces) +
                  "&tonemap=" + kToneMapNames[int(settings_.tonemap)];
  if (!auto_exposure_) {
    char e[32];
    std::snprintf(e, sizeof e, "%.4g", double(settings_.exposure));
    q += std::string("&exposure=") + e;
  }
  return q;
}

void App::scan_scenes() {
  namespace fs = std::filesystem;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(options_.scene_root, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file() && it->path().extension() == ".xml") scene_files_.push_back(it->path().string());
  std::sort(scene_files_.begin(), scene_files_.end());
}

bool App::load_scene(const std::string& path, bool keep_camera) {
  try {
    // The XML is checked here; its meshes are read in slices (work()).
    auto read = std::make_unique<SceneLoad>(read_scene_file(path), path);
    error_.reset();
    Loading l;
    l.path = path;
    l.read = std::move(read);
    l.keep_camera = keep_camera && loads_ > 0;
    begin_loading(std::move(l));
    return true;
  } catch (const std::exception& e) {
    error_ = e.what();
    return false;
  }
}

void App::set_fixed_size(int w, int h) {
  options_.width = std::max(0, w);
  options_.height = std::max(0, h);
}

void App::set_sample_limit(int n) { settings_.sample_limit = std::max(0, n); }

void App::frame(int fb_w, int fb_h, double now_ms) {
  const double dt_ms = last_frame_ms_ < 0 ? 0.0 : now_ms - last_frame_ms_;
  last_frame_ms_ = now_ms;

  fb_w_ = fb_w;
  fb_h_ = fb_h;
  poll_loading();
  handle_input(std::min(dt_ms, 100.0) * 1e-3);
  handle_click();
  const glm::ivec2 size = render_size(fb_w, fb_h, now_ms);
  renderer_->resize(size.x, size.y);
  draw_panel();
  draw_selection_panel(fb_w);
  renderer_->set_settings(settings_);  // restarts only when the estimate changes
  render_passes(now_ms, dt_ms);
  update_auto_exposure();
  present(fb_w, fb_h);
}

void App::update_auto_exposure() {
  const int n = renderer_->samples();
  if (n < next_exposure_at_ / 2) next_exposure_at_ = 4;  // restarted since the last measure
  if (!auto_exposure_ || n < next_exposure_at_) return;
  settings_.exposure = float(auto_exposure(renderer_->read_radiance()));
  renderer_->set_settings(settings_);
  next_exposure_at_ = std::min(n * 2, n + 512);
}

void App::handle_input(double dt_s) {
  const ImGuiIO& io = ImGui::GetIO();
  Camera c = renderer_->camera();
  const glm::vec3 forward = camera_forward(c);
  const glm::vec3 up = glm::normalize(c.up);
  const glm::vec3 right = glm::normalize(glm::cross(forward, up));
  // Scene units differ by orders of magnitude between scenes: move at 1% of the distance
  // to the origin per 60 Hz frame, at least one unit.
  const float step = std::max(1.0f, 0.01f * glm::length(c.position));
  const float move = step * 60.0f * float(dt_s);
  bool changed = false;

  // Keys only while the canvas has focus and no modifier is held: Ctrl+W, Alt+Left and
  // friends stay the browser's.
  if (!io.WantCaptureKeyboard && keys_enabled_ && !io.KeyCtrl && !io.KeyAlt && !io.KeySuper && !io.KeyShift) {
    const auto down = [&](int key) { return io.KeysDown[key]; };
    glm::vec3 d(0.0f);
    if (down(GLFW_KEY_W)) d += up;
    if (down(GLFW_KEY_S)) d -= up;
    if (down(GLFW_KEY_D)) d += right;
    if (down(GLFW_KEY_A)) d -= right;
    if (down(GLFW_KEY_Q)) d += forward;
    if (down(GLFW_KEY_E)) d -= forward;
    if (d != glm::vec3(0.0f)) {
      c.position += d * move;
      changed = true;
    }
    const float turn = kTurnDegPerSecond * float(dt_s);
    const float yaw = float(down(GLFW_KEY_RIGHT) - down(GLFW_KEY_LEFT));
    const float pitch = float(down(GLFW_KEY_UP) - down(GLFW_KEY_DOWN));
    if (yaw != 0.0f || pitch != 0.0f) {
      c.yaw += yaw * turn;
      c.pitch += pitch * turn;
      changed = true;
    }
  }

  // A drag looks around only if it started on the image, not on a panel, and only from
  // the frame after the press: the move that brought the pointer there is not a drag
  // (a click that picks an object leaves the view alone).
  const bool was_dragging = dragging_;
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !io.WantCaptureMouse) dragging_ = true;
  if (!io.MouseDown[ImGuiMouseButton_Left]) dragging_ = false;
  if (was_dragging && dragging_ && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
    c.yaw += io.MouseDelta.x * kLookDegPerPixel;
    c.pitch -= io.MouseDelta.y * kLookDegPerPixel;
    changed = true;
  }
  if (!io.WantCaptureMouse && io.MouseWheel != 0.0f) {
    c.position += forward * (io.MouseWheel * 5.0f * step);
    changed = true;
  }

  if (changed) {
    c.pitch = std::clamp(c.pitch, -89.0f, 89.0f);
    c.yaw = std::fmod(c.yaw + 360.0f, 360.0f);
    renderer_->set_camera(c);
    moving_until_ms_ = last_frame_ms_ + kSettleMs;
  }
}

// Values of the scene: editing them re-packs its data and restarts, never recompiles
// (the program depends only on the kinds present). Ranges follow the seed's sliders.
void App::draw_scene_controls() {
  bool edited = false, moved = false;
  if (!scene_.lights.empty() && ImGui::CollapsingHeader("Light", ImGuiTreeNodeFlags_DefaultOpen)) {
    Light& l = scene_.lights[0];
    moved = ImGui::SliderFloat3("position", &l.position.x, -300.0f, 300.0f);
    bool changed = ImGui::ColorEdit3("colour", &l.color.x);
    changed |= ImGui::SliderFloat("intensity", &l.intensity, 0.0f, 300.0f);
    if (changed || moved) {
      sync_light(scene_, 0);
      edited = true;
    }
  }
  edited |= env_panel_.draw(scene_.environment);
  Camera cam = renderer_->camera();
  if (ImGui::CollapsingHeader("Lens and shutter")) {
    const float scale = std::max(1.0f, glm::length(cam.position));  // drag speeds follow the scene's size
    bool changed = ImGui::DragFloat("aperture", &cam.aperture, 0.001f * scale, 0.0f, scale, "%.3f");
    changed |= ImGui::DragFloat("focal distance", &cam.focal_distance, 0.005f * scale, 0.001f * scale, 100.0f * scale, "%.2f");
    changed |= ImGui::SliderFloat("shutter", &cam.shutter, 0.0f, 1.0f);
    if (changed) renderer_->set_camera(cam);
  }
  if (edited) scene_edited(moved ? scene_.lights[0].shape : -1);
}

void App::draw_panel() {
  const std::string& root = options_.scene_root;
  const auto label = [&](const std::string& path) {
    return path.rfind(root + "/", 0) == 0 ? path.substr(root.size() + 1) : path;
  };
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::Begin("Path tracer", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  // Long texts (errors, the GPU's name) wrap instead of widening the auto-sized panel.
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 24.0f);
  ImGui::PushItemWidth(ImGui::GetFontSize() * 14.0f);

  if (ImGui::BeginCombo("scene", label(scene_.path).c_str())) {
    for (const std::string& f : scene_files_) {
      const bool selected = f == scene_.path;
      if (ImGui::Selectable(label(f).c_str(), selected)) {
        if (options_.request_scene) options_.request_scene(f);
        else load_scene(f);
      }
      if (selected) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  }
  if (error_) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextUnformatted(error_->c_str());
    ImGui::PopStyleColor();
  }

  ImGui::SliderInt("bounces", &settings_.max_bounces, 1, 16);
  if (ImGui::InputInt("sample limit", &settings_.sample_limit, 16, 256)) settings_.sample_limit = std::max(0, settings_.sample_limit);
  int tonemap = int(settings_.tonemap);
  if (ImGui::Combo("tone map", &tonemap, kToneMapNames, kNumToneMaps)) settings_.tonemap = ToneMap(tonemap);
  if (ImGui::SliderFloat("exposure", &settings_.exposure, 0.001f, 16.0f, "%.3f", ImGuiSliderFlags_Logarithmic))
    auto_exposure_ = false;
  ImGui::SameLine();
  if (ImGui::Checkbox("auto", &auto_exposure_) && auto_exposure_) next_exposure_at_ = 0;

  draw_scene_controls();
  int mode = int(settings_.mode);  // each mode is its own program, compiled on first use
  if (ImGui::Combo("mode", &mode, kRenderModeLabels, kNumRenderModes)) settings_.mode = RenderMode(mode);
  if (options_.save_file) {
    // PNG: the image as displayed (tone-mapped); HDR: linear radiance.
    const int w = renderer_->width(), h = renderer_->height();
    if (ImGui::Button("save PNG")) options_.save_file("pathtracer.png", encode_png(w, h, renderer_->read_display()), "image/png");
    ImGui::SameLine();
    if (ImGui::Button("save HDR"))
      options_.save_file("pathtracer.hdr", encode_hdr(w, h, renderer_->read_radiance()), "image/vnd.radiance");
  }

  ImGui::Separator();
  const double end_ms = done_ms_ >= 0 ? done_ms_ : last_frame_ms_;
  if (settings_.sample_limit > 0)
    ImGui::Text("samples    %d / %d", renderer_->samples(), settings_.sample_limit);
  else
    ImGui::Text("samples    %d", renderer_->samples());
  ImGui::Text("samples/s  %.1f", samples_per_second_);
  ImGui::Text("elapsed    %.1f s", std::max(0.0, end_ms - restart_ms_) * 1e-3);
  ImGui::Text("resolution %d x %d", renderer_->width(), renderer_->height());
  draw_view_controls();
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextUnformatted(options_.gl_renderer.c_str());
  ImGui::PopStyleColor();
  ImGui::PopItemWidth();
  ImGui::PopTextWrapPos();
  ImGui::End();
}

// The narrowest tile of a band of kMinBandRows rows.
int App::min_band_columns() const {
  const int w = renderer_->width(), h = renderer_->height();
  const int per_sweep = (double(w) * h) / (double(kMaxDrawsPerSweep) * std::min(kMinBandRows, std::max(1, h))) + 1;
  return std::min(w, std::max(kMinBandColumns, per_sweep));
}

// Scales the draw (band_rows x band_columns) by `factor` in pixels: whole rows down to
// kMinBandRows, then columns down to min_band_columns(); the reverse when growing.
void App::scale_draw(double factor) {
  const int w = renderer_->width(), h = renderer_->height();
  const int rows = settings_.band_rows > 0 ? std::min(settings_.band_rows, h) : h;
  const int columns = settings_.band_columns > 0 && rows <= kMinBandRows ? std::min(settings_.band_columns, w) : w;
  const double now = double(rows) * columns;
  const double pixels = factor > 1.0 ? std::max(now * factor, now + 1.0) : std::min(now * factor, now - 1.0);
  const int new_rows = std::clamp(int(pixels / w), std::min(kMinBandRows, h), h);
  const int new_columns = new_rows > kMinBandRows || pixels >= double(kMinBandRows) * w
                              ? w
                              : std::clamp(int(pixels / kMinBandRows), min_band_columns(), w);
  settings_.band_rows = new_rows >= h ? 0 : new_rows;
  settings_.band_columns = new_columns >= w ? 0 : new_columns;
  draw_settle_ = kDrawSettleFrames;
}

// Frames still slow after a shrink from shrink_from_pixels_ (frames then
// shrink_from_ms_) to `pixels` (frames now `ms`): the difference prices a pixel. When
// even the smallest draw would leave frames slower than kSlowDrawFrameMs, the fixed cost
// of a frame is what makes them slow (a software GL at a large canvas, or a loaded
// machine): smaller draws would only slow the sweep down, so the draw goes back to the
// size before the shrink and stays at least that for kDrawFloorMs. True when it did.
bool App::judge_shrink(double pixels, double ms, double now_ms) {
  const double from = shrink_from_pixels_;
  shrink_from_pixels_ = 0.0;
  if (from <= pixels) return false;
  const double per_pixel = std::max(0.0, (shrink_from_ms_ - ms) / (from - pixels));
  const double smallest = double(std::min(kMinBandRows, renderer_->height())) * min_band_columns();
  if (ms - per_pixel * std::max(0.0, pixels - smallest) <= kSlowDrawFrameMs) return false;
  floor_pixels_ = from;
  floor_set_ms_ = now_ms;
  scale_draw(from / pixels);
  return true;
}

void App::render_passes(double now_ms, double dt_ms) {
  // The interval since the last frame measures the work queued then (and the hidden time
  // of a background tab, after which the count simply grows back).
  const bool whole = (settings_.band_rows <= 0 || settings_.band_rows >= renderer_->height()) &&
                     (settings_.band_columns <= 0 || settings_.band_columns >= renderer_->width());
  const bool smallest = settings_.band_rows == std::min(kMinBandRows, renderer_->height()) &&
                        settings_.band_columns == (min_band_columns() < renderer_->width() ? min_band_columns() : 0);
  const double pixels = double(settings_.band_rows > 0 ? std::min(settings_.band_rows, renderer_->height()) : renderer_->height()) *
                        (settings_.band_columns > 0 ? std::min(settings_.band_columns, renderer_->width()) : renderer_->width());
  const bool settled = draw_settle_ == 0;
  if (draw_settle_ > 0) --draw_settle_;
  // The draw size follows two frames, not one: a browser catching up after a long frame
  // delivers the next one at once (short), and a single slow frame may be a hiccup.
  const double slower = std::max(dt_ms, prev_dt_ms_), faster = std::min(dt_ms, prev_dt_ms_);
  prev_dt_ms_ = dt_ms;
  if (dt_ms > kSlowFrameMs && !preparing() && settled) {  // frames slowed by a preparation say nothing of the draws
    if (passes_per_frame_ > 1) {
      passes_per_frame_ = std::max(1, int(std::min(0.9, kTargetFrameMs / dt_ms) * passes_per_frame_));
    } else if (dt_ms > 2.0 * kSlowDrawFrameMs) {  // far too slow: the draw, surely; shrink at once
      shrink_from_pixels_ = 0.0;
      if (!smallest) scale_draw(std::min(0.5, kTargetFrameMs / dt_ms));
    } else if (faster > kSlowDrawFrameMs && !judge_shrink(pixels, faster, now_ms) && !smallest && pixels > floor_pixels_) {
      shrink_from_pixels_ = pixels;
      shrink_from_ms_ = faster;
      scale_draw(0.7);
    }
  }
  if (now_ms - floor_set_ms_ > kDrawFloorMs) floor_pixels_ = 0.0;

  if (renderer_->samples() == 0 && !renderer_->mid_sweep()) restart_ms_ = now_ms;
  const auto t0 = std::chrono::steady_clock::now();
  int done = 0;
  // While a scene is being prepared, one draw per frame: the preparation gets the time
  // (and, with a software GPU, the CPU) that more draws would take.
  const int passes = preparing() ? 1 : passes_per_frame_;
  const double image_pixels = std::max(1.0, double(renderer_->width()) * renderer_->height());
  while (done < passes && !renderer_->converged()) {
    renderer_->step();
    // Samples count as they are drawn, in fractions of the image: a sweep of small tiles
    // on a slow GPU may take longer than the rate's window.
    total_samples_ += double(renderer_->last_draw_samples()) / image_pixels;
    ++done;
    if (ms_since(t0) > kCpuBudgetMs) break;
  }
  // Grow only when this frame used all its passes, else an idle (converged) image would
  // ratchet the count up and the next restart would start with one very long frame.
  if (dt_ms > 0 && done == passes_per_frame_ && !preparing() && settled) {
    if (!whole && slower < kGrowDrawFrameMs) {
      shrink_from_pixels_ = 0.0;  // a shrink that let frames get fast did its job
      scale_draw(slower < kFastFrameMs ? 2.0 : 1.25);
    }
    else if (whole && dt_ms < kFastFrameMs) passes_per_frame_ = std::min(kMaxPassesPerFrame, passes_per_frame_ + 1);
  }

  if (!renderer_->converged()) done_ms_ = -1.0;  // a raised limit resumes the clock
  else if (done_ms_ < 0) done_ms_ = now_ms;
  if (done == 0) {
    rate_history_.clear();  // idle frames are not part of the rate; the last rate stays shown
    return;
  }
  rate_history_.push_back({now_ms, total_samples_});
  while (rate_history_.size() > 2 && now_ms - rate_history_[1].ms >= kRateWindowMs)
    rate_history_.erase(rate_history_.begin());
  // The samples issued by the frames after the oldest one, over the time since it.
  const RatePoint& first = rate_history_.front();
  const bool finished = renderer_->converged() && now_ms > first.ms;  // a short render gets a rate too
  if (now_ms - first.ms >= 1000.0 || finished) samples_per_second_ = (total_samples_ - first.samples) * 1000.0 / (now_ms - first.ms);
}

void App::present(int fb_w, int fb_h) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fb_w, fb_h);
  glClearColor(0.06f, 0.06f, 0.07f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  const int w = renderer_->width(), h = renderer_->height();
  if (w == fb_w && h == fb_h) {
    image_rect_ = glm::vec4(0.0f, 0.0f, float(w), float(h));
    renderer_->display(0, 0);
    return;
  }
  // A fixed render size: tone-map into an 8-bit target, then scale it to fit the canvas.
  if (present_tex_.width() != w || present_tex_.height() != h) {
    present_tex_ = Texture(w, h, GL_RGBA8, nullptr);
    present_fbo_ = Framebuffer(present_tex_);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, present_fbo_.id());
  renderer_->display(0, 0);
  const float s = std::min(float(fb_w) / float(w), float(fb_h) / float(h));
  const int dw = int(float(w) * s), dh = int(float(h) * s);
  const int dx = (fb_w - dw) / 2, dy = (fb_h - dh) / 2;
  image_rect_ = glm::vec4(float(dx), float(dy), float(dw), float(dh));
  // A fixed size shows its pixels; a scaled canvas (resolution scale, motion) is smoothed.
  const GLenum up = options_.width > 0 ? GL_NEAREST : GL_LINEAR;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, present_fbo_.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, w, h, dx, dy, dx + dw, dy + dh, GL_COLOR_BUFFER_BIT, s >= 1.0f ? up : GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fb_w, fb_h);
}

const std::vector<float>& App::radiance_snapshot() {
  snapshot_ = renderer_->read_radiance();
  return snapshot_;
}

const std::vector<uint8_t>& App::display_snapshot() {
  display_snapshot_ = renderer_->read_display();
  return display_snapshot_;
}

std::string App::stats_json() const {
  // The mean is computed on demand: a read-back stalls the GPU pipeline.
  const std::vector<float> px = renderer_->read_radiance();
  double sum[3] = {0, 0, 0};
  for (size_t i = 0; i + 3 < px.size(); i += 4)
    for (int k = 0; k < 3; ++k) sum[k] += px[i + k];
  const double n = std::max<double>(1.0, double(px.size() / 4));
  std::string j = "{";
  j += "\"samples\":" + std::to_string(renderer_->samples());
  j += ",\"sampleLimit\":" + std::to_string(settings_.sample_limit);
  j += ",\"view\":" + json_string(view_query());
  j += ",\"samplesPerSecond\":" + json_number(samples_per_second_);
  j += ",\"passesPerFrame\":" + std::to_string(passes_per_frame_);
  j += ",\"bandRows\":" + std::to_string(settings_.band_rows);
  j += ",\"bandColumns\":" + std::to_string(settings_.band_columns);
  j += ",\"width\":" + std::to_string(renderer_->width());
  j += ",\"height\":" + std::to_string(renderer_->height());
  j += std::string(",\"accumFormat\":") + (renderer_->accum_format() == GL_RGBA32F ? "\"rgba32f\"" : "\"rgba16f\"");
  j += ",\"mean\":[" + json_number(sum[0] / n) + "," + json_number(sum[1] / n) + "," + json_number(sum[2] / n) + "]";
  j += ",\"scene\":" + json_string(scene_.path);
  j += ",\"error\":" + (error_ ? json_string(*error_) : std::string("null"));
  j += ",\"renderer\":" + json_string(options_.gl_renderer);
  j += ",\"loads\":" + std::to_string(loads_);
  j += ",\"compiling\":" + std::string(loading_ && !preparing() ? "true" : "false");
  j += "," + load_fields();
  j += ",\"programsCompiled\":" + std::to_string(renderer_->programs_compiled());
  j += ",\"contextRestores\":" + std::to_string(context_restores_);
  j += ",\"renderScale\":" + json_number(render_scale_);
  j += ",\"files\":" + scene_files_json();
  j += ",\"selected\":" + std::to_string(selected_);
  if (selected_ >= 0) {
    const Shape& sh = scene_.shapes[size_t(selected_)];
    j += ",\"selectedKind\":" + json_string(info(sh.kind).xml) + ",\"selectedLine\":" + std::to_string(sh.line);
  }
  return j + "}";
}

std::string App::load_stage() const {
  if (!loading_) return "";
  const Loading& l = *loading_;
  return l.read ? l.read->stage() : !l.pack ? "starting the packing" : !l.packed ? l.pack->stage() : l.staged && l.staged->done() ? "compiling" : "uploading";
}

// The scene on its way (null when none) and the last one's preparation.
std::string App::load_fields() const {
  std::string j = "\"loading\":";
  if (loading_) {
    j += "{\"scene\":" + json_string(loading_->path) + ",\"stage\":" + json_string(load_stage()) +
         ",\"progress\":" + json_number(load_progress()) + "}";
  } else {
    j += "null";
  }
  const Renderer::BvhStats& b = renderer_->bvh_stats();
  j += ",\"lastLoad\":{\"ms\":" + json_number(last_load_ms_) + ",\"readWorkMs\":" + json_number(last_read_ms_) +
       ",\"readSlices\":" + std::to_string(last_read_slices_) + ",\"packWorkMs\":" + json_number(last_pack_work_ms_) +
       ",\"slices\":" + std::to_string(last_slices_) + ",\"longestSliceMs\":" + json_number(last_longest_slice_ms_) +
       ",\"longestSliceStage\":" + json_string(last_longest_slice_stage_) +
       ",\"bvhBuildMs\":" + json_number(b.build_ms) + ",\"primitives\":" + std::to_string(b.primitives) + "}";
  return j;
}

std::string App::load_status_json() const {
  return "{\"samples\":" + std::to_string(renderer_->samples()) + ",\"scene\":" + json_string(scene_.path) +
         ",\"error\":" + (error_ ? json_string(*error_) : std::string("null")) + ",\"loads\":" + std::to_string(loads_) + "," +
         load_fields() + "}";
}

}  // namespace pt
