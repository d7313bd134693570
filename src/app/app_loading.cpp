// The App's scene loading: a scene file, an edit that re-packs and the scene a lost context
// dropped all go through the scene pipeline (render/pipeline.h) in slices between frames
// while the current scene keeps rendering, and replace it at once when packed, uploaded and
// compiled; the page's settings and the scene's <Render> are applied on the way in.
#include <algorithm>
#include <chrono>
#include <cstdio>

#include <imgui.h>

#include "app/app.h"
#include "gpu/gl_objects.h"

namespace pt {
namespace {

// Scene preparation: each frame reads and packs for about this long (the page adds slices
// between frames: web.cpp).
constexpr double kFrameWorkMs = 4.0;

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

ScenePipeline::ModeFor App::mode_for(bool edit) {
  // An edit keeps the page's mode; a load builds the program of the mode it will be shown in.
  return [this, edit](const Scene& scene) { return edit ? settings_.mode : shown_settings(scene).mode; };
}

bool App::load_scene(const std::string& path, bool keep_camera) {
  try {
    // The XML is checked here; its meshes are read in slices (work()).
    auto pipe = std::make_unique<ScenePipeline>(path, renderer_.get(), mode_for(false));
    error_.reset();
    Loading l;
    l.pipe = std::move(pipe);
    l.keep_camera = keep_camera && loads_ > 0;
    begin_loading(std::move(l));
    return true;
  } catch (const std::exception& e) {
    error_ = e.what();
    return false;
  }
}

void App::start_loading(Scene scene, bool keep_camera, bool edit) {
  Loading l;
  l.edit = edit;
  l.pipe = std::make_unique<ScenePipeline>(std::move(scene), renderer_.get(), mode_for(edit));  // packing and program start here
  l.keep_camera = keep_camera;
  begin_loading(std::move(l));
}

void App::begin_loading(Loading l) {
  packed_.reset();  // the shown scene's packing is not edited while another is prepared
  l.since = std::chrono::steady_clock::now();
  l.pipe->on_read([path = l.pipe->path(), since = l.since](Scene&, const ScenePipeline::Times& t) {
    std::printf("scene %s: read in %d slices (%.0f ms of work, %.0f ms after the request)\n", path.c_str(), t.read_slices,
                t.read_ms, ms_since(since));
  });
  loading_ = std::move(l);  // a newer request replaces one in progress
}

bool App::work(double budget_ms) {
  if (!preparing()) return false;
  Loading& l = *loading_;
  const std::string stage = l.pipe->stage();
  const auto t0 = std::chrono::steady_clock::now();
  try {
    l.pipe->work(budget_ms);
  } catch (const std::exception& e) {
    load_failed(l.pipe->path(), e.what());
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
  // The scene's name where the reason lacks it (a GPU limit; a parse error has file:line).
  const std::string file = path.substr(path.find_last_of('/') + 1);
  if (why.find(file) == std::string::npos) why = file + ": " + why;
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
  renderer_->poll_programs();  // builds done in the background are finished, even while idle
  work(kFrameWorkMs);  // the frame's own slice; the page adds slices between frames
  if (!loading_) return;
  const std::string path = loading_->pipe->path();
  try {
    if (!loading_->pipe->ready()) return;
    Loading l = std::move(*loading_);
    loading_.reset();
    std::optional<Camera> camera;
    if (l.keep_camera) camera = renderer_->camera();
    const auto t1 = std::chrono::steady_clock::now();
    if (l.edit) {  // scene_ is the edited scene (or newer): only the renderer changes
      l.pipe->finish();
      renderer_->set_camera(*camera);
      shown_ = true;
    } else {
      apply_scene(*l.pipe, camera);  // throws before changing anything if the program does not build
    }
    packed_ = l.pipe->take_packed();  // kept for refitting the shown scene's BVH after an edit
    const ScenePipeline::Times& t = l.pipe->times();
    last_load_ms_ = ms_since(l.since);
    last_pack_work_ms_ = t.pack_ms;
    last_slices_ = t.pack_slices;
    last_longest_slice_ms_ = l.longest_slice_ms;
    last_longest_slice_stage_ = l.longest_slice_stage;
    last_read_ms_ = t.read_ms;
    last_read_slices_ = t.read_slices;
    const Renderer::BvhStats& b = renderer_->bvh_stats();
    std::printf("scene %s: BVH of %d primitives built in %.0f ms; packed in %d slices (%.0f ms, the longest %.0f ms); "
                "uploaded in %.0f ms; scene set in %.0f ms; ready %.0f ms after the request\n",
                scene_.path.c_str(), b.primitives, b.build_ms, t.pack_slices, t.pack_ms, l.longest_slice_ms, t.upload_ms,
                ms_since(t1), last_load_ms_);
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

void App::apply_scene(ScenePipeline& pipe, const std::optional<Camera>& camera) {
  // The scene's <Render>, on every load and reload (an author's edit of it applies), set
  // with the scene: its program (mode) was built ahead.
  const Scene& scene = pipe.scene();
  const RenderSettings next = shown_settings(scene);
  pipe.finish(&next);  // throws before changing anything if the program does not build
  shown_ = true;
  env_panel_.scene_loaded(scene.environment);
  // A new scene's view does not inherit the last view's motion: rendered at the motion
  // size until kSettleMs after the last key, it would restart at full size a moment later.
  if (!camera) moving_until_ms_ = -1.0;
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
  scene_ = pipe.take_scene();
  ++loads_;
}

void App::context_restored() {
  // Every GL name held is stale: drop the offscreen target and the renderer (their stale
  // names are not deleted: WebGL would warn for each), then build them again from the
  // kept scene model.
  gl_objects::context_replaced();
  const Camera camera = renderer_->camera();
  present_fbo_ = Framebuffer();
  presented_ms_ = -1e9;  // the restored canvas is blank: present the next frame
  present_tex_ = Texture();
  renderer_ = std::make_unique<Renderer>();
  renderer_->set_settings(settings_);
  renderer_->set_sliced_denoise(true);
  renderer_->set_camera(camera);
  shown_ = false;
  // The kept scene is packed again (in slices), unless another is on its way (its staged
  // textures were the lost context's); should that one fail, load_failed brings the kept
  // one back.
  if (loading_) loading_->pipe->context_restored(*renderer_);
  else if (loads_ > 0) start_loading(scene_, true, true);
  ++context_restores_;
}

std::string App::load_stage() const { return loading_ ? loading_->pipe->stage() : ""; }

double App::load_progress() const { return loading_ ? loading_->pipe->progress() : 1.0; }

// A scene on its way: what is being done, and how far (the page keeps drawing meanwhile).
void App::draw_loading() {
  if (!loading_) return;
  const ScenePipeline& p = *loading_->pipe;
  const std::string& path = p.path();
  const size_t slash = path.find_last_of('/');
  ImGui::Text("loading %s", slash == std::string::npos ? path.c_str() : path.c_str() + slash + 1);
  char overlay[96];
  const double s = ms_since(loading_->since) * 1e-3;
  if (p.packed() && p.preparing()) {
    std::snprintf(overlay, sizeof overlay, "uploading %.0f%%  %.1f s", 100.0 * load_progress(), s);
  } else if (p.packed()) {
    const char* frames = "|/-\\";  // a spinner: the driver compiles in the background
    std::snprintf(overlay, sizeof overlay, "compiling shader %c %.1f s", frames[int(last_frame_ms_ / 120.0) & 3], s);
  } else {
    std::snprintf(overlay, sizeof overlay, "%s %.0f%%  %.1f s", load_stage().c_str(), 100.0 * load_progress(), s);
  }
  ImGui::ProgressBar(float(load_progress()), ImVec2(ImGui::GetFontSize() * 20.0f, 0.0f), overlay);
}

}  // namespace pt
