// Shader generator tests: a program holds the code of the kinds its scene uses and
// nothing else, its size does not depend on the number of objects, and includes and
// compiler logs resolve to snippet files.
#include <algorithm>
#include <utility>
#include <catch2/catch.hpp>

#include "scene/xml_loader.h"
#include "shadergen/shadergen.h"
#include "test_paths.h"

using namespace pt;

namespace {

bool contains(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

Scene spheres(int n) {
  std::string xml = "<SceneLevel><Camera position=\"0 0 10\"/><Objects>";
  for (int i = 0; i < n; ++i)
    xml += "<Sphere center=\"" + std::to_string(i) + " 0 0\" radius=\"0.5\"><Attenuate color=\"0.5 0.5 0.5\"><Diffuse/></Attenuate></Sphere>";
  return load_scene_text(xml + "</Objects></SceneLevel>", "spheres.xml");
}

}  // namespace

TEST_CASE("a spheres-and-diffuse scene carries no other shape or material code", "[shadergen]") {
  const Features f = Features::of(spheres(3));
  CHECK(f.has(ShapeKind::Sphere));
  CHECK(f.has(MaterialKind::Diffuse));
  const std::string src = generate_integrator(f).text;
  CHECK(contains(src, "void intersect_sphere("));
  CHECK(contains(src, "bool sample_diffuse("));
  for (const char* absent : {"intersect_box", "intersect_plane", "intersect_triangle", "sample_metal", "fresnel_conductor",
                             "sample_smooth_dielectric", "sample_transmit", "refract_local", "sample_emit"})
    CHECK_FALSE(contains(src, absent));
}

TEST_CASE("every kind in the lists brings exactly its own snippet", "[shadergen]") {
  for (int i = 0; i < kNumShapeKinds; ++i) {
    Features f;
    f.shapes = 1u << i;
    f.materials = 1u;
    const ShaderSource src = generate_integrator(f);
    for (int j = 0; j < kNumShapeKinds; ++j) {
      // A mesh's triangles are intersected by the triangle's code: it brings both.
      const bool expect = i == j || (ShapeKind(i) == ShapeKind::Mesh && ShapeKind(j) == ShapeKind::Triangle);
      const std::string file = std::string("shapes/") + kShapeKinds[j].glsl + ".glsl";
      INFO("kind " << kShapeKinds[i].glsl << ", snippet " << file);
      CHECK((std::find(src.files.begin(), src.files.end(), file) != src.files.end()) == expect);
      if (kShapeKinds[j].bvh != BvhRole::Instanced)  // an instance has no intersection of its own
        CHECK(contains(src.text, std::string("void intersect_") + kShapeKinds[j].glsl + "(") == expect);
    }
  }
  for (int i = 0; i < kNumMaterialKinds; ++i) {
    Features f;
    f.shapes = 1u;
    f.materials = 1u << i;
    const std::string src = generate_integrator(f).text;
    for (int j = 0; j < kNumMaterialKinds; ++j)
      CHECK(contains(src, std::string("bool sample_") + kMaterialKinds[j].glsl + "(") == (i == j));
  }
}

TEST_CASE("only scenes with a moving sphere get time-dependent intersection", "[shadergen]") {
  Scene s = spheres(2);
  CHECK(generate_integrator(Features::of(s)).text.find("#define HAS_MOTION") == std::string::npos);
  s.shapes[1].as<Sphere>()->velocity = glm::vec3(1.0f, 0.0f, 0.0f);
  CHECK(Features::of(s).motion);
  CHECK(generate_integrator(Features::of(s)).text.find("#define HAS_MOTION 1") != std::string::npos);
}

TEST_CASE("the program does not grow with the number of objects", "[shadergen]") {
  // (The traversal, flat or BVH, is the renderer's choice: render/packing.h, accel_costs.)
  const Features a = Features::of(spheres(1)), b = Features::of(spheres(1000));
  CHECK(a.key() == b.key());
  CHECK(generate_integrator(a).text == generate_integrator(b).text);
}

TEST_CASE("scene_primitives counts what a flat loop tests; the traversal flag is in the key", "[shadergen][accel]") {
  CHECK(scene_primitives(spheres(7)) == 7);
  // A plane counts (every ray tests it either way); a mesh counts its triangles.
  const Scene s0 = load_scene_file(repo_path("scenes/reference/scene0.xml"));
  CHECK(scene_primitives(s0) == long(s0.shapes.size()));
  const Scene cube = load_scene_file(repo_path("scenes/mesh-cube.xml"));
  long tris = 0, others = 0;
  for (const Shape& sh : cube.shapes)
    if (const Mesh* m = sh.as<Mesh>()) tris += long(cube.meshes[size_t(m->mesh)]->triangles.size());
    else ++others;
  REQUIRE(tris > 0);
  CHECK(scene_primitives(cube) == tris + others);
  CHECK_FALSE(Features::of(cube).flat);  // Features::of leaves it to the renderer
  Features f = Features::of(spheres(2)), g = f;
  g.flat = !f.flat;
  CHECK(f.key() != g.key());
  Accel a = Accel::Auto;
  CHECK(accel_from_name("flat", &a));
  CHECK(a == Accel::Flat);
  CHECK_FALSE(accel_from_name("kd-tree", &a));
  CHECK(a == Accel::Flat);
}

TEST_CASE("reference scenes select their kinds", "[shadergen]") {
  const Features f0 = Features::of(load_scene_file(repo_path("scenes/reference/scene0.xml")));
  CHECK(f0.has(ShapeKind::Plane));
  CHECK(f0.has(ShapeKind::Box));
  CHECK_FALSE(f0.has(ShapeKind::Triangle));
  CHECK(f0.has(MaterialKind::SmoothDielectric));
  CHECK_FALSE(f0.has(MaterialKind::Transmit));
  const Features f1 = Features::of(load_scene_file(repo_path("scenes/reference/scene1.xml")));
  CHECK(f1.has(MaterialKind::Transmit));
}

TEST_CASE("includes resolve once each; unknown ones are errors", "[shadergen]") {
  const ShaderSource s = resolve_includes("#include \"fresnel.glsl\"\n#include \"fresnel.glsl\"\nvoid f() {}\n", "root");
  CHECK(s.files == std::vector<std::string>{"root", "fresnel.glsl"});
  CHECK(s.text.find("float fresnel_dielectric(") == s.text.rfind("float fresnel_dielectric("));
  CHECK_THROWS_WITH(resolve_includes("\n#include \"nope.glsl\"\n", "root"), "root:2: unknown include \"nope.glsl\"");
}

TEST_CASE("compiler logs name the snippet file and its own line", "[shadergen]") {
  ShaderSource s;
  s.files = {"<generated>", "materials/metal.glsl"};
  CHECK(s.map_log("ERROR: 1:42: 'foo' : undeclared identifier") == "ERROR: materials/metal.glsl:42: 'foo' : undeclared identifier");
  CHECK(s.map_log("0(7) : error C1008: undefined variable") == "<generated>:7: error C1008: undefined variable");
  CHECK(s.map_log("1:5(20): error: `x' undeclared") == "materials/metal.glsl:5: error: `x' undeclared");
}
