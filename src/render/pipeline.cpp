// The scene pipeline: read, pack, stage, compile (render/pipeline.h).
#include "render/pipeline.h"

#include <chrono>
#include <climits>

namespace pt {
namespace {

constexpr int kUploadRows = 1;  // rows of record texels per upload call (64 KB)

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

}  // namespace

ScenePipeline::ScenePipeline(const std::string& path, Renderer* renderer, ModeFor mode)
    : path_(path), renderer_(renderer), mode_(std::move(mode)), read_(SceneLoad::open(path)) {}

ScenePipeline::ScenePipeline(Scene scene, Renderer* renderer, ModeFor mode)
    : path_(scene.path), renderer_(renderer), mode_(std::move(mode)), scene_(std::make_unique<Scene>(std::move(scene))) {
  start_packing(true);
}

RenderMode ScenePipeline::mode() const { return mode_ ? mode_(*scene_) : renderer_->settings().mode; }

void ScenePipeline::start_packing(bool ahead) {
  if (ahead && renderer_) renderer_->program_ready(*scene_, mode());  // its program starts building alongside the packing
  pack_ = std::make_unique<PackJob>(*scene_);
}

void ScenePipeline::context_restored(Renderer& r) {
  renderer_ = &r;
  staged_.reset();  // its textures were the lost context's
  if (scene_) r.program_ready(*scene_, mode());
}

void ScenePipeline::slice(long units, const std::function<bool()>& more, bool ahead) {
  const auto ts = Clock::now();
  if (read_) {
    bool done = false;
    while (!(done = read_->run(units)) && more()) {
    }
    times_.read_ms += ms_since(ts);
    ++times_.read_slices;
    if (done) {
      scene_ = std::make_unique<Scene>(read_->take());
      read_.reset();
      if (on_read_) on_read_(*scene_, times_);
    }
  } else if (!pack_) {
    start_packing(ahead);
  } else if (!packed_) {
    bool done = false;
    while (!(done = pack_->run(units)) && more()) {
    }
    if (done) packed_ = pack_->take();
    times_.pack_ms += ms_since(ts);
    ++times_.pack_slices;
  } else if (!renderer_) {
    return;  // nothing to stage on
  } else if (!staged_) {
    staged_ = std::make_unique<StagedScene>(renderer_->limits(), *packed_);
    times_.upload_ms += ms_since(ts);
  } else if (!staged_->done()) {
    // The record textures, a row at a time (copies to the GPU; WebGL calls between
    // animation frames are fine, and a lost context drops `staged_`).
    while (!staged_->upload(kUploadRows) && more()) {
    }
    times_.upload_ms += ms_since(ts);
  }
}

bool ScenePipeline::work(double budget_ms) {
  if (!preparing()) return false;
  const auto t0 = Clock::now();
  // The stages in order, as many as the budget allows: a small scene loads in one slice.
  // A long step (starting the packing, creating the record textures) starts a stage only
  // with the budget untouched, so that it never adds to another stage's slice.
  auto fresh = [&] { return ms_since(t0) < 1.0; };
  auto more = [&] { return ms_since(t0) < budget_ms; };
  do {
    if (!read_ && !pack_ && !fresh() && scene_->meshes.size() > 0) break;  // the program's build starts: 10+ ms in the page
    if (packed_ && renderer_ && !staged_ && !fresh() && packed_->prims.count() > kDataWidth) break;  // large textures: their own slice
    slice(kWorkUnits, more, true);
  } while (preparing() && more());
  return preparing();
}

bool ScenePipeline::step(long units) {
  if (preparing()) slice(units, [] { return false; }, true);
  return preparing();
}

bool ScenePipeline::ready() { return !preparing() && renderer_ && renderer_->program_ready(*scene_, mode()); }

std::string ScenePipeline::stage() const {
  return read_ ? read_->stage() : !pack_ ? "starting the packing" : !packed_ ? pack_->stage() : staged_ && staged_->done() ? "compiling" : "uploading";
}

// The whole preparation: reading the meshes (a scene file's first part of the bar), then
// packing (its stages weighted in PackJob::progress) and the upload, which took about a
// tenth as long as the packing for a large mesh.
double ScenePipeline::progress() const {
  constexpr double kReadShare = 0.3;
  if (read_) return kReadShare * read_->progress();
  const double rest = packed_ ? 0.9 + 0.1 * (staged_ ? staged_->progress() : 0.0) : pack_ ? 0.9 * pack_->progress() : 0.0;
  return times_.read_slices > 0 ? kReadShare + (1.0 - kReadShare) * rest : rest;
}

void ScenePipeline::read() {
  while (read_) slice(LONG_MAX, [] { return true; }, false);
}

void ScenePipeline::finish(const RenderSettings* settings) {
  // What a page staged ahead is swapped in; the command line's scene is packed here and
  // staged by the renderer, which then builds (or finds) the program: nothing was built
  // ahead, so the compile time it reports is the compile's alone.
  while (read_ || !packed_) slice(LONG_MAX, [] { return true; }, false);
  renderer_->set_scene(*scene_, *packed_, staged_.get(), settings);  // throws before changing anything if the program does not build
}

}  // namespace pt
