// A scene made from a glTF file alone (scene/gltf_scene.h): the glTF's first camera node
// read back (position, orientation, yfov through a parent's transform), the framing
// camera (the bounds project inside the image; the bounding sphere just fits the
// vertical field of view), the default environment and path mode, and a malformed file's
// error naming the glTF file and its JSON pointer.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "render/camera.h"
#include "scene/gltf_scene.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

// One triangle (0 0 0), (1 0 0), (0 1 0) in a data: URI, node 0; `nodes` and `cameras`
// are the rest of the file's arrays (JSON text after node 0), `roots` the scene's nodes.
std::string gltf_text(const std::string& nodes, const std::string& cameras, const std::string& roots) {
  return R"({"asset":{"version":"2.0"},
 "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
 "bufferViews":[{"buffer":0,"byteLength":36}],
 "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
 "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
 "nodes":[{"mesh":0})" + nodes + R"(],)" + (cameras.empty() ? "" : R"("cameras":[)" + cameras + "],") +
         R"("scenes":[{"nodes":[)" + roots + R"(]}],"scene":0})";
}

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string dir = (std::filesystem::temp_directory_path() / "pt-gltf-scene-test").string();
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// Where p lands in the image of camera c (render/camera.h): -1..1 across each axis.
glm::vec2 project(const Camera& c, glm::vec3 p, float aspect) {
  const CameraBasis b = camera_basis(c, aspect);
  const glm::vec3 d = p - b.position;
  const float z = glm::dot(d, b.forward);
  REQUIRE(z > 0.0f);
  return {glm::dot(d, b.right) / glm::dot(b.right, b.right) / z, glm::dot(d, b.up) / glm::dot(b.up, b.up) / z};
}

constexpr float kCamY90 = 0.70710678f;  // sin, cos of 45 degrees: a quarter turn's quaternion

}  // namespace

TEST_CASE("glTF scene: the first camera node, through its parent's transform", "[loader][gltf][camera]") {
  // Node 1 (translation 1 0 0) is the parent of node 2: a camera at (0 2 3), turned a
  // quarter about +y, so it looks down -x from (1 2 3). Node 3 (a second camera, pitched
  // up 30 degrees) comes later in the scene's list but has the higher index: not used.
  const std::string nodes = R"(,{"translation":[1,0,0],"children":[2]},
    {"camera":0,"translation":[0,2,3],"rotation":[0,)" + std::to_string(kCamY90) + "," + "0," + std::to_string(kCamY90) + R"(]},
    {"camera":1,"rotation":[0.25881905,0,0,0.96592583]})";
  const std::string cameras = R"({"type":"perspective","perspective":{"yfov":0.6,"znear":0.1,"aspectRatio":3}},
    {"type":"perspective","perspective":{"yfov":1.0,"znear":0.1}})";
  const Scene s = load_scene_file(write_temp("cam.gltf", gltf_text(nodes, cameras, "3,0,1")));
  const Camera& c = s.camera;
  CHECK(c.position.x == Approx(1.0f).margin(1e-5));
  CHECK(c.position.y == Approx(2.0f).margin(1e-5));
  CHECK(c.position.z == Approx(3.0f).margin(1e-5));
  const glm::vec3 f = camera_forward(c);
  CHECK(f.x == Approx(-1.0f).margin(1e-5));
  CHECK(f.y == Approx(0.0f).margin(1e-5));
  CHECK(f.z == Approx(0.0f).margin(1e-5));
  CHECK(c.up.y == Approx(1.0f).margin(1e-5));
  CHECK(c.fov_y == Approx(0.6 * 180.0 / M_PI).epsilon(1e-5));
  CHECK(s.render.mode == RenderMode::PathTracer);
  CHECK(s.environment.map_path == default_env_map());
  CHECK(s.environment.map);

  // The pitched camera alone: 30 degrees up, looking down -z otherwise; rolled cameras
  // keep their up (node +y).
  const Scene p = load_scene_file(write_temp("pitch.gltf", gltf_text(nodes, cameras, "0,3")));
  CHECK(p.camera.pitch == Approx(30.0f).epsilon(1e-4));
  const glm::vec3 pf = camera_forward(p.camera);
  CHECK(pf.y == Approx(0.5f).margin(1e-5));
  CHECK(pf.z == Approx(-std::sqrt(3.0f) / 2.0f).margin(1e-5));
  CHECK(p.camera.up.z == Approx(0.5f).margin(1e-5));
  CHECK(p.camera.fov_y == Approx(1.0 * 180.0 / M_PI).epsilon(1e-5));
}

TEST_CASE("glTF scene: without a camera node, a camera that frames the bounds", "[loader][gltf][camera]") {
  const Scene s = load_scene_file(write_temp("nocam.gltf", gltf_text("", "", "0")));
  const auto [lo, hi] = mesh_bounds(s);
  CHECK(lo == glm::vec3(0.0f));
  CHECK(hi == glm::vec3(1.0f, 1.0f, 0.0f));
  // The shipped test grid too: every corner of its box inside the image, at 1:1 and 16:9.
  const Scene g = load_scene_file(repo_path("assets/gltf/mr-grid.gltf"));
  for (const Scene* sc : {&s, &g}) {
    const auto [l, h] = mesh_bounds(*sc);
    const Camera& c = sc->camera;
    const glm::vec3 centre = 0.5f * (l + h);
    const float radius = 0.5f * glm::length(h - l);
    // Looking along -z at the centre; the sphere's angular radius is half the field of view.
    CHECK(camera_forward(c).z == Approx(-1.0f).margin(1e-6));
    CHECK(glm::length(glm::vec2(c.position - centre)) == Approx(0.0f).margin(1e-5));
    CHECK(std::asin(radius / glm::length(c.position - centre)) == Approx(glm::radians(c.fov_y) / 2.0f).epsilon(1e-5));
    for (float aspect : {1.0f, 16.0f / 9.0f})
      for (int k = 0; k < 8; ++k) {
        const glm::vec3 corner(k & 1 ? h.x : l.x, k & 2 ? h.y : l.y, k & 4 ? h.z : l.z);
        const glm::vec2 q = project(c, corner, aspect);
        INFO("corner " << k << " at " << q.x << ", " << q.y);
        CHECK(std::abs(q.x) <= 1.0f);
        CHECK(std::abs(q.y) <= 1.0f);
      }
  }
  CHECK(g.materials.size() >= 25);  // its own materials, as <Mesh src> brings them
}

TEST_CASE("glTF scene: a malformed file names itself and the JSON pointer", "[loader][gltf]") {
  auto error_of = [](const std::string& path) -> std::string {
    try {
      load_scene_file(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  };
  const std::string bad_cam = write_temp("badcam.gltf", gltf_text(R"(,{"camera":0})", R"({"type":"perspective","perspective":{"yfov":0,"znear":0.1}})", "0,1"));
  CHECK(error_of(bad_cam) == bad_cam + ": /cameras/0/perspective/yfov: must be in (0, pi) radians");
  const std::string no_cam = write_temp("nocamera.gltf", gltf_text(R"(,{"camera":4})", "", "0,1"));
  CHECK(error_of(no_cam) == no_cam + ": /nodes/1: no camera 4");
  std::string text = gltf_text("", "", "0");
  text.replace(text.find("\"count\":3"), 9, "\"count\":4");
  const std::string bad_acc = write_temp("badacc.gltf", text);
  CHECK(error_of(bad_acc).rfind(bad_acc + ": /accessors/0", 0) == 0);
  const std::string syntax = write_temp("syntax.gltf", "{\"asset\":\n{\"version\":\"2.0\"}\n,,}");
  CHECK(error_of(syntax).rfind(syntax + ":", 0) == 0);
  CHECK(error_of(syntax).find("<Mesh>") == std::string::npos);
}
