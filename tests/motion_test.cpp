// Motion blur on every shape kind (issue 15): a translation by velocity * t over the
// shutter (shapes/shape.h: parse_motion).
//  - the loader: every kind takes `velocity` or `end` (its position at time 1), not both;
//  - bounds: a moving kind's box holds its hits at every time in [0, motion_bound]
//    (CPU); in the packed BVH, each primitive is inside its leaf's and every ancestor's
//    box at times 0, motion_bound / 2 and motion_bound (a node marked with a moving shape
//    moving with it: render/packing_motion.cpp), a moving mesh's hierarchy is marked,
//    moving triangle primitives are marked, and a refit keeps all of it;
//  - intersection: the GLSL (scene_intersect at time g_time, through the BVH) against the
//    CPU twin of the shape moved to that time, for every kind;
// The renders (tests/motion_render_test.cpp): moving box, disk and triangle lights
// against the time-averaged closed form, and a moving mesh against the mean of static
// renders at shutter times.
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "app/picking.h"
#include "core/error.h"
#include "gl_context.h"
#include "glsl_harness.h"
#include "render/packing.h"
#include "scene/xml_loader.h"
#include "shadergen/shadergen.h"
#include "test_paths.h"

using namespace pt;

namespace {

constexpr const char* kVelocity = "0.7 -0.4 0.9";
const glm::vec3 kV(0.7f, -0.4f, 0.9f);

// The kind's example with extra attributes, inside a scene, with a Diffuse material.
std::string example_xml(int kind, const std::string& attrs) {
  std::string e = kShapeTraits[kind].example;
  REQUIRE(e.substr(e.size() - 2) == "/>");
  return e.substr(0, e.size() - 2) + " " + attrs + "><Diffuse/></" + kShapeKinds[kind].xml + ">";
}

Scene load(const std::string& objects) {
  return load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects>" + objects + "</Objects></SceneLevel>",
                         repo_path("scenes") + "/x.xml");
}

std::string load_error(const std::string& objects) {
  try {
    load(objects);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string vec_text(glm::vec3 v) { return std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z); }

glm::vec3 unit(std::mt19937& rng) {
  std::normal_distribution<float> g;
  for (;;) {
    const glm::vec3 v(g(rng), g(rng), g(rng));
    if (glm::dot(v, v) > 1e-6f) return glm::normalize(v);
  }
}

bool within(glm::vec3 p, glm::vec3 lo, glm::vec3 hi, float eps) {
  return glm::all(glm::greaterThanEqual(p, lo - eps)) && glm::all(glm::lessThanEqual(p, hi + eps));
}

// The scene with every shape moved to time t (what the shutter sees then).
Scene at_time(Scene s, float t) {
  for (Shape& sh : s.shapes) move(sh.params, velocity(sh.params) * t);
  return s;
}

}  // namespace

TEST_CASE("motion: every shape kind takes velocity or end, not both", "[loader][motion]") {
  for (int kind = 0; kind < kNumShapeKinds; ++kind) {
    INFO(kShapeKinds[kind].xml);
    const Scene still = load(example_xml(kind, ""));
    REQUIRE(still.shapes.size() == 1);
    CHECK(velocity(still.shapes[0].params) == glm::vec3(0.0f));
    const Scene v = load(example_xml(kind, std::string("velocity=\"") + kVelocity + "\""));
    CHECK(velocity(v.shapes[0].params) == kV);
    // `end`: the kind's position at time 1.
    const glm::vec3 start = position(still.shapes[0].params);
    const Scene e = load(example_xml(kind, "end=\"" + vec_text(start + kV) + "\""));
    CHECK(glm::distance(velocity(e.shapes[0].params), kV) < 1e-5f);
    CHECK_THAT(load_error(example_xml(kind, std::string("velocity=\"") + kVelocity + "\" end=\"1 1 1\"")),
               Catch::Contains(std::string("<") + kShapeKinds[kind].xml + ">: give either 'velocity' or 'end'"));
    CHECK_THAT(load_error(example_xml(kind, "velocity=\"1 0\"")), Catch::Contains("velocity"));
  }
  // Every instance a mesh file makes moves together.
  const Scene m = load("<Mesh src=\"../assets/gltf/mr-grid.gltf\" velocity=\"1 2 3\"/>");
  REQUIRE(m.shapes.size() > 1);
  for (const Shape& s : m.shapes) CHECK(velocity(s.params) == glm::vec3(1, 2, 3));
}

TEST_CASE("motion: a moving kind's bounds hold its hits at every time of the shutter", "[shapes][motion]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const float motion_bound = 1.5f;
  for (int kind = 0; kind < kNumShapeKinds; ++kind) {
    INFO(kShapeKinds[kind].xml);
    const Scene s = load(example_xml(kind, std::string("velocity=\"") + kVelocity + "\""));
    const ShapeBounds b = bounds(s.shapes[0].params, ShapeContext{&s.meshes, motion_bound});
    const ShapeBounds b0 = bounds(s.shapes[0].params, ShapeContext{&s.meshes, 0.0f});
    if (info(s.shapes[0].kind()).bvh != BvhRole::Unbounded) {  // the box grows by the motion
      CHECK(glm::distance(b.hi - b.lo, (b0.hi - b0.lo) + glm::abs(kV) * motion_bound) < 1e-4f);
    }
    int hits = 0, late = 0;
    for (int i = 0; i < 3000; ++i) {
      const float t = motion_bound * u(rng);
      const Scene moved = at_time(s, t);
      const glm::vec3 o = 4.0f * unit(rng) + position(moved.shapes[0].params);
      const Ray r{o, glm::normalize(position(moved.shapes[0].params) + 0.8f * unit(rng) * u(rng) - o)};
      const Hit h = intersect_scene(moved, r);
      if (h.id < 0) continue;
      ++hits;
      late += !within(h.p, b0.lo, b0.hi, 1e-5f);
      CHECK(within(h.p, b.lo, b.hi, 1e-5f));
    }
    CHECK(hits > 500);
    if (info(s.shapes[0].kind()).bvh != BvhRole::Unbounded) CHECK(late > 100);  // the motion takes it out of its box at time 0
  }
}

TEST_CASE("motion: packed moving triangles and mesh instances are marked and bounded over the shutter", "[packing][motion]") {
  const std::string objects =
      "<Triangle v0=\"0 0 0\" v1=\"1 0 0\" v2=\"0 1 0\" velocity=\"3 0 -1\"><Diffuse/></Triangle>"
      "<Triangle v0=\"0 0 2\" v1=\"1 0 2\" v2=\"0 1 2\"><Diffuse/></Triangle>"
      "<Mesh generate=\"icosphere\" level=\"2\" scale=\"0.5\" position=\"-2 0 0\" velocity=\"0 2 0.5\"><Diffuse/></Mesh>"
      "<Mesh generate=\"icosphere\" level=\"1\" scale=\"0.5\" position=\"2 0 0\"><Diffuse/></Mesh>"
      "<Box min=\"4 0 0\" max=\"5 1 1\" velocity=\"0 0 -2\"><Diffuse/></Box>"
      "<Disk center=\"0 4 0\" normal=\"0 1 0\" radius=\"0.5\" velocity=\"1 1 1\"><Diffuse/></Disk>";
  Scene scene = load_scene_text("<SceneLevel><Camera position=\"0 0 5\" shutter=\"1.25\"/><Objects>" + objects + "</Objects></SceneLevel>",
                                repo_path("scenes") + "/x.xml");
  PackedScene p = pack_scene(scene);
  CHECK(p.motion_bound == 1.25f);
  // At times 0, motion_bound / 2 and motion_bound, each node's box (a node marked with a
  // moving shape: moved with it) holds every primitive below it where it is then (checked
  // through the leaves' ancestors).
  int marked = 0;
  for (int n = 0; n < p.nodes.count(); ++n) marked += node_mover(p.node_count[size_t(n)]) >= 0;
  auto check_prim = [&](int q) {
    const Shape& s = scene.shapes[size_t(p.prim_shape[size_t(q)])];
    const glm::vec3 v = velocity(s.params);
    const int tag = int(p.prims.get(q, prim_rec::tag));
    std::vector<glm::vec3> pts;
    if (tag >= 0) {  // a triangle: marked when it moves, its vertices at time 0
      CHECK(p.prims.get(q, prim_rec::extra) == (v != glm::vec3(0.0f) ? 1.0f : 0.0f));
      for (const Field* f : {&prim_rec::v0, &prim_rec::v1, &prim_rec::v2}) pts.push_back(p.prims.get3(q, *f));
    } else {
      const ShapeBounds b = bounds(s.params, ShapeContext{&scene.meshes, 0.0f});
      pts = {b.lo, b.hi};
    }
    for (const float t : {0.0f, 0.5f * p.motion_bound, p.motion_bound})
      for (int n = p.prim_leaf[size_t(q)]; n >= 0; n = p.node_parent[size_t(n)]) {
        const int m = node_mover(p.node_count[size_t(n)]);
        const glm::vec3 moved = m >= 0 ? velocity(scene.shapes[size_t(m)].params) * t : glm::vec3(0.0f);
        if (m >= 0) CHECK(m == p.prim_shape[size_t(q)]);
        for (const glm::vec3& x : pts)
          CHECK(within(x + v * t, p.nodes.get3(n, node_rec::lo) + moved, p.nodes.get3(n, node_rec::hi) + moved, 1e-5f * (1.0f + glm::length(x))));
      }
  };
  // The moving mesh's 320 triangles lie under nodes marked with it: most of its hierarchy.
  CHECK(marked > 300);
  for (int q = p.unbounded; q < p.prims.count(); ++q) check_prim(q);
  // An analytic primitive's copy of its record carries the velocity (the box: q6..q8).
  const int box = p.shape_prim[4];
  CHECK(glm::vec3(p.prims.get(box, *prim_rec::kAnalytic[6]), p.prims.get(box, *prim_rec::kAnalytic[7]),
                  p.prims.get(box, *prim_rec::kAnalytic[8])) == glm::vec3(0, 0, -2));
  // The mesh's shape record holds its velocity (prim_velocity reads it).
  CHECK(glm::vec3(p.shapes.get(2, shape_rec::q0), p.shapes.get(2, shape_rec::q1), p.shapes.get(2, shape_rec::q2)) == glm::vec3(0, 2, 0.5f));
  // A moved moving triangle (the panel) is refit over the shutter too.
  move(scene.shapes[0].params, glm::vec3(0.0f, 5.0f, 0.0f));
  std::vector<int> prims, nodes;
  REQUIRE(refit_shape(scene, p, 0, prims, nodes));
  check_prim(p.shape_prim[0]);
}

TEST_CASE("motion: only a scene with a moving shape compiles the time-dependent intersection", "[shadergen][motion]") {
  Scene still = load("<Triangle v0=\"0 0 0\" v1=\"1 0 0\" v2=\"0 1 0\"><Diffuse/></Triangle><Mesh generate=\"icosphere\" level=\"1\"><Diffuse/></Mesh>");
  const std::string a = generate_integrator(Features::of(still)).text;
  CHECK(a.find("#define HAS_MOTION") == std::string::npos);
  CHECK(a.find("vec3 prim_velocity(") == std::string::npos);
  still.shapes[1].as<Mesh>()->velocity = glm::vec3(1, 0, 0);
  const std::string b = generate_integrator(Features::of(still)).text;
  CHECK(b.find("#define HAS_MOTION 1") != std::string::npos);
  CHECK(b.find("if (s.kind == SHAPE_MESH) return mesh_rec(s).velocity;") != std::string::npos);
  CHECK(b.find("if (s.kind == SHAPE_TRIANGLE) return triangle_rec(s).velocity;") != std::string::npos);
}

TEST_CASE("motion: every kind's GLSL at time t hits what its CPU twin moved to t hits", "[gpu][shapes][motion]") {
  test_gl();
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  // Each kind through the BVH (its nodes moved by node_mover) and through the flat loop
  // (accel_choice.h: a one-shape scene would otherwise be flat only).
  for (int run = 0; run < 2 * kNumShapeKinds; ++run) {
    const int kind = run / 2;
    INFO(kShapeKinds[kind].xml << (run % 2 ? ", flat" : ", bvh"));
    const Scene s = load(example_xml(kind, std::string("velocity=\"") + kVelocity + "\""));
    Features f = Features::of(s);
    f.flat = run % 2 == 1;
    const PackedScene packed = pack_scene(s);
    REQUIRE(packed.motion_bound == 1.0f);
    // Rays towards the shape where it is at a random time t in [0, 1]; x.w carries t.
    std::vector<glm::vec4> origins;
    std::vector<glm::vec4> dirs(4096, glm::vec4(0.0f));
    std::vector<float> times;
    std::vector<Ray> rays;
    for (int i = 0; i < 4096; ++i) {
      const float t = u(rng);
      const glm::vec3 c = position(at_time(s, t).shapes[0].params);
      const glm::vec3 o = c + 3.0f * unit(rng);
      const Ray r{o, glm::normalize(c + glm::vec3(u(rng), u(rng), u(rng)) * 2.0f - 1.0f - o)};
      rays.push_back(r);
      times.push_back(t);
      origins.emplace_back(r.o, t);
      dirs[size_t(i)] = glm::vec4(r.d, 0.0f);
    }
    GlslKernel k(
        "uniform sampler2D u_dirs;\n"
        "vec4 kernel(vec4 x, int i) {\n"
        "  vec3 d = texelFetch(u_dirs, ivec2(i % 4096, i / 4096), 0).xyz;\n"
        "  g_time = x.w;\n"
        "  Hit h = scene_intersect(Ray(x.xyz, d));\n"
        "  return vec4(float(h.id), h.t, h.id >= 0 ? dot(h.p - x.xyz, d) : 0.0, 0.0);\n}\n",
        f);
    k.bind_scene(s, packed);
    const Texture dir_tex(4096, 1, GL_RGBA32F, &dirs[0].x);
    k.bind("u_dirs", dir_tex);
    const std::vector<glm::vec4> gpu = k.run(origins);
    int hits = 0, differ = 0, late = 0;
    const ShapeBounds b0 = bounds(s.shapes[0].params, ShapeContext{&s.meshes, 0.0f});
    for (size_t i = 0; i < rays.size(); ++i) {
      const Hit h = intersect_scene(at_time(s, times[i]), rays[i]);
      hits += h.id >= 0;
      if (int(gpu[i].x) != h.id) {
        ++differ;  // within rounding of an edge
        continue;
      }
      if (h.id < 0) continue;
      late += !within(h.p, b0.lo, b0.hi, 1e-4f);
      const float m = std::max(1.0f, h.t);
      CHECK(std::abs(gpu[i].y - h.t) <= 1e-4f * m);
      CHECK(std::abs(gpu[i].z - h.t) <= 1e-4f * m);  // the hit point is where the shape is at t
    }
    INFO(hits << " hits, " << differ << " differ, " << late << " outside the time-0 box");
    CHECK(hits > 400);
    CHECK(differ <= 8);  // 0.2%
    if (info(s.shapes[0].kind()).bvh != BvhRole::Unbounded) CHECK(late > 100);
  }
}
