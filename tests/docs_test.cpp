// The documentation cannot drift. The format page: every ```xml block of docs/scene-format.md is
// a scene that must load (paths in it are relative to docs/).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/file_io.h"
#include "scene/xml_loader.h"
#include "shadergen/shadergen.h"
#include "gl_context.h"
#include "scene_builders.h"
#include "render/renderer.h"
#include "test_paths.h"

using namespace pt;

namespace {

// The ```xml blocks of docs/scene-format.md.
std::vector<std::string> format_examples() {
  const auto text = read_file(repo_path("docs/scene-format.md"));
  REQUIRE(text);
  std::vector<std::string> out;
  for (size_t at = text->find("```xml\n"); at != std::string::npos; at = text->find("```xml\n", at)) {
    const size_t begin = at + 7, end = text->find("```", begin);
    REQUIRE(end != std::string::npos);
    out.push_back(text->substr(begin, end - begin));
    at = end + 3;
  }
  return out;
}

}  // namespace

TEST_CASE("every example in docs/scene-format.md loads", "[loader][docs]") {
  const std::string path = repo_path("docs/scene-format.md");
  int examples = 0;
  for (const std::string& xml : format_examples()) {
    INFO("example " << examples + 1 << ":\n" << xml);
    try {
      load_scene_text(xml, path);
    } catch (const InputError& e) {
      FAIL(e.what());
    }
    ++examples;
  }
  CHECK(examples >= 8);  // one per section
}

TEST_CASE("every example in docs/scene-format.md renders without NaN and not black", "[gpu][docs]") {
  test_gl();
  int examples = 0;
  for (const std::string& xml : format_examples()) {
    const Scene scene = load_scene_text(xml, repo_path("docs/scene-format.md"));
    INFO("example " << examples + 1 << ":\n" << xml);
    RenderSettings st;
    if (scene.render.mode) st.mode = *scene.render.mode;
    const RenderResult r = render_scene(scene, 24, 16, 2, st);
    double sum = 0.0;
    for (size_t i = 0; i < r.rgba.size(); i += 4) sum += r.rgba[i] + r.rgba[i + 1] + r.rgba[i + 2];
    CHECK(r.counters.bad_samples == 0);
    CHECK(sum > 0.0);
    ++examples;
  }
  CHECK(examples >= 8);
}

// The table of shipped scenes in docs/scenes.md: each scene's kinds and the size of the
// program generated for it (the page's WebGL 2 path tracer), regenerated here; the page
// must contain it verbatim (the regenerated table is written to the build folder).
TEST_CASE("docs/scenes.md lists every shipped scene with its generated shader's size", "[loader][docs][shadergen]") {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(repo_path("scenes")))
    if (e.path().extension() == ".xml") files.push_back(std::filesystem::relative(e.path(), repo_path("")).generic_string());
  std::sort(files.begin(), files.end());
  std::string table = "| scene | shapes | materials | lights sampled | shader (bytes) |\n|---|---|---|---|---|\n";
  for (const std::string& f : files) {
    const Scene scene = load_scene_file(repo_path(f));
    const Features k = Renderer::scene_features(scene);  // the program the renderer builds (auto's traversal)
    std::string shapes, materials, lights;
    for (int i = 0; i < kNumShapeKinds; ++i) {
      if (k.has(ShapeKind(i))) shapes += std::string(shapes.empty() ? "" : ", ") + kShapeKinds[i].xml;
      if (k.has_light(ShapeKind(i))) lights += std::string(lights.empty() ? "" : ", ") + kShapeKinds[i].xml;
    }
    for (int i = 0; i < kNumMaterialKinds; ++i)
      if (k.has(MaterialKind(i))) materials += std::string(materials.empty() ? "" : ", ") + kMaterialKinds[i].xml;
    for (int i = 0; i < kNumLightKinds; ++i)
      if (k.has(LightKind(i))) lights += std::string(lights.empty() ? "" : ", ") + kLightKinds[i].xml;
    if (k.env_map) lights += std::string(lights.empty() ? "" : ", ") + "environment map";
    table += "| `" + f + "` | " + shapes + " | " + materials + " | " + (lights.empty() ? "-" : lights) + " | " +
             std::to_string(generate_integrator(k).text.size()) + " |\n";
  }
  std::ofstream(std::string(PT_BINARY_DIR) + "/scenes-table.md") << table;
  const auto doc = read_file(repo_path("docs/scenes.md"));
  REQUIRE(doc);
  const bool same = doc->find(table) != std::string::npos;
  if (!same) std::printf("docs/scenes.md: the table differs; the current one is in %s/scenes-table.md\n", PT_BINARY_DIR);
  CHECK(same);
}

// The fuzzer's dictionary (tests/fuzz/scene_xml.dict) names every kind of the lists, so
// mutations reach each kind's parser: a kind added without its entry fails here.
TEST_CASE("the scene fuzzer's dictionary names every shape, material and light kind", "[loader][docs]") {
  const auto dict = read_file(repo_path("tests/fuzz/scene_xml.dict"));
  REQUIRE(dict);
  std::vector<const char*> names;
  for (const KindInfo& k : kShapeKinds) names.push_back(k.xml);
  for (const MaterialKindInfo& k : kMaterialKinds) names.push_back(k.xml);
  for (const LightKindInfo& k : kLightKinds) names.push_back(k.xml);
  for (const char* n : names) {
    INFO("missing \"<" << n << "\" in tests/fuzz/scene_xml.dict");
    CHECK(dict->find("\"<" + std::string(n)) != std::string::npos);
  }
}
