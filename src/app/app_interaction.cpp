// The App's interaction beyond the main panel: picking and editing the selected object
// (an edit re-packs through app_loading.cpp when the BVH cannot be refitted), touch
// gestures and the small screen's collapsed panel (issue 16), and the render size
// (resolution scale, reduced while the camera moves).
#include <algorithm>
#include <cfloat>
#include <cmath>

#include <imgui.h>

#include "app/app.h"

#include <chrono>
#include <cstdio>
#include "app/picking.h"
#include "app/selection.h"

namespace pt {

std::string json_string(const std::string& s);  // app_stats.cpp

namespace {

constexpr float kMotionScale = 0.5f;       // of the render size, per axis, while the camera moves
constexpr float kClickSlopPixels = 4.0f;   // a press and release closer than this is a click, not a drag
// Touch, in units of the camera's distance to the origin (at least 1; scenes differ in
// size by orders of magnitude): a pinch that doubles the fingers' distance moves forward
// kPinchReach * ln 2 (0.35) of it; a two-finger pan of one CSS pixel strafes kPanReach of
// it (a phone's width: about the width of the view at the origin's depth).
constexpr float kPinchReach = 0.5f;
constexpr float kPanReach = 1.0f / 400.0f;

}  // namespace

std::string App::scene_files_json() const {
  std::string j = "[";
  for (const std::string& f : scene_.files) j += (j.size() > 1 ? "," : "") + json_string(f);
  return j + "]";
}

std::string App::scene_list_json() const {
  std::string j = "[";
  for (const std::string& f : scene_files_) j += (j.size() > 1 ? "," : "") + json_string(f);
  return j + "]";
}

glm::ivec2 App::render_size(int fb_w, int fb_h, double now_ms) const {
  glm::vec2 size = options_.width > 0 ? glm::vec2(options_.width, options_.height)
                                      : glm::vec2(float(fb_w), float(fb_h)) * render_scale_;
  if (now_ms < moving_until_ms_) size *= kMotionScale;
  return glm::max(glm::ivec2(glm::round(size)), glm::ivec2(1));
}

glm::vec2 App::image_pixel(glm::vec2 mouse) const {
  const glm::vec2 gl(mouse.x, float(fb_h_) - mouse.y);  // y up, as gl_FragCoord
  const glm::vec2 rel = (gl - glm::vec2(image_rect_.x, image_rect_.y)) / glm::vec2(image_rect_.z, image_rect_.w);
  return rel * glm::vec2(renderer_->width(), renderer_->height());
}

void App::handle_click() {
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    press_on_image_ = !io.WantCaptureMouse;
    press_pos_ = glm::vec2(io.MousePos.x, io.MousePos.y);
  }
  if (!ImGui::IsMouseReleased(ImGuiMouseButton_Left) || !press_on_image_) return;
  press_on_image_ = false;
  const glm::vec2 pos(io.MousePos.x, io.MousePos.y);
  if (glm::length(pos - press_pos_) > kClickSlopPixels) return;  // a drag looked around
  pick_at(pos);
}

void App::pick_at(glm::vec2 pos) {
  const glm::vec2 px = image_pixel(pos);
  const glm::ivec2 size(renderer_->width(), renderer_->height());
  if (px.x < 0.0f || px.y < 0.0f || px.x >= float(size.x) || px.y >= float(size.y)) return;
  selected_ = pick(scene_, renderer_->camera(), px, size);
}

void App::set_display(float pixels_per_css, bool touch_screen) {
  pixels_per_css_ = pixels_per_css > 0.0f ? pixels_per_css : 1.0f;
  touch_screen_ = touch_screen;
  touch_.set_scale(pixels_per_css_);
}

bool App::apply_touch(Camera& c, float deg_per_pixel) {
  const TouchGestures g = touch_.take();
  if (!g.any()) return false;
  bool changed = false;
  if (g.double_tap) {  // the scene's view again; the lens and shutter stay as set
    c.position = scene_.camera.position;
    c.yaw = scene_.camera.yaw;
    c.pitch = scene_.camera.pitch;
    changed = true;
  }
  const glm::vec3 forward = camera_forward(c), up = glm::normalize(c.up);
  const glm::vec3 right = glm::normalize(glm::cross(forward, up));
  if (g.look != glm::vec2(0.0f)) {  // as the mouse's drag: the same degrees per device pixel
    c.yaw += g.look.x * deg_per_pixel;
    c.pitch -= g.look.y * deg_per_pixel;
    changed = true;
  }
  if (g.pinch != 0.0f || g.pan != glm::vec2(0.0f)) {  // the image follows the fingers
    const float reach = std::max(1.0f, glm::length(c.position));
    const glm::vec2 pan = g.pan / pixels_per_css_ * (kPanReach * reach);
    c.position += forward * (g.pinch * kPinchReach * reach) - right * pan.x + up * pan.y;
    changed = true;
  }
  if (g.tap) pick_at(*g.tap);  // as a click
  return changed;
}

bool App::draw_panel_bar() {
  // This frame's canvas: narrow, or a phone turned sideways (a touch screen, low).
  compact_ = std::min(float(fb_w_), touch_screen_ ? float(fb_h_) : 1e9f) / pixels_per_css_ < kCompactWidth;
  if (!panel_collapsed_) panel_collapsed_ = compact_;  // the first frame decides
  if (compact_ && !*panel_collapsed_) {  // the expanded panel leaves a third of the image visible (it scrolls)
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(FLT_MAX, float(fb_h_) * 0.65f));
    return false;
  }
  if (!compact_) return false;
  const float pad = 6.0f * pixels_per_css_;
  ImGui::SetNextWindowPos(ImVec2(pad, pad), ImGuiCond_Always);
  ImGui::Begin("##bar", nullptr, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar);
  const std::string& path = scene_.path;
  const std::string name = path.substr(path.find_last_of('/') + 1);
  // The label changes with every sample; its ID ("###" on) must not: a tap whose press
  // and release frames straddle a new sample would otherwise press one button and
  // release over another, and expand nothing (phone_test saw it after a drag's restart).
  char text[200];
  if (error_history_.empty())
    std::snprintf(text, sizeof text, "+  %s  %d spp###bar", name.c_str(), renderer_->samples());
  else
    std::snprintf(text, sizeof text, "+  %s  %d spp  relMSE %.3g###bar", name.c_str(), renderer_->samples(), error_history_.back().rel_mse);
  if (ImGui::Button(text)) panel_collapsed_ = false;
  const ImVec2 p = ImGui::GetWindowPos(), s = ImGui::GetWindowSize();
  bar_rect_ = glm::vec4(p.x, p.y, s.x, s.y);
  panel_rect_ = glm::vec4(0.0f);
  ImGui::End();
  return true;
}

void App::draw_panel_collapse() {
  const ImVec2 p = ImGui::GetWindowPos(), s = ImGui::GetWindowSize();
  panel_rect_ = glm::vec4(p.x, p.y, s.x, s.y);
  panel_scroll_ = ImGui::GetScrollY();
  bar_rect_ = glm::vec4(0.0f);
  hide_rect_ = glm::vec4(0.0f);
  if (!compact_) return;
  if (ImGui::Button("-  hide the panel")) panel_collapsed_ = true;
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  hide_rect_ = glm::vec4(a.x, a.y, b.x - a.x, b.y - a.y);
}

std::string App::ui_json() const {
  char j[512];
  std::snprintf(j, sizeof j,
                "{\"compact\":%s,\"panelCollapsed\":%s,\"touchScreen\":%s,\"pixelsPerCss\":%g,\"fingers\":%d,"
                "\"bar\":[%g,%g,%g,%g],\"panel\":[%g,%g,%g,%g],\"hide\":[%g,%g,%g,%g],\"panelScroll\":%g,\"fontPixels\":%g,\"rowPixels\":%g,\"accumFormat\":\"%s\"}",
                compact_ ? "true" : "false", panel_collapsed_.value_or(false) ? "true" : "false", touch_screen_ ? "true" : "false",
                double(pixels_per_css_), touch_.fingers(), double(bar_rect_.x), double(bar_rect_.y), double(bar_rect_.z),
                double(bar_rect_.w), double(panel_rect_.x), double(panel_rect_.y), double(panel_rect_.z), double(panel_rect_.w),
                double(hide_rect_.x), double(hide_rect_.y), double(hide_rect_.z), double(hide_rect_.w),
                double(panel_scroll_), double(ImGui::GetFontSize()), double(ImGui::GetFrameHeightWithSpacing()),
                renderer_->accum_format() == GL_RGBA32F ? "rgba32f" : "rgba16f");
  return j;
}

// The selected object's transform and material: value edits re-upload the scene's data
// and restart; the kinds do not change, so the program is reused.
void App::draw_selection_panel(int fb_w) {
  if (selected_ < 0 || selected_ >= int(scene_.shapes.size())) return;
  // On a small screen in portrait at the bottom, above the page's Open button (the top
  // holds the panel's bar), at most 40% of the height (it scrolls); else top right (on a
  // small screen at most 60% of its height).
  if (compact_) ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(FLT_MAX, float(fb_h_) * (fb_h_ > fb_w ? 0.4f : 0.6f)));
  if (compact_ && fb_h_ > fb_w) {
    ImGui::SetNextWindowPos(ImVec2(float(fb_w) * 0.5f, float(fb_h_) - 56.0f * pixels_per_css_), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
  } else {
    ImGui::SetNextWindowPos(ImVec2(float(fb_w) - 10.0f, 10.0f), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  }
  bool open = true;
  ImGui::Begin("Selection", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
  ImGui::PushItemWidth(ImGui::GetFontSize() * 12.0f);
  Shape& sh = scene_.shapes[size_t(selected_)];
  Material& m = scene_.materials[size_t(sh.material)];
  ImGui::Text("%s #%d (line %d)", info(sh.kind()).xml, selected_, sh.line);
  ImGui::Text("material: %s", info(m.kind()).xml);
  const float speed = 0.005f * std::max(1.0f, glm::length(renderer_->camera().position));
  bool edited = false, moved = false;
  glm::vec3 p = shape_position(sh);
  if (ImGui::DragFloat3("position", &p.x, speed, 0.0f, 0.0f, "%.2f")) {
    move_shape(scene_, selected_, p);
    edited = moved = true;
  }
  struct ImGuiEditor {
    float base_speed;  // the position's drag speed: a shape's fields drag relative to it
    bool color(const char* label, glm::vec3& c) { return ImGui::ColorEdit3(label, &c.x); }
    bool slider(const char* label, float& v, float lo, float hi) { return ImGui::SliderFloat(label, &v, lo, hi); }
    bool drag3(const char* label, glm::vec3& v, float s, float lo, float hi) { return ImGui::DragFloat3(label, &v.x, s, lo, hi); }
    bool drag(const char* label, float& v, float s, float lo, float hi) { return ImGui::DragFloat(label, &v, base_speed * s, lo, hi, "%.3f"); }
  } editor{speed};
  if (edit_shape(scene_, selected_, editor)) edited = moved = true;  // the fields its kind offers
  edited |= edit_material(m, editor);  // the fields its kind offers
  if (sh.light >= 0) ImGui::TextDisabled("the scene's light %d", sh.light);
  ImGui::PopItemWidth();
  ImGui::End();
  if (!open) selected_ = -1;
  if (edited) scene_edited(moved ? selected_ : -1);
}

// Values (materials, emission, the environment) go to the renderer at once, and so does a
// moved or resized analytic shape (the BVH refitted); a mesh instance moved re-packs the
// scene in slices like a load, the view kept and the current image rendering meanwhile.
// Either way the program is the cached one: the kinds are the same.
void App::scene_edited(int moved) {
  if (loading_ && !loading_->edit) return;  // another scene on its way replaces this one
  if (!loading_) {
    if (moved < 0 && renderer_->update_values(scene_)) return;
    // An analytic shape moved: the BVH refitted over the same tree, a path to its root.
    std::vector<int> prims, nodes;
    if (moved >= 0 && packed_ && refit_shape(scene_, *packed_, moved, prims, nodes) &&
        renderer_->update_geometry(scene_, *packed_, prims, nodes))
      return;
  }
  packed_.reset();  // refitted, maybe, but not shown: the new packing replaces it
  start_loading(scene_, true, true);  // replaces an edit in progress: scene_ has both
}

// Resolution scale, the sample target's estimated time, and a compiling indicator.
void App::draw_view_controls() {
  if (options_.width <= 0) ImGui::SliderFloat("resolution scale", &render_scale_, 0.25f, 1.0f, "%.2f");
  const int n = renderer_->samples(), limit = settings_.sample_limit;
  if (limit > 0 && n < limit && samples_per_second_ > 0.0)
    ImGui::Text("remaining  %.1f s to %d samples", double(limit - n) / samples_per_second_, limit);
  draw_loading();
}

}  // namespace pt
