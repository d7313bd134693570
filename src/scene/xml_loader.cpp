// The XML scene loader: parses the document (tinyxml2), reads ahead the meshes it names
// so that a page can load them in slices (SceneLoad), then walks it into a Scene
// (scene/xml_walk.h: elements, shapes, materials; each material kind parses itself).
#include "scene/xml_loader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <tinyxml2.h>

#include "core/error.h"
#include "core/file_io.h"
#include "scene/gltf_scene.h"
#include "scene/xml_walk.h"

namespace pt {

using tinyxml2::XMLElement;

// Text between elements is never meaningful in the format: it is an error, not ignored.
static void reject_text(const tinyxml2::XMLNode* n, const std::string& path) {
  for (const tinyxml2::XMLNode* c = n->FirstChild(); c; c = c->NextSibling()) {
    if (const tinyxml2::XMLText* t = c->ToText()) {
      const char* v = t->Value();
      if (v && v[std::strspn(v, " \t\r\n")] != '\0')
        throw InputError(path, c->GetLineNum(), "unexpected text \"" + std::string(v).substr(0, 40) + "\"" +
                                                    (n->ToElement() ? " in <" + std::string(n->Value()) + ">" : ""));
    } else if (c->ToUnknown()) {
      throw InputError(path, c->GetLineNum(), "unexpected markup <" + std::string(c->Value()).substr(0, 40) + ">");
    }
    reject_text(c, path);  // depth is bounded by tinyxml2 (TINYXML2_MAX_ELEMENT_DEPTH)
  }
}

struct SceneLoad::State {
  tinyxml2::XMLDocument doc;
  Loader loader;
  std::vector<MeshSource> sources;  // in the order of the document, each key once
  std::vector<double> estimate;     // units each is expected to take
  size_t current = 0;               // the source being loaded
  size_t last_current = 0;
  double spent = 0.0;               // units given to the current source so far
  double progress = 0.0;            // never goes back
  std::string stage;
  Scene scene;
  bool gltf = false;  // a scene of a glTF file alone (scene/gltf_scene.h)
};

SceneLoad::SceneLoad(const std::string& text, const std::string& path, bool allow_files,
                     long long generated_triangle_budget)
    : s_(std::make_unique<State>()) {
  // tinyxml2 stops at a NUL byte and accepts what came before: a NUL is an error here.
  const size_t nul = text.find('\0');
  if (nul != std::string::npos)
    throw InputError(path, 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(nul), '\n')),
                     "NUL byte at byte " + std::to_string(nul) + " (not a text file?)");
  tinyxml2::XMLDocument& doc = s_->doc;
  if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    // ErrorStr() is "Error=NAME ErrorID=.. Line number=N[: detail]": keep NAME and detail.
    const std::string full = doc.ErrorStr() ? doc.ErrorStr() : "";
    const size_t detail = full.find(": ", full.find("Line number="));
    const std::string why = std::string(doc.ErrorName()) + (detail == std::string::npos ? "" : full.substr(detail));
    throw InputError(path, std::max(1, doc.ErrorLineNum()), "malformed XML: " + why);
  }
  reject_text(&doc, path);
  Loader& l = s_->loader;
  l.allow_files = allow_files;
  l.generated_triangle_budget = generated_triangle_budget;
  l.file = path;
  l.scene.path = path;
  l.scene.files = {path};
  // Read ahead: every <Mesh> with a well-formed source, wherever it is. One that is not
  // (or is somewhere a mesh is not allowed) is left to the scene's own pass, which says why.
  Loader ahead;
  ahead.allow_files = allow_files;
  ahead.generated_triangle_budget = generated_triangle_budget;
  ahead.file = path;
  std::vector<const XMLElement*> todo{doc.RootElement()};
  while (!todo.empty()) {
    const XMLElement* e = todo.back();
    todo.pop_back();
    for (const XMLElement* c = e ? e->LastChildElement() : nullptr; c; c = c->PreviousSiblingElement()) todo.push_back(c);
    if (!e || std::strcmp(e->Name(), "Mesh") != 0) continue;
    try {
      XmlAttrs a(e, path);
      MeshSource m = ahead.mesh_source(a, e);
      if (std::none_of(s_->sources.begin(), s_->sources.end(), [&](const MeshSource& o) { return o.key == m.key; })) {
        double units = 1.0;
        if (m.src.empty()) {
          const double tris = 20.0 * std::pow(4.0, m.level);
          units = tris * (4.0 / 3.0 + 1.0) + 2.0 * (tris / 2.0);  // subdivisions, normals; displacement and uv per vertex
        } else {
          std::error_code ec;
          const auto bytes = std::filesystem::file_size(m.src, ec);
          if (!ec) units = double(bytes) * (has_extension(m.src, ".obj") ? 1.5 : 0.4);
        }
        s_->sources.push_back(std::move(m));
        s_->estimate.push_back(std::max(1.0, units));
      }
    } catch (const InputError&) {
    }
  }
  s_->stage = s_->sources.empty() ? "building the scene" : "reading the meshes";
  job_ = steps();
}

SceneLoad::~SceneLoad() = default;

Resumable SceneLoad::steps() {
  State& s = *s_;
  for (s.current = 0; s.current < s.sources.size(); ++s.current) {
    const MeshSource& m = s.sources[s.current];
    s.stage = m.src.empty() ? "generating the mesh" : "reading " + m.src.substr(m.src.find_last_of('/') + 1);
    Resumable load = load_mesh_steps(m, s.loader.mesh_files[m.key]);
    while (!co_await load) {
    }
  }
  s.stage = "building the scene";
  // After meshes, the scene's build (one step: 10-40 ms in the page for a million
  // triangles) gets a slice of its own.
  if (!s.sources.empty()) co_await EndSlice{};
  build();
}

void SceneLoad::build() {
  State& s = *s_;
  if (!s.gltf) {
    s.loader.root(s.doc.RootElement());
    s.scene = std::move(s.loader.scene);
    return;
  }
  try {
    s.loader.root(s.doc.RootElement());
  } catch (const InputError& e) {
    throw gltf_scene_error(e, s.loader.file);
  }
  s.scene = std::move(s.loader.scene);
  set_gltf_camera(s.scene, s.loader.mesh_files.begin()->second.camera);  // its one mesh file
  if (s.scene.environment.map_path.empty())
    s.scene.warnings.push_back(s.loader.file + ": the default environment " + default_env_map() + " is missing: a constant sky instead");
}

std::unique_ptr<SceneLoad> SceneLoad::open(const std::string& path) {
  if (!is_gltf_file(path)) return std::make_unique<SceneLoad>(read_scene_file(path), path);
  std::string env = default_env_map();
  if (!std::filesystem::exists(env)) env.clear();
  auto l = std::make_unique<SceneLoad>(gltf_scene_text(path, env), path);
  l->s_->gltf = true;
  return l;
}

void SceneLoad::finish() { job_.finish(); }

bool SceneLoad::run(long work) {
  State& s = *s_;
  s.spent += double(work);
  const bool done = job_.run(work);
  if (s.current != s.last_current) s.spent = 0.0, s.last_current = s.current;  // the units went mostly to the next source
  if (!done && s.current < s.sources.size())
    s.progress = std::max(s.progress, (double(s.current) + std::min(0.99, s.spent / s.estimate[s.current])) / double(s.sources.size()));
  return done;
}

bool SceneLoad::done() const { return job_.done(); }

double SceneLoad::progress() const { return job_.done() ? 1.0 : std::min(0.99, s_->progress); }

const std::string& SceneLoad::stage() const { return s_->stage; }

Scene SceneLoad::take() { return std::move(s_->scene); }

Scene load_scene_text(const std::string& text, const std::string& path, bool allow_files,
                      long long generated_triangle_budget) {
  SceneLoad l(text, path, allow_files, generated_triangle_budget);
  l.finish();
  return l.take();
}

std::string read_scene_file(const std::string& path) {
  auto text = read_file(path);
  if (!text) throw InputError(path, 0, "cannot open the scene file");
  // Meshes and images are separate files: a scene this large is not a scene.
  if (text->size() > kMaxSceneBytes)
    throw InputError(path, 0, "the scene file has " + std::to_string(text->size()) + " bytes (at most " +
                                  std::to_string(kMaxSceneBytes) + ")");
  return std::move(*text);
}

Scene load_scene_file(const std::string& path) {
  const std::unique_ptr<SceneLoad> l = SceneLoad::open(path);
  l->finish();
  return l->take();
}

}  // namespace pt
