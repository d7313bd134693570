// The App's main panel (scene, settings, the light, environment, lens, progress, saving)
// and the camera controls (keys, mouse look, wheel): what a frame reads from the user
// before it draws.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <GLFW/glfw3.h>  // key codes only: the ImGui GLFW backend indexes io.KeysDown by them
#include <imgui.h>

#include "app/app.h"
#include "core/image.h"
#include "render/camera.h"

namespace pt {
namespace {

constexpr float kLookDegPerPixel = 0.2f;
constexpr double kSettleMs = 200.0;  // the camera counts as moving until this long after its last change
constexpr float kTurnDegPerSecond = 90.0f;

}  // namespace

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
  changed |= apply_touch(c, kLookDegPerPixel);  // touch gestures (app_interaction.cpp)

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

void App::take_readout() {
  const int n = renderer_->samples();
  const bool done = done_ms_ >= 0;
  if (last_frame_ms_ - readout_.ms < kRefreshMs && n == readout_.samples && done == readout_.done) return;
  readout_ = {last_frame_ms_, samples_per_second_, n, done};
}

void App::draw_panel() {
  const std::string& root = options_.scene_root;
  const auto label = [&](const std::string& path) {
    return path.rfind(root + "/", 0) == 0 ? path.substr(root.size() + 1) : path;
  };
  if (draw_panel_bar()) return;  // a small screen's collapsed panel (app_interaction.cpp)
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::Begin("Path tracer", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  draw_panel_collapse();
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
  // The denoiser on the shown image (the accumulation stays the unbiased mean), with its
  // blend weight, which falls as the estimated relMSE does (render/denoise.h). On the
  // mode's row: the rows below keep their places (the browser tests click them), except
  // on a small screen (compact_) where it would pass the canvas's right edge (a phone:
  // it was cut off there): then on its own row. The widest label ("denoise 0.00") and
  // the canvas, not the auto-sized window, decide, so the row does not flip between
  // frames.
  const float denoise_width = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("denoise 0.00").x;
  ImGui::SameLine();
  if (compact_ && ImGui::GetCursorScreenPos().x + denoise_width + ImGui::GetStyle().WindowPadding.x > float(fb_w_)) ImGui::NewLine();
  char denoise_label[48];
  std::snprintf(denoise_label, sizeof denoise_label, denoise_ ? "denoise %.2f###denoise" : "denoise###denoise", double(denoise_blend()));
  ImGui::Checkbox(denoise_label, &denoise_);
  // Adaptive sampling (render/adaptive.h; a change restarts), on the same row for the
  // same reason; its default is RenderSettings' (docs/benchmarks.md says why).
  ImGui::SameLine();
  ImGui::Checkbox("adaptive", &settings_.adaptive);
  if (options_.save_file) {
    // PNG: the image as displayed (tone-mapped); HDR: linear radiance.
    const int w = renderer_->width(), h = renderer_->height();
    if (ImGui::Button("save PNG")) options_.save_file("pathtracer.png", encode_png(w, h, renderer_->read_display()), "image/png");
    ImGui::SameLine();
    if (ImGui::Button("save HDR"))
      options_.save_file("pathtracer.hdr", encode_hdr(w, h, renderer_->read_radiance()), "image/vnd.radiance");
    if (denoise_) {  // the raw estimate above, the denoised image as shown here
      ImGui::SameLine();
      if (ImGui::Button("save denoised HDR"))
        options_.save_file("pathtracer-denoised.hdr", encode_hdr(w, h, renderer_->read_denoised(1.0f)), "image/vnd.radiance");
    }
  }

  ImGui::Separator();
  take_readout();
  const double end_ms = done_ms_ >= 0 ? done_ms_ : readout_.ms;
  if (settings_.sample_limit > 0)
    ImGui::Text("samples    %d / %d", renderer_->samples(), settings_.sample_limit);
  else
    ImGui::Text("samples    %d", renderer_->samples());
  ImGui::Text("samples/s  %.1f", readout_.samples_per_second);
  ImGui::Text("elapsed    %.1f s", std::max(0.0, end_ms - restart_ms_) * 1e-3);
  // Until the first full-resolution sweep is complete the image shown is a coarse level
  // (render/coarse.h), said on this row (the rows below keep their places).
  if (const int d = renderer_->shown_divisor(); d > 1)
    ImGui::Text("resolution %d x %d (first image: 1/%d)", renderer_->width(), renderer_->height(), d);
  else
    ImGui::Text("resolution %d x %d", renderer_->width(), renderer_->height());
  draw_view_controls();
  draw_error();  // after the view's controls: their place stays where the browser tests click
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextUnformatted(options_.gl_renderer.c_str());
  // Last, so that no control moves: which traversal the program has (the URL's accel=).
  ImGui::Text("traversal: %s (accel=%s)", renderer_->using_flat() ? "flat, no BVH" : "BVH", accel_name(settings_.accel));
  ImGui::PopStyleColor();
  ImGui::PopItemWidth();
  ImGui::PopTextWrapPos();
  ImGui::End();
}

// The estimated relMSE, its trend against time (log-log: each decade a grid line; the
// fitted line dashed on to the target) and the target field.
void App::draw_error() {
  const int n = renderer_->samples();
  if (error_history_.empty()) {
    // The estimate is of the full-resolution mean, raw: never of a coarse first image nor
    // of the denoised one shown.
    ImGui::TextUnformatted(n < 2 ? "est. relMSE of the raw image (from 2 samples)" : "est. relMSE ...");
  } else {
    const ErrorPoint& last = error_history_.back();
    ImGui::Text("est. relMSE %.4g at %d samples (raw)", last.rel_mse, last.samples);
  }
  double a = 0, b = 0;
  const bool trend = error_trend(a, b);
  if (error_history_.size() >= 2) {
    // Bounds in log10: the points', the target's, whole decades around them.
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (const ErrorPoint& p : error_history_) {
      const double x = std::log10(std::max(p.seconds, 1e-3)), y = std::log10(std::max(p.rel_mse, 1e-12));
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    if (target_relmse_ > 0.0f) y0 = std::min(y0, std::log10(double(target_relmse_)));
    x0 = std::floor(x0), x1 = std::max(std::ceil(x1), x0 + 1), y0 = std::floor(y0), y1 = std::max(std::ceil(y1), y0 + 1);
    const ImVec2 size(ImGui::GetFontSize() * 14.0f, ImGui::GetFontSize() * 5.0f), o = ImGui::GetCursorScreenPos();
    ImGui::Dummy(size);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const auto at = [&](double x, double y) {
      return ImVec2(o.x + float((x - x0) / (x1 - x0)) * size.x, o.y + float((y1 - y) / (y1 - y0)) * size.y);
    };
    dl->PushClipRect(o, ImVec2(o.x + size.x, o.y + size.y), true);  // the fit may leave the box
    dl->AddRectFilled(o, ImVec2(o.x + size.x, o.y + size.y), IM_COL32(0, 0, 0, 90));
    for (double x = x0 + 1; x < x1; ++x) dl->AddLine(at(x, y0), at(x, y1), IM_COL32(255, 255, 255, 40));
    for (double y = y0 + 1; y < y1; ++y) dl->AddLine(at(x0, y), at(x1, y), IM_COL32(255, 255, 255, 40));
    if (target_relmse_ > 0.0f) {
      const double y = std::log10(double(target_relmse_));
      dl->AddLine(at(x0, y), at(x1, y), IM_COL32(120, 220, 120, 200));
    }
    std::vector<ImVec2> pts;
    for (const ErrorPoint& p : error_history_) pts.push_back(at(std::log10(std::max(p.seconds, 1e-3)), std::log10(std::max(p.rel_mse, 1e-12))));
    dl->AddPolyline(pts.data(), int(pts.size()), IM_COL32(255, 200, 80, 255), 0, 1.5f);
    if (trend && target_stop_at_ == 0) {  // the fit, on to the plot's right edge
      const double xs = std::log10(std::max(error_history_.back().seconds, 1e-3));
      for (double x = xs; x < x1; x += (x1 - x0) / 40.0)
        dl->AddLine(at(x, a + b * x), at(std::min(x1, x + (x1 - x0) / 80.0), a + b * std::min(x1, x + (x1 - x0) / 80.0)),
                    IM_COL32(255, 200, 80, 140));
    }
    char axes[96];
    std::snprintf(axes, sizeof axes, "1e%d..1e%d s, 1e%d..1e%d", int(x0), int(x1), int(y0), int(y1));
    dl->AddText(ImVec2(o.x + 2, o.y + size.y - ImGui::GetFontSize()), IM_COL32(255, 255, 255, 120), axes);
    dl->PopClipRect();
  }
  if (ImGui::InputFloat("target relMSE", &target_relmse_, 0.0f, 0.0f, "%.4g")) {
    target_relmse_ = std::isfinite(target_relmse_) ? std::max(0.0f, target_relmse_) : 0.0f;
    // A new target: the last estimate of this image decides at once, later ones after.
    target_stop_at_ = 0;
    const bool current = !error_history_.empty() && error_history_.back().samples == n;
    if (target_relmse_ > 0.0f && current && error_history_.back().rel_mse <= double(target_relmse_)) target_stop_at_ = n;
  }
  if (target_relmse_ <= 0.0f) return;
  if (target_stop_at_ > 0) {
    ImGui::Text("target reached at %d samples", target_stop_at_);
  } else if (trend && b < -0.05) {
    // The fitted line reaches the target at 10^((log10 target - a) / b) seconds.
    const double t = std::pow(10.0, (std::log10(double(target_relmse_)) - a) / b);
    const double left = t - std::max(0.0, readout_.ms - restart_ms_) * 1e-3;
    ImGui::Text("to target  ~%.1f s (slope %.2f)", std::max(0.0, left), b);
  } else {
    ImGui::TextUnformatted("to target  (estimating the trend)");
  }
}

}  // namespace pt
