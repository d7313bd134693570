// The one way a scene gets from its file to the renderer, for the page, the command line
// and the tools: read (SceneLoad: the XML checked, then its meshes read or generated), pack
// (PackJob: the records and the BVH), stage (StagedScene: the record textures uploaded a
// row at a time) and compile (the renderer's program, started alongside the packing, in
// the background where the context can), then swapped into the Renderer at once, so the
// previous scene renders until then. A page runs it in slices between frames (work()), a
// tool one slice at a time (step()), the command line to completion (read(), finish()).
// Errors are thrown as they are found (InputError: `file:line: message`; GlError), and
// nothing reaches the renderer before finish().
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "render/packing.h"
#include "render/renderer.h"
#include "render/staged_scene.h"
#include "scene/xml_loader.h"

namespace pt {

class ScenePipeline {
 public:
  // The render mode whose program is built ahead for the scene, asked once it is read and
  // while waiting for the program (a page's mode may change meanwhile). Empty: the
  // renderer's current mode.
  using ModeFor = std::function<RenderMode(const Scene&)>;
  // Time spent in slices of each stage so far, and how many slices.
  struct Times {
    double read_ms = 0.0, pack_ms = 0.0, upload_ms = 0.0;
    int read_slices = 0, pack_slices = 0;
  };
  // Called once the scene is read, before it is packed; it may still change the scene
  // (the command line's --env) or throw.
  using OnRead = std::function<void(Scene& scene, const Times& times)>;

  // A scene file: its text is read and its XML checked here (throws InputError naming the
  // file and line); its meshes are read by the steps. A .gltf or .glb is a scene of its
  // own (SceneLoad::open). Without a renderer (attach() gives
  // one later) it reads and packs only.
  explicit ScenePipeline(const std::string& path, Renderer* renderer = nullptr, ModeFor mode = {});
  // A scene in memory (an edit of the shown one, the one a lost context dropped): its
  // packing, and with a renderer its program's build, start here.
  explicit ScenePipeline(Scene scene, Renderer* renderer = nullptr, ModeFor mode = {});
  ScenePipeline(const ScenePipeline&) = delete;  // the packing refers to the scene it holds
  ScenePipeline& operator=(const ScenePipeline&) = delete;

  void on_read(OnRead f) { on_read_ = std::move(f); }
  // The renderer to stage on and set the scene in, once there is one (the command line
  // reads the scene before it makes a GL context).
  void attach(Renderer& r) { renderer_ = &r; }
  // The GL context was lost and `r` replaces the renderer: the staged textures were the
  // old context's (they are staged again) and the program's build starts again on r.
  void context_restored(Renderer& r);

  // Slices. work(): the stages in order, as many as about budget_ms allows, checking the
  // clock every kWorkUnits units (a small scene is ready in one call; a long step, such
  // as starting the packing or creating the record textures, starts only in a call whose
  // budget it would not add to). step(): one slice of `units` of the current stage, or
  // its one long step (sliced() says which). Both return preparing().
  static constexpr long kWorkUnits = 8192;  // about 0.1-0.5 ms (a unit: core/resumable.h)
  bool work(double budget_ms);
  bool step(long units);
  bool sliced() const { return read_ || (pack_ && !packed_) || (staged_ && !staged_->done()); }
  // Reading, packing or (with a renderer) uploading remain.
  bool preparing() const { return read_ || !packed_ || (renderer_ && !(staged_ && staged_->done())); }
  bool reading() const { return read_ != nullptr; }
  bool packed() const { return packed_.has_value(); }
  // Nothing left that finish() would wait for: the textures are uploaded and the program
  // is built (it polls the driver; a page asks once a frame).
  bool ready();
  // What it is doing, for a progress line ("generating the mesh", "building the BVH",
  // "uploading", "compiling", ...), and how far, 0..1.
  std::string stage() const;
  double progress() const;
  const Times& times() const { return times_; }
  const std::string& path() const { return path_; }

  // To completion: read() the meshes (no GL needed), finish() everything else, then the
  // scene is set in the renderer with `settings` (null: the renderer's; see
  // Renderer::set_scene). Throws, leaving the renderer's scene as it was, on failure.
  void read();
  void finish(const RenderSettings* settings = nullptr);

  // The scene (once read) and, after finish(), what the caller keeps of it.
  const Scene& scene() const { return *scene_; }
  Scene take_scene() { return std::move(*scene_); }
  PackedScene take_packed() { return std::move(*packed_); }  // for refit_shape

 private:
  RenderMode mode() const;
  void start_packing(bool ahead);
  void slice(long units, const std::function<bool()>& more, bool ahead);

  std::string path_;
  Renderer* renderer_ = nullptr;
  ModeFor mode_;
  OnRead on_read_;
  std::unique_ptr<SceneLoad> read_;    // first its meshes are read or generated in slices
  std::unique_ptr<Scene> scene_;       // then it is packed; at a fixed address: the job reads it
  std::unique_ptr<PackJob> pack_;
  std::optional<PackedScene> packed_;
  std::unique_ptr<StagedScene> staged_;  // its record textures, uploaded a row per call
  Times times_;
};

}  // namespace pt
