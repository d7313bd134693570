// SceneLoad (scene/xml_loader.h): a scene loaded in slices - its meshes read and
// generated a few thousand units at a time - is the scene loaded in one go, bit for bit,
// and fails with the same message.
#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/file_io.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

bool same_floats(const void* a, const void* b, size_t bytes) { return bytes == 0 || std::memcmp(a, b, bytes) == 0; }

void require_same(const Scene& a, const Scene& b) {
  REQUIRE(a.files == b.files);
  REQUIRE(a.shapes.size() == b.shapes.size());
  for (size_t i = 0; i < a.shapes.size(); ++i) {
    CHECK(a.shapes[i].kind() == b.shapes[i].kind());
    const Mesh *ma = a.shapes[i].as<Mesh>(), *mb = b.shapes[i].as<Mesh>();
    CHECK((ma ? ma->mesh : -1) == (mb ? mb->mesh : -1));
    CHECK(a.shapes[i].material == b.shapes[i].material);
    CHECK((ma ? ma->transform : glm::mat4(1.0f)) == (mb ? mb->transform : glm::mat4(1.0f)));
  }
  REQUIRE(a.materials.size() == b.materials.size());
  REQUIRE(a.meshes.size() == b.meshes.size());
  for (size_t i = 0; i < a.meshes.size(); ++i) {
    const MeshData& x = *a.meshes[i];
    const MeshData& y = *b.meshes[i];
    REQUIRE(x.positions.size() == y.positions.size());
    REQUIRE(x.normals.size() == y.normals.size());
    REQUIRE(x.uvs.size() == y.uvs.size());
    REQUIRE(x.triangles.size() == y.triangles.size());
    CHECK(same_floats(x.positions.data(), y.positions.data(), x.positions.size() * sizeof(glm::vec3)));
    CHECK(same_floats(x.normals.data(), y.normals.data(), x.normals.size() * sizeof(glm::vec3)));
    CHECK(same_floats(x.uvs.data(), y.uvs.data(), x.uvs.size() * sizeof(glm::vec2)));
    CHECK(same_floats(x.triangles.data(), y.triangles.data(), x.triangles.size() * sizeof(glm::uvec3)));
  }
}

// Runs a load to its end in slices of `units`; returns the number of slices.
int run_sliced(SceneLoad& l, long units, double* last_progress = nullptr) {
  int slices = 1;
  double p = 0.0;
  while (!l.run(units)) {
    ++slices;
    const double q = l.progress();
    CHECK(q >= p);  // the bar never goes back
    CHECK(q < 1.0);
    p = q;
  }
  CHECK(l.progress() == 1.0);
  if (last_progress) *last_progress = p;
  return slices;
}

struct TempDir {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "pt-scene-load-test";
  TempDir() {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  ~TempDir() { std::filesystem::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name, std::ios::binary) << text;
    return (dir / name).string();
  }
};

// An OBJ grid of n x n quads with normals and uv (2 n^2 triangles).
std::string obj_grid(int n) {
  std::string s = "# grid\n";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) s += "v " + std::to_string(i) + " " + std::to_string(0.01 * ((i * 7 + j * 3) % 5)) + " " + std::to_string(j) + "\n";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) s += "vt " + std::to_string(double(i) / n) + " " + std::to_string(double(j) / n) + "\n";
  s += "vn 0 1 0\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 2, d = a + n + 1;
      s += "f " + std::to_string(a) + "/" + std::to_string(a) + "/1 " + std::to_string(b) + "/" + std::to_string(b) + "/1 " +
           std::to_string(c) + "/" + std::to_string(c) + "/1 " + std::to_string(d) + "/" + std::to_string(d) + "/1\n";
    }
  return s;
}

}  // namespace

TEST_CASE("a scene loaded in slices equals the scene loaded in one go (generated, OBJ, glTF, JSON meshes)", "[loader][slices]") {
  TempDir t;
  t.write("grid.obj", obj_grid(60));
  const std::string models = repo_path("assets/models/");
  const std::string scene = t.write("s.xml", "<SceneLevel><Camera position=\"0 0 9\" up=\"0 1 0\" yaw=\"270\" pitch=\"0\"/><Objects>\n"
      "<Mesh generate=\"icosphere\" level=\"5\" displace=\"0.1\"><Diffuse/></Mesh>\n"
      "<Mesh src=\"grid.obj\" scale=\"0.1\"><Diffuse/></Mesh>\n"
      "<Mesh src=\"" + models + "torus-instances.glb\" position=\"3 0 0\"/>\n"
      "<Mesh src=\"" + models + "torus-instances.gltf\" position=\"-3 0 0\"/>\n"
      "<Mesh src=\"" + repo_path("scenes/reference/cube.json") + "\" position=\"0 3 0\"><Diffuse/></Mesh>\n"
      "<Mesh generate=\"icosphere\" level=\"5\" displace=\"0.1\" position=\"0 -3 0\"><Diffuse/></Mesh>\n"  // the same mesh again: one load
      "</Objects></SceneLevel>\n");
  const Scene whole = load_scene_file(scene);
  REQUIRE(whole.meshes.size() >= 4);
  for (long units : {4096L, 65536L}) {
    SceneLoad l(read_scene_file(scene), scene);
    const int slices = run_sliced(l, units);
    // 20480 triangles subdivided and shaded, 7200 OBJ triangles, the tori: far more units than a few slices.
    CHECK(slices > (units == 4096 ? 20 : 2));
    require_same(l.take(), whole);
  }
}

TEST_CASE("the benchmark scene's million triangles are generated in thousands of slices, the same as in one go", "[loader][slices]") {
  const std::string path = repo_path("scenes/bench/million.xml");
  const Scene whole = load_scene_file(path);
  SceneLoad l(read_scene_file(path), path);
  double last = 0.0;
  const int slices = run_sliced(l, 8192, &last);
  CHECK(slices > 300);   // 1.3 M triangles at 8192 units a slice
  CHECK(last > 0.5);     // the estimate of the work is not far off: the bar gets past half
  require_same(l.take(), whole);
  CHECK(whole.meshes.at(0)->triangles.size() == 1310720);
}

TEST_CASE("a broken mesh fails a sliced load with the message of a load in one go, and a malformed scene fails at once", "[loader][slices]") {
  TempDir t;
  std::string obj = obj_grid(40);
  obj += "f 1 2 99999\n";  // the last line refers to a vertex that does not exist
  t.write("bad.obj", obj);
  const std::string scene = t.write("s.xml", "<SceneLevel><Camera position=\"0 0 9\" up=\"0 1 0\" yaw=\"270\" pitch=\"0\"/><Objects>\n"
      "<Mesh generate=\"icosphere\" level=\"4\"><Diffuse/></Mesh>\n<Mesh src=\"bad.obj\"><Diffuse/></Mesh>\n</Objects></SceneLevel>\n");
  std::string whole_error;
  try {
    load_scene_file(scene);
  } catch (const InputError& e) {
    whole_error = e.what();
  }
  INFO(whole_error);
  REQUIRE(whole_error.find("s.xml:3: <Mesh>: cannot load the mesh:") != std::string::npos);
  REQUIRE(whole_error.find("bad.obj:4965: face corner") != std::string::npos);
  SceneLoad l(read_scene_file(scene), scene);
  std::string sliced_error;
  int slices = 0;
  try {
    while (!l.run(2048)) ++slices;
  } catch (const InputError& e) {
    sliced_error = e.what();
  }
  CHECK(slices > 5);  // it failed late, after slices of work
  CHECK(sliced_error == whole_error);
  // The XML itself is checked by the constructor.
  CHECK_THROWS_AS(SceneLoad("<SceneLevel><Objects>", "broken.xml"), InputError);
}
