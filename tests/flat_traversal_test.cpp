// The flat traversal (accel/accel_choice.h: every ray tests every primitive, no BVH)
// against the BVH's: the same packing, the same primitive routines, only the order of the
// tests differs, so the renders must be identical - every float of the mean and the ray
// count - on scenes without two primitives at exactly the same distance along a ray. And
// the flat program has no traversal: no node record, no stack, no node count.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "accel_run.h"
#include "gl_context.h"
#include "glsl_harness.h"
#include "render/packing.h"
#include "render/renderer.h"
#include "core/file_io.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

bool contains(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

AccelRun run_accel(const Scene& scene, Accel accel, bool compute) {
  RenderSettings st;
  st.accel = accel;
  st.compute = compute;
  st.sample_limit = 6;
  st.spp_per_pass = 2;
  return run_render(scene, st, 37, 29);
}

// scene2 with `extra` small diffuse spheres inside the room (more primitives than auto
// makes flat). Not thousands: llvmpipe ends a shader invocation's loops after 65,535
// iterations in all (gallivm's loop limiter), and a flat loop over 20,000 triangles
// reaches that within one sample (a forced flat on a large scene renders wrong there).
Scene room(int extra) {
  const std::string path = repo_path("scenes/reference/scene2.xml");
  std::string xml = *read_file(path), spheres;
  for (int i = 0; i < extra; ++i)
    spheres += "<Sphere center=\"" + std::to_string(-170 + (i % 10) * 25) + " " + std::to_string(20 + (i / 10) % 5 * 20) + " " +
               std::to_string(-80 + (i / 50) * 40) + "\" radius=\"4\"><Diffuse/></Sphere>";
  xml.replace(xml.find("</Objects>"), 0, spheres);
  return load_scene_text(xml, path);
}

}  // namespace

TEST_CASE("flat traversal: the same image and ray count as the BVH's", "[gpu][accel]") {
  // Planes (unbounded), boxes and spheres, meshes and instances, motion blur (node_mover),
  // glTF alpha MASK and BLEND (hit cuts: hit_present decides during the traversal), and
  // rooms of 110 and 160 primitives (the flat loop forced where auto picks the BVH: kind by
  // kind, and above kFlatOrderMax the one loop).
  struct Case {
    const char* name;
    bool compute;
  };
  const Case cases[] = {{"scenes/reference/scene0.xml", false},   {"scenes/reference/scene2.xml", false},
                        {"scenes/reference/scene2.xml", true},    {"scenes/cornell-box.xml", false},
                        {"scenes/mesh-cube.xml", true},           {"scenes/seed/06-logo.xml", false},
                        {"room", false},                          {"room-100", false},
                        {"scenes/analytic/closed-room.xml", false},
                        {"alpha", false}};
  for (const Case& c : cases) {
    const std::string name = c.name;
    const Scene scene =
        name == "alpha" ? load_scene_text("<SceneLevel><Camera position=\"0 0 3\"/><Objects><Mesh src=\"../assets/gltf/test-mask.gltf\"/>"
                                          "<Mesh src=\"../assets/gltf/test-blend.gltf\" position=\"0.3 0.2 -0.5\"/><Sphere center=\"0 0 -2\" radius=\"1\">"
                                          "<Emit><Absorb intensity=\"2\" color=\"1 1 1\"/></Emit></Sphere></Objects></SceneLevel>",
                                          repo_path("scenes/alpha-test.xml"))
                        : name == "room"     ? room(150)
                        : name == "room-100" ? room(100)
                                             : load_scene_file(repo_path(name));
    const AccelRun bvh = run_accel(scene, Accel::Bvh, c.compute);
    const AccelRun flat = run_accel(scene, Accel::Flat, c.compute);
    REQUIRE_FALSE(bvh.flat);
    REQUIRE(flat.flat);
    size_t differ = 0;
    double max_value = 0.0;
    for (size_t i = 0; i < bvh.rgba.size(); ++i) {
      differ += bvh.rgba[i] != flat.rgba[i];
      max_value = std::max(max_value, double(std::abs(bvh.rgba[i])));
    }
    std::printf("%-34s %-8s primitives %5ld: %zu of %zu floats differ, rays %.0f vs %.0f\n", c.name, c.compute ? "compute" : "fragment",
                scene_primitives(scene), differ, bvh.rgba.size(), flat.counters.rays, bvh.counters.rays);
    INFO(c.name << (c.compute ? " compute" : " fragment"));
    CHECK(max_value > 0.0);
    CHECK(flat.counters.bad_samples == 0);
    CHECK(flat.counters.rays == bvh.counters.rays);
    CHECK(differ == 0);
  }
}

TEST_CASE("flat traversal: auto follows the SAH rule; bvh and flat override it", "[gpu][accel]") {
  const Scene small = load_scene_file(repo_path("scenes/reference/scene2.xml"));
  std::string xml = "<SceneLevel><Camera position=\"0 0 30\"/><Objects>";
  for (int i = 0; i < int(kFlatMaxConsidered) + 1; ++i)
    xml += "<Sphere center=\"" + std::to_string(i % 10) + " " + std::to_string(i / 10) + " 0\" radius=\"0.4\"><Diffuse/></Sphere>";
  const Scene big = load_scene_text(xml + "</Objects></SceneLevel>", "big.xml");
  REQUIRE(accel_costs(small).flat());
  REQUIRE_FALSE(accel_costs(big).flat());
  test_gl();
  Renderer r;
  r.resize(8, 8);
  for (Accel a : {Accel::Auto, Accel::Bvh, Accel::Flat}) {
    RenderSettings st;
    st.accel = a;
    r.set_settings(st);
    r.set_scene(small);
    CHECK(r.using_flat() == (a != Accel::Bvh));
    r.set_scene(big);
    CHECK(r.using_flat() == (a == Accel::Flat));
  }
}

TEST_CASE("flat traversal: the program has no node record, node count nor stack", "[gpu][accel]") {
  test_gl();
  const Scene scene = load_scene_file(repo_path("scenes/reference/scene2.xml"));
  for (bool flat : {false, true}) {
    Features f = Features::of(scene);
    f.flat = flat;
    const std::string text = generate_integrator(f).text;
    CHECK((text.find("#define HAS_FLAT 1") != std::string::npos) == flat);
    CHECK((text.find("u_node_data") != std::string::npos) == !flat);  // the node record's sampler and loader
    // What the compiler kept: the traversal's uniforms are gone from the flat program.
    GlslKernel k("vec4 kernel(vec4 x, int i) { return vec4(scene_intersect(Ray(x.xyz, vec3(0.0, 0.0, 1.0))).t); }", f);
    CHECK((k.program().loc("u_num_nodes") == -1) == flat);
    CHECK((k.program().loc("u_num_unbounded") == -1) == flat);
    // scene2 (10 primitives) loops kind by kind: its order is in uniforms instead of a count.
    if (flat) CHECK(k.program().loc("u_flat_order") != -1);
    if (flat) CHECK(k.program().loc("u_num_prims") == -1);
  }
}

// Kind by kind, each loop runs its own kind's test and nothing dispatches on a kind: a
// software rasteriser (SwiftShader, the page's) runs every side of a branch, so the one
// loop's dispatch ran every kind's test for every primitive. Planes first, as in leaf order.
TEST_CASE("flat traversal: kind by kind, each loop with one kind's test", "[shadergen][accel]") {
  const Scene scene = load_scene_text(
      "<SceneLevel><Camera position=\"0 0 3\"/><Objects><Sphere center=\"1 0 0\" radius=\"0.4\"><Diffuse/></Sphere>"
      "<Plane normal=\"0 1 0\" d=\"-1\"><Diffuse/></Plane><Box min=\"-1 -1 -1\" max=\"0 0 0\"><Diffuse/></Box>"
      "<Triangle v0=\"0 0 0\" v1=\"1 0 0\" v2=\"0 1 0\"><Diffuse/></Triangle></Objects></SceneLevel>",
      "kinds.xml");
  Features f = Features::of(scene);
  REQUIRE(f.flat_order);
  f.flat = true;
  const std::string text = generate_integrator(f).text;
  const size_t at = text.find("void flat_groups(Ray r, RayPre pre, bool any_hit, int skip, inout Hit h) {");
  REQUIRE(at != std::string::npos);
  const std::string body = text.substr(at, text.find("\n}\n", at) - at);
  std::vector<std::string> loops;
  for (size_t i = body.find("  for ("); i != std::string::npos; i = body.find("  for (", i + 1))
    loops.push_back(body.substr(i, body.find("\n  }", i) - i));
  REQUIRE(loops.size() == 4);
  const char* tests[] = {"intersect_plane(", "intersect_sphere(", "intersect_box(", "bvh_triangle("};
  for (size_t l = 0; l < loops.size(); ++l)
    for (size_t t = 0; t < 4; ++t) CHECK(contains(loops[l], tests[t]) == (l == t));
  CHECK_FALSE(contains(body, "kind =="));
  CHECK_FALSE(contains(body, "intersect_analytic("));
  // Above kFlatOrderMax primitives the one loop stays.
  f.flat_order = false;
  CHECK_FALSE(contains(generate_integrator(f).text, "void flat_groups(Ray r, RayPre pre, bool any_hit, int skip, inout Hit h) {"));
}
