// GL objects are not leaked: every texture, framebuffer, program, shader and vertex array
// the renderer makes through gpu/ is deleted when it is dropped, and loading scenes again
// and again (new programs, new data textures, resizes) keeps the live count where the
// first load left it. The page's long-use test (tests/browser/endurance_test.mjs) reads
// the same counters through ptStats().glObjects.
#include <catch2/catch.hpp>

#include <string>

#include "gl_context.h"
#include "gpu/gl_objects.h"
#include "render/renderer.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {
std::string counts_text(const std::array<int, gl_objects::kKinds>& c) {
  std::string t;
  for (int k = 0; k < gl_objects::kKinds; ++k) t += std::string(gl_objects::kNames[size_t(k)]) + " " + std::to_string(c[size_t(k)]) + "  ";
  return t;
}
}  // namespace

TEST_CASE("the renderer deletes every GL object it makes, and reloads do not accumulate them", "[gpu][leaks]") {
  test_gl();
  const auto before = gl_objects::live();
  const char* scenes[] = {"scenes/reference/scene2.xml", "scenes/textures.xml", "scenes/mesh-cube.xml",
                          "scenes/reference/scene0.xml"};
  {
    Renderer r;
    r.resize(16, 16);
    std::array<int, gl_objects::kKinds> after_first{};
    for (int round = 0; round < 3; ++round) {
      for (const char* name : scenes) {
        r.set_scene(load_scene_file(repo_path(name)));
        r.resize(16 + 8 * round, 16);
        r.step();
      }
      if (round == 0) after_first = gl_objects::live();
      INFO("round " << round << ": " << counts_text(gl_objects::live()) << " after the first: " << counts_text(after_first));
      // Textures and framebuffers depend only on the last scene and the size: the same.
      CHECK(gl_objects::live()[gl_objects::kTexture] == after_first[gl_objects::kTexture]);
      CHECK(gl_objects::live()[gl_objects::kFramebuffer] == after_first[gl_objects::kFramebuffer]);
      CHECK(gl_objects::live()[gl_objects::kShader] == after_first[gl_objects::kShader]);
      // Programs: the cache keeps at most what it kept after the first round.
      CHECK(gl_objects::live()[gl_objects::kProgram] <= after_first[gl_objects::kProgram]);
    }
    CHECK(gl_objects::live()[gl_objects::kProgram] > before[gl_objects::kProgram]);
  }
  INFO("before " << counts_text(before) << " after " << counts_text(gl_objects::live()));
  CHECK(gl_objects::live() == before);
}

TEST_CASE("a scene's textures go with it: what stays after a scene depends on that scene alone", "[gpu][leaks]") {
  test_gl();
  const Scene plain = load_scene_file(repo_path("scenes/reference/scene2.xml"));
  // An environment map (glTF spheres under the afternoon sky), then back to a scene without.
  const Scene mapped = load_scene_file(repo_path("scenes/gltf/mr-grid.xml"));
  REQUIRE(plain.environment.map == nullptr);
  REQUIRE(mapped.environment.map != nullptr);
  Renderer r;
  r.resize(16, 16);
  r.set_scene(plain);
  r.step();
  const auto alone = gl_objects::live();
  r.set_scene(mapped);
  r.step();
  CHECK(gl_objects::live()[gl_objects::kTexture] > alone[gl_objects::kTexture]);
  r.set_scene(plain);
  r.step();
  INFO("after the plain scene alone: " << counts_text(alone) << " after the mapped one, then the plain one: " << counts_text(gl_objects::live()));
  CHECK(gl_objects::live()[gl_objects::kTexture] == alone[gl_objects::kTexture]);
}
