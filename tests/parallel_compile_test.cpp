// Asynchronous program builds (KHR_parallel_shader_compile where the driver has it):
// Renderer::program_ready() starts the build and polls it; set_scene() then uses the same
// program; a broken build still reports its mapped log, at finish().
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>

#include "gl_context.h"
#include "gpu/program.h"
#include "render/packing.h"
#include "render/renderer.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

TEST_CASE("program_ready starts a build, polls it, and set_scene reuses it", "[gpu][compile]") {
  test_gl();
  std::printf("KHR_parallel_shader_compile: %s\n", Program::parallel_compile() ? "yes" : "no");
  const Scene s = load_scene_file(repo_path("scenes/reference/scene2.xml"));
  Renderer r;
  r.resize(8, 8);
  const auto t0 = std::chrono::steady_clock::now();
  int polls = 0;
  while (!r.program_ready(s)) {
    ++polls;
    REQUIRE(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120));
  }
  CHECK(r.programs_compiled() == 1);
  r.set_scene(s);
  CHECK(r.programs_compiled() == 1);
  r.step();
  CHECK(r.samples() == 1);
  INFO("polls before the program was ready: " << polls);
  if (!Program::parallel_compile()) CHECK(polls == 0);  // no extension: ready at once (finish blocks)
}

// A page showing a scene whose <Render mode> differs from the current mode builds that
// mode's program ahead (program_ready with the mode) and sets settings and scene at once:
// no program of the old mode for the new scene is built on the way.
TEST_CASE("a scene set with its own mode uses the program built ahead for that mode, and only it", "[gpu][compile]") {
  test_gl();
  const Scene first = load_scene_file(repo_path("scenes/analytic/closed-room.xml"));  // other kinds than scene2
  const Scene next = load_scene_file(repo_path("scenes/reference/scene2.xml"));
  Renderer r;
  r.resize(8, 8);
  r.set_scene(first);
  REQUIRE(r.programs_compiled() == 1);
  RenderSettings whitted;
  whitted.mode = RenderMode::Whitted;
  while (!r.program_ready(next, RenderMode::Whitted)) {
  }
  CHECK(r.programs_compiled() == 2);
  r.set_scene(next, pack_scene(next), nullptr, &whitted);
  CHECK(r.programs_compiled() == 2);  // the path tracer's program for `next` was never built
  CHECK(r.settings().mode == RenderMode::Whitted);
  CHECK(r.step() >= 0);
}

TEST_CASE("a started program that fails reports its log at finish", "[gpu][compile]") {
  test_gl();
  ShaderSource fs = resolve_includes("#version 300 es\nprecision highp float;\nout vec4 o;\nvoid main() { o = vec4(undefined_name); }\n", "broken.glsl");
  Program p = Program::start(fullscreen_vertex(), fs);
  while (!p.completed()) {
  }
  try {
    p.finish();
    FAIL("finish() did not throw");
  } catch (const GlError& e) {
    CHECK(std::string(e.what()).find("broken.glsl:4") != std::string::npos);
  }
  CHECK(p.id() == 0);
}
