// The seed's JSON meshes: the reference cube loads through a scene; malformed files fail
// with file and line; a mesh cube renders as the box it describes.
#include <catch2/catch.hpp>

#include "core/error.h"
#include "core/file_io.h"
#include "gl_context.h"
#include "scene/mesh_json.h"
#include "scene/mesh_obj.h"

#include <filesystem>
#include <fstream>
#include "scene/xml_loader.h"
#include "scene_builders.h"
#include "test_paths.h"

using namespace pt;

namespace {

std::string mesh_error(const std::string& json) {
  try {
    parse_mesh_json(json, "m.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

Scene cube_scene(bool as_mesh, const char* src = "reference/cube.json") {
  const std::string shape = as_mesh ? "<Mesh src=\"" + std::string(src) + "\" position=\"0 1 0\" scale=\"1\">"
                                    : "<Box min=\"-1 0 -1\" max=\"1 2 1\">";
  const std::string close = as_mesh ? "</Mesh>" : "</Box>";
  return load_scene_text(
      "<SceneLevel><Camera position=\"4 3.5 5\" yaw=\"51.3\" pitch=\"-21\"/>"
      "<Light position=\"2 6 3\" radius=\"0.5\" intensity=\"40\"/><Objects>"
      "<Plane normal=\"0 1 0\" d=\"0\"><Attenuate color=\"0.6 0.6 0.6\"><Diffuse/></Attenuate></Plane>" +
          shape + "<Attenuate color=\"0.8 0.3 0.2\"><Diffuse/></Attenuate>" + close + "</Objects></SceneLevel>",
      repo_path("scenes/cube-test.xml"));
}

}  // namespace

TEST_CASE("the reference cube.json loads through <Mesh>", "[loader][mesh]") {
  const Scene s = cube_scene(true);
  int meshes = 0;
  for (const Shape& sh : s.shapes)
    if (const Mesh* inst = sh.as<Mesh>()) {
      ++meshes;
      CHECK(s.meshes.at(size_t(inst->mesh))->triangles.size() == 12);
    }
  CHECK(meshes == 1);
  const MeshData m = parse_mesh_json(*read_file(repo_path("scenes/reference/cube.json")), "cube.json");
  CHECK(m.positions.size() == 28);
  CHECK(m.normals.size() == 28);
  CHECK(m.uvs.size() == 28);
  CHECK(m.triangles.size() == 12);
}

TEST_CASE("malformed JSON meshes name the file and line", "[loader][mesh]") {
  CHECK(mesh_error("{\"vertex\": [0, 0, 0,\n 1, 1 1], \"indices\": [0, 0, 0]}") == "m.json:2: expected ']'");
  CHECK(mesh_error("{\"vertex\": [0, 0], \"indices\": [0, 0, 0]}") == "m.json:1: \"vertex\" needs 3 numbers per vertex");
  CHECK(mesh_error("{\"vertex\": [0, 0, 0], \"indices\": [0, 0, 1]}") == "m.json:1: index 1.000000 is not a vertex (there are 1)");
  CHECK(mesh_error("{\"vertex\": [0, 0, 0], \"indices\": [0, 0, 0], \"colour\": []}") == "m.json:1: unknown key \"colour\"");
  CHECK(mesh_error("{\"vertex\": [0, 0, 1e999], \"indices\": [0, 0, 0]}") == "m.json:1: a number is not finite");
  CHECK(mesh_error("{\"vertex\": [0, 0, 0], \"indices\": [0, 0, 0]} x") == "m.json:1: unexpected text after the object");
  CHECK(mesh_error("{\"vertex\": [0, 0, 0], \"vertex\": [0, 0, 0]}") == "m.json:1: duplicate key \"vertex\"");
  try {
    load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects>\n<Mesh src=\"missing.json\"><Diffuse/></Mesh>"
                    "</Objects></SceneLevel>",
                    repo_path("scenes/x.xml"));
    FAIL("loaded");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("x.xml:2: <Mesh>: cannot load the mesh: ") != std::string::npos);
    CHECK(std::string(e.what()).find("missing.json: cannot open the mesh file") != std::string::npos);
  }
}

TEST_CASE("a Wavefront OBJ mesh loads (quads triangulated); bad ones name the file", "[loader][mesh]") {
  const Scene s = cube_scene(true, "../assets/cube.obj");
  size_t triangles = 0;
  for (const Shape& sh : s.shapes)
    if (const Mesh* inst = sh.as<Mesh>()) triangles += s.meshes.at(size_t(inst->mesh))->triangles.size();
  CHECK(triangles == 12);
  const std::string dir = std::string(PT_BINARY_DIR) + "/mesh-test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/bad.obj") << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
  try {
    parse_mesh_obj(*read_file(dir + "/bad.obj"), dir + "/bad.obj");
    FAIL("loaded");
  } catch (const InputError& e) {
    INFO(e.what());
    CHECK(std::string(e.what()) == dir + "/bad.obj:3: face corner '7' refers to vertex 7, but 2 are defined before it");
  }
  try {
    load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects>\n<Mesh src=\"m.ply\"><Diffuse/></Mesh></Objects></SceneLevel>", "x.xml");
    FAIL("loaded");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "x.xml:2: <Mesh>: 'src' must be a .json (the seed's format), .obj, .gltf or .glb mesh");
  }
}

TEST_CASE("a mesh cube renders as the box it describes", "[gpu][mesh]") {
  test_gl();
  const int W = 48, T = 8;
  for (const char* src : {"reference/cube.json", "../assets/cube.obj"}) {
  INFO(src);
  const RenderResult a = render_scene(cube_scene(true, src), W, W, 128), b = render_scene(cube_scene(false), W, W, 128);
  double worst = 0;
  for (int ty = 0; ty < W / T; ++ty)
    for (int tx = 0; tx < W / T; ++tx) {
      const Estimate x = region_mean(a, tx * T, ty * T, (tx + 1) * T, (ty + 1) * T);
      const Estimate y = region_mean(b, tx * T, ty * T, (tx + 1) * T, (ty + 1) * T);
      worst = std::max(worst, std::abs(x.mean - y.mean) / std::sqrt(x.se * x.se + y.se * y.se + 1e-12));
    }
  INFO("worst tile |z| " << worst);
  CHECK(worst < 5.0);
  CHECK(a.counters.bad_samples == 0);
  }
}
