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

// The samples-per-second shown are measured over this window.
constexpr double kRateWindowMs = 3000.0;

constexpr float kLookDegPerPixel = 0.2f;
constexpr double kSettleMs = 200.0;  // the camera counts as moving until this long after its last change
constexpr float kTurnDegPerSecond = 90.0f;

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
  settings_.band_rows = FramePacer::kFirstBandRows;
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

void App::render_passes(double now_ms, double dt_ms) {
  if (renderer_->samples() == 0 && !renderer_->mid_sweep()) restart_ms_ = now_ms;
  // The draws of this frame, sized by the interval between frames (render/pacing.h).
  const int done = pacer_.frame(*renderer_, settings_, dt_ms, now_ms, preparing(), total_samples_);
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
  j += ",\"passesPerFrame\":" + std::to_string(pacer_.passes_per_frame());
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

// The scene on its way (null when none) and the last one's preparation.
std::string App::load_fields() const {
  std::string j = "\"loading\":";
  if (loading_) {
    j += "{\"scene\":" + json_string(loading_->pipe->path()) + ",\"stage\":" + json_string(load_stage()) +
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
