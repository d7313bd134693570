// GL objects are not leaked: every texture, framebuffer, program, shader and vertex array
// the renderer makes through gpu/ is deleted when it is dropped, and loading scenes again
// and again (new programs, new data textures, resizes) keeps the live count where the
// first load left it. The page's long-use test (tests/browser/endurance_test.mjs) reads
// the same counters through ptStats().glObjects.
#include <catch2/catch.hpp>

#include <chrono>
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

// A build started and never asked for (a page's load replaced before its program was used;
// one built ahead for settings that changed on the way) is finished by poll_programs(),
// which the page calls every frame, idle or not: its two shaders and its sources' copies do
// not stay until that feature set is used again (the long-use test saw 2 shaders and
// 250 KB of wasm heap pending for good). The program itself stays cached.
TEST_CASE("a program built ahead and never used is finished by the renderer's poll", "[gpu][leaks][compile]") {
  test_gl();
  const Scene shown = load_scene_file(repo_path("scenes/reference/scene2.xml"));
  const Scene ahead = load_scene_file(repo_path("scenes/analytic/closed-room.xml"));  // other kinds
  Renderer r;
  r.resize(8, 8);
  r.set_scene(shown);
  r.step();
  const auto alone = gl_objects::live();
  REQUIRE(r.pending_programs().empty());
  r.program_ready(ahead);  // started, and then the page moves on
  REQUIRE(r.pending_programs().size() == 1);
  CHECK(gl_objects::live()[gl_objects::kShader] == alone[gl_objects::kShader] + 2);
  const auto t0 = std::chrono::steady_clock::now();
  while (!r.pending_programs().empty() && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120)) {
    r.poll_programs();  // a frame of the page at its sample limit: no draws
  }
  INFO("after the first scene alone: " << counts_text(alone) << " after the poll: " << counts_text(gl_objects::live()));
  CHECK(r.pending_programs().empty());
  CHECK(gl_objects::live()[gl_objects::kShader] == alone[gl_objects::kShader]);
  CHECK(gl_objects::live()[gl_objects::kProgram] == alone[gl_objects::kProgram] + 1);
  const size_t built = r.programs_compiled();
  r.set_scene(ahead);  // the finished program is used as it is
  CHECK(r.programs_compiled() == built);
  CHECK(r.step() >= 0);
}
