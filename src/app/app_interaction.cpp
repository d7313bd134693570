// The App's interaction beyond the main panel: switching scenes (and waiting for a
// program compiling in the background), picking and editing the selected object, the
// render size (resolution scale, reduced while the camera moves), and re-creating every
// GL object after a lost context.
#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "app/app.h"

#include <chrono>
#include <cstdio>
#include "app/picking.h"
#include "app/selection.h"

namespace pt {

std::string json_string(const std::string& s);  // app.cpp

namespace {

constexpr float kMotionScale = 0.5f;       // of the render size, per axis, while the camera moves
constexpr float kClickSlopPixels = 4.0f;   // a press and release closer than this is a click, not a drag
// Scene preparation: each frame reads and packs for about this long (the page adds slices
// between frames), checking the clock every kWorkUnits units of either (a unit is about a
// triangle, a vertex, a BVH node or 64 bytes of a file: 0.1-0.5 ms).
constexpr double kFrameWorkMs = 4.0;
constexpr long kWorkUnits = 8192;
constexpr int kUploadRows = 1;  // rows of record texels per upload call (64 KB)

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

void App::start_loading(Scene scene, bool keep_camera, bool edit) {
  Loading l;
  l.path = scene.path;
  l.edit = edit;
  l.scene = std::make_unique<Scene>(std::move(scene));
  start_packing(l);
  l.keep_camera = keep_camera;
  begin_loading(std::move(l));
}

void App::begin_loading(Loading l) {
  packed_.reset();  // the shown scene's packing is not edited while another is prepared
  l.since = std::chrono::steady_clock::now();
  loading_ = std::move(l);  // a newer request replaces one in progress
}

void App::start_packing(Loading& l) {
  renderer_->program_ready(*l.scene, mode_for(l));  // its program starts building alongside the packing
  l.pack = std::make_unique<PackJob>(*l.scene);
}

bool App::work(double budget_ms) {
  if (!preparing()) return false;
  Loading& l = *loading_;
  const std::string stage = load_stage();
  const auto t0 = std::chrono::steady_clock::now();
  // The stages in order, as many as the budget allows: a small scene loads in one slice.
  // A long step (starting the packing, creating the record textures) starts a stage only
  // with the budget untouched, so that it never adds to another stage's slice.
  auto fresh = [&] { return ms_since(t0) < 1.0; };
  try {
    do {
      const auto ts = std::chrono::steady_clock::now();
      if (l.read) {
        bool done = false;
        while (!(done = l.read->run(kWorkUnits)) && ms_since(t0) < budget_ms) {
        }
        l.read_ms += ms_since(ts);
        ++l.read_slices;
        if (done) {
          l.scene = std::make_unique<Scene>(l.read->take());
          l.read.reset();
          std::printf("scene %s: read in %d slices (%.0f ms of work, %.0f ms after the request)\n", l.path.c_str(), l.read_slices,
                      l.read_ms, ms_since(l.since));
        }
      } else if (!l.pack) {
        if (!fresh() && l.scene->meshes.size() > 0) break;  // the program's build starts: 10+ ms in the page
        start_packing(l);
      } else if (!l.packed) {
        bool done = false;
        while (!(done = l.pack->run(kWorkUnits)) && ms_since(t0) < budget_ms) {
        }
        if (done) l.packed = l.pack->take();
        l.work_ms += ms_since(ts);
        ++l.slices;
      } else if (!l.staged) {
        if (!fresh() && l.packed->prims.count() > kDataWidth) break;  // large textures: their own slice
        l.staged = std::make_unique<StagedScene>(renderer_->limits(), *l.packed);
        l.upload_ms += ms_since(ts);
      } else {
        // The record textures, a row at a time (copies to the GPU; WebGL calls between
        // animation frames are fine, and a lost context drops `staged`).
        while (!l.staged->upload(kUploadRows) && ms_since(t0) < budget_ms) {
        }
        l.upload_ms += ms_since(ts);
      }
    } while (preparing() && ms_since(t0) < budget_ms);
  } catch (const std::exception& e) {
    load_failed(l.path, e.what());
    return false;
  }
  if (const double ms = ms_since(t0); ms > l.longest_slice_ms) {
    l.longest_slice_ms = ms;  // of any stage (reading, packing, uploading), and which
    l.longest_slice_stage = stage;
  }
  return preparing();
}

void App::load_failed(std::string path, std::string why) {  // copies: loading_ holds the originals
  loading_.reset();
  error_ = why;
  if (loads_ == 0) {
    // Nothing rendered yet, so there is no previous scene to keep: fall back to the
    // default one, but keep showing why the requested scene failed.
    const std::string fallback = AppOptions{}.scene;
    if (path != fallback && load_scene(fallback)) error_ = why;
  } else if (!shown_) {
    start_loading(scene_, true, true);  // after a lost context: the kept scene again
  }
}

void App::poll_loading() {
  work(kFrameWorkMs);  // the frame's own slice; the page adds slices between frames
  if (!loading_) return;
  const std::string path = loading_->path;
  try {
    if (preparing() || !renderer_->program_ready(*loading_->scene, mode_for(*loading_))) return;
    Loading l = std::move(*loading_);
    loading_.reset();
    std::optional<Camera> camera;
    if (l.keep_camera) camera = renderer_->camera();
    const auto t1 = std::chrono::steady_clock::now();
    if (l.edit) {  // scene_ is the edited scene (or newer): only the renderer changes
      renderer_->set_scene(*l.scene, *l.packed, l.staged.get());
      renderer_->set_camera(*camera);
      shown_ = true;
    } else {
      apply_scene(std::move(*l.scene), *l.packed, l.staged.get(), camera);  // throws before changing anything if the program does not build
    }
    packed_ = std::move(l.packed);  // kept for refitting the shown scene's BVH after an edit
    last_load_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - l.since).count();
    last_pack_work_ms_ = l.work_ms;
    last_slices_ = l.slices;
    last_longest_slice_ms_ = l.longest_slice_ms;
    last_longest_slice_stage_ = l.longest_slice_stage;
    last_read_ms_ = l.read_ms;
    last_read_slices_ = l.read_slices;
    const Renderer::BvhStats& b = renderer_->bvh_stats();
    std::printf("scene %s: BVH of %d primitives built in %.0f ms; packed in %d slices (%.0f ms, the longest %.0f ms); "
                "uploaded in %.0f ms; scene set in %.0f ms; ready %.0f ms after the request\n",
                scene_.path.c_str(), b.primitives, b.build_ms, l.slices, l.work_ms, l.longest_slice_ms, l.upload_ms, ms_since(t1),
                last_load_ms_);
  } catch (const std::exception& e) {
    load_failed(path, e.what());
  }
}

UserSet App::link_set() const {
  const bool first = loads_ == 0;  // what the page's link set wins on the first scene only
  return {first && options_.bounces.has_value(), false, first && options_.tonemap.has_value(), first && options_.exposure.has_value(),
          first && options_.sample_limit > 0};
}

RenderSettings App::shown_settings(const Scene& scene) const {
  RenderSettings s = with_scene_render(settings_, scene.render, link_set());
  s.max_bounces = std::clamp(s.max_bounces, 1, 16);  // the panel's range
  return s;
}

RenderMode App::mode_for(const Loading& l) const { return l.edit || !l.scene ? settings_.mode : shown_settings(*l.scene).mode; }

void App::apply_scene(Scene scene, const PackedScene& packed, StagedScene* staged, const std::optional<Camera>& camera) {
  // The scene's <Render>, on every load and reload (an author's edit of it applies), set
  // with the scene: its program (mode) was built ahead.
  const RenderSettings next = shown_settings(scene);
  renderer_->set_scene(scene, packed, staged, &next);  // throws before changing anything if the program does not build
  shown_ = true;
  env_panel_.scene_loaded(scene.environment);
  if (camera) {
    renderer_->set_camera(*camera);
  } else if (loads_ == 0 && (options_.camera_position || options_.camera_yaw_pitch)) {
    Camera c = renderer_->camera();  // the first scene: a view from a link
    if (options_.camera_position) c.position = *options_.camera_position;
    if (options_.camera_yaw_pitch) {
      c.yaw = options_.camera_yaw_pitch->x;
      c.pitch = std::clamp(options_.camera_yaw_pitch->y, -89.0f, 89.0f);
    }
    renderer_->set_camera(c);
  }
  if (scene.render.exposure && !link_set().exposure) auto_exposure_ = false;  // the scene's exposure applied
  settings_ = next;
  // A reload keeps the selection when the object is still there.
  if (selected_ >= int(scene.shapes.size()) || scene.path != scene_.path) selected_ = -1;
  scene_ = std::move(scene);
  ++loads_;
}

std::string App::scene_files_json() const {
  std::string j = "[";
  for (const std::string& f : scene_.files) j += (j.size() > 1 ? "," : "") + json_string(f);
  return j + "]";
}

void App::context_restored() {
  // Every GL name held is stale: drop the offscreen target and the renderer (deleting
  // stale names does nothing), then build them again from the kept scene model.
  const Camera camera = renderer_->camera();
  present_fbo_ = Framebuffer();
  present_tex_ = Texture();
  renderer_ = std::make_unique<Renderer>();
  renderer_->set_settings(settings_);
  renderer_->set_camera(camera);
  shown_ = false;
  // The kept scene is packed again (in slices), unless another is on its way; should that
  // one fail, load_failed brings the kept one back.
  if (loading_) {
    loading_->staged.reset();  // its textures were the lost context's
    if (loading_->scene) renderer_->program_ready(*loading_->scene, mode_for(*loading_));
  }
  else if (loads_ > 0) start_loading(scene_, true, true);
  ++context_restores_;
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
  const glm::vec2 px = image_pixel(pos);
  const glm::ivec2 size(renderer_->width(), renderer_->height());
  if (px.x < 0.0f || px.y < 0.0f || px.x >= float(size.x) || px.y >= float(size.y)) return;
  selected_ = pick(scene_, renderer_->camera(), px, size);
}

// The selected object's transform and material: value edits re-upload the scene's data
// and restart; the kinds do not change, so the program is reused.
void App::draw_selection_panel(int fb_w) {
  if (selected_ < 0 || selected_ >= int(scene_.shapes.size())) return;
  ImGui::SetNextWindowPos(ImVec2(float(fb_w) - 10.0f, 10.0f), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  bool open = true;
  ImGui::Begin("Selection", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
  ImGui::PushItemWidth(ImGui::GetFontSize() * 12.0f);
  Shape& sh = scene_.shapes[size_t(selected_)];
  Material& m = scene_.materials[size_t(sh.material)];
  ImGui::Text("%s #%d (line %d)", info(sh.kind).xml, selected_, sh.line);
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

// The whole preparation: packing (its stages weighted in PackJob::progress), then the
// upload, which took about a tenth as long for a large mesh.
double App::load_progress() const {
  if (!loading_) return 1.0;
  const Loading& l = *loading_;
  // Reading the meshes (a scene's first part of the bar), then packing and uploading.
  constexpr double kReadShare = 0.3;
  if (l.read) return kReadShare * l.read->progress();
  const double rest = l.packed ? 0.9 + 0.1 * (l.staged ? l.staged->progress() : 0.0) : l.pack ? 0.9 * l.pack->progress() : 0.0;
  return l.read_slices > 0 ? kReadShare + (1.0 - kReadShare) * rest : rest;
}

// A scene on its way: what is being done, and how far (the page keeps drawing meanwhile).
void App::draw_loading() {
  if (!loading_) return;
  const Loading& l = *loading_;
  const std::string& path = l.path;
  const size_t slash = path.find_last_of('/');
  ImGui::Text("loading %s", slash == std::string::npos ? path.c_str() : path.c_str() + slash + 1);
  char overlay[96];
  const double s = ms_since(l.since) * 1e-3;
  if (l.packed && !(l.staged && l.staged->done())) {
    std::snprintf(overlay, sizeof overlay, "uploading %.0f%%  %.1f s", 100.0 * load_progress(), s);
  } else if (l.packed) {
    const char* frames = "|/-\\";  // a spinner: the driver compiles in the background
    std::snprintf(overlay, sizeof overlay, "compiling shader %c %.1f s", frames[int(last_frame_ms_ / 120.0) & 3], s);
  } else {
    std::snprintf(overlay, sizeof overlay, "%s %.0f%%  %.1f s", load_stage().c_str(), 100.0 * load_progress(), s);
  }
  ImGui::ProgressBar(float(load_progress()), ImVec2(ImGui::GetFontSize() * 20.0f, 0.0f), overlay);
}

}  // namespace pt
