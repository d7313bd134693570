#pragma once
#include <memory>
#include <string>

#include "core/resumable.h"
#include "scene/scene.h"

namespace pt {

// Loads a scene in the seed's XML format. Throws InputError naming file and line for
// anything malformed or not understood; never returns a partial scene.
constexpr size_t kMaxSceneBytes = size_t(16) << 20;
// A .gltf or .glb file is a scene of its own (scene/gltf_scene.h); any other file is XML.
Scene load_scene_file(const std::string& path);
// allow_files = false refuses every file reference (<Mesh src>, <Environment map>): for
// text from an untrusted source, and for the fuzzer. generated_triangle_budget >= 0 caps
// the triangles the scene's <Mesh generate> elements make together (an InputError past
// it): the fuzzer's limit, so that a legal level-9 icosphere (5.2 million triangles, seconds
// under ASan) is not reported as a hang (docs/reliability.md); negative: no cap.
Scene load_scene_text(const std::string& text, const std::string& path, bool allow_files = true,
                      long long generated_triangle_budget = -1);
// The scene file's text (throws InputError: missing, or over kMaxSceneBytes).
std::string read_scene_file(const std::string& path);

// The same load in slices, for a page that must not stop drawing for a large mesh: the
// constructor parses and checks the XML (throws InputError), then run(work) reads or
// generates the meshes the scene names (a unit: about a triangle, vertex or byte; see
// core/resumable.h) and finally builds the scene, throwing InputError as
// load_scene_text would (the same code: load_scene_text runs it in one go).
class SceneLoad {
 public:
  SceneLoad(const std::string& text, const std::string& path, bool allow_files = true,
            long long generated_triangle_budget = -1);
  // The scene file `path` by its name: a .gltf or .glb is the scene of that file alone
  // (scene/gltf_scene.h: its errors name the glTF file, not the generated scene), any
  // other file is read (read_scene_file) as XML. The one place a scene file is opened.
  static std::unique_ptr<SceneLoad> open(const std::string& path);
  ~SceneLoad();
  SceneLoad(const SceneLoad&) = delete;
  SceneLoad& operator=(const SceneLoad&) = delete;
  bool run(long work);  // true once the scene is built
  void finish();
  bool done() const;
  double progress() const;         // 0..1, by the meshes read so far
  const std::string& stage() const;  // "reading model.glb", ...
  Scene take();                    // once done()

 private:
  Resumable steps();
  void build();
  struct State;
  std::unique_ptr<State> s_;
  Resumable job_;
};

}  // namespace pt
