// The BVH traversal in GLSL against brute force in GLSL: the same primitive routines, the
// same rays, once through the hierarchy (trace_scene) and once over every primitive in
// order. The nearest hit must be the same primitive at the same distance; any-hit
// (shadow) queries must agree with it. Also: the shader does not grow with the scene.
#include <cstdio>
#include <random>

#include <catch2/catch.hpp>

#include "gl_context.h"
#include "glsl_harness.h"
#include "render/packing.h"
#include "scene_builders.h"

using namespace pt;

namespace {

// Spheres, boxes (some nested, some overlapping), lone triangles, a plane and a creased
// grid mesh with shared edges: about 400 primitives.
Scene mixed_scene(std::vector<glm::vec3>* grid_vertices, int* grid_n) {
  Scene s;
  const int m = add_material(s, Material{});
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-10.0f, 10.0f), r(0.05f, 2.0f);
  for (int i = 0; i < 60; ++i) add_sphere(s, glm::vec3(u(rng), u(rng), u(rng)), r(rng), m);
  for (int i = 0; i < 60; ++i) {
    const glm::vec3 c(u(rng), u(rng), u(rng)), e(r(rng), r(rng), r(rng));
    add_box(s, c - e, c + e, m);
  }
  for (int i = 0; i < 60; ++i) {
    Triangle t;
    t.v0 = glm::vec3(u(rng), u(rng), u(rng));
    t.v1 = t.v0 + glm::vec3(r(rng), u(rng) * 0.3f, r(rng));
    t.v2 = t.v0 + glm::vec3(-r(rng), r(rng), u(rng) * 0.3f);
    s.shapes.push_back(Shape(t, m));
  }
  s.shapes.push_back(Shape(Plane{.normal = glm::vec3(0.0f, 1.0f, 0.0f), .d = -11.0f}, m));
  // A 10 x 10 creased grid (200 triangles), placed by a transform.
  const int N = 10;
  auto mesh = std::make_shared<MeshData>();
  for (int y = 0; y <= N; ++y)
    for (int x = 0; x <= N; ++x) mesh->positions.emplace_back(float(x), float(y), 0.3f * std::sin(float(x * 7 + y * 3)));
  for (int y = 0; y < N; ++y)
    for (int x = 0; x < N; ++x) {
      const unsigned a = unsigned(y * (N + 1) + x), b = a + 1, c = a + unsigned(N + 1), d = c + 1;
      mesh->triangles.emplace_back(a, b, d);
      mesh->triangles.emplace_back(a, d, c);
    }
  s.meshes.push_back(mesh);
  Mesh inst{.mesh = 0, .transform = glm::mat4(1.0f)};
  inst.transform[3] = glm::vec4(-5.0f, -5.0f, -2.0f, 1.0f);
  s.shapes.push_back(Shape(inst, m));
  if (grid_vertices) {
    for (glm::vec3 p : mesh->positions) grid_vertices->push_back(p + glm::vec3(-5.0f, -5.0f, -2.0f));
    *grid_n = N;
  }
  return s;
}

// Input: ray origin (xyz) and a seed (w); output: (prim, t, shape, occluded at t_test).
const char* kRays =
    "uniform int u_mode;  // 0: random directions; 1: aimed at x.xyz from a random point\n"
    "Ray make_ray(vec4 x, int i) {\n"
    "  rng_init(uvec2(uint(i), 17u), 0u);\n"
    "  if (u_mode == 0) {\n"
    "    float z = 1.0 - 2.0 * rand01(), phi = TWO_PI * rand01(), s = sqrt(max(0.0, 1.0 - z * z));\n"
    "    return Ray(x.xyz, vec3(s * cos(phi), s * sin(phi), z));\n"
    "  }\n"
    "  float hgt = 1.0 + 3.0 * rand01(), rad = hgt * sqrt(rand01()), phi = TWO_PI * rand01();\n"
    "  vec3 o = x.xyz + vec3(rad * cos(phi), rad * sin(phi), hgt);\n"
    "  return Ray(o, normalize(x.xyz - o));\n"
    "}\n";

std::vector<glm::vec4> run(const Scene& scene, const PackedScene& p, const std::string& body, const std::vector<glm::vec4>& in, int mode) {
  GlslKernel k(std::string(kRays) + body, Features::of(scene));
  k.bind_scene(scene, p);
  k.program().set("u_num_prims", p.prims.count());
  k.program().set("u_mode", mode);
  return k.run(in);
}

// Compares the hierarchy with brute force on the same rays; returns the number of rays
// that hit something.
int compare(const Scene& scene, const std::vector<glm::vec4>& in, int mode, const char* what) {
  const PackedScene p = pack_scene(scene);
  // The shadow query is asked at a distance that splits the hits: half the nearest t.
  const std::vector<glm::vec4> bvh = run(scene, p,
                                         "vec4 kernel(vec4 x, int i) {\n  Ray r = make_ray(x, i);\n"
                                         "  Hit h = trace_scene(r, T_INF, false, -1);\n"
                                         "  float probe = h.id >= 0 ? (fract(x.w) < 0.5 ? h.t * 0.999 : h.t * 1.001) : 1e30;\n"
                                         "  bool occ = occluded(r, probe, -1);\n"
                                         "  return vec4(float(h.prim), h.t, float(h.id), occ ? 1.0 : 0.0);\n}\n",
                                         in, mode);
  const std::vector<glm::vec4> brute = run(scene, p,
                                           "vec4 kernel(vec4 x, int i) {\n  Ray r = make_ray(x, i);\n"
                                           "  RayPre pre = prepare_ray(r);\n  Hit h = no_hit();\n"
                                           "  for (int k = 0; k < u_num_prims; ++k) bvh_prim(k, r, pre, -1, h);\n"
                                           "  return vec4(float(h.prim), h.t, float(h.id), 0.0);\n}\n",
                                           in, mode);
  int hits = 0, other_prim = 0, ties = 0, t_off = 0, shadow_wrong = 0;
  for (size_t i = 0; i < in.size(); ++i) {
    const glm::vec4 a = bvh[i], c = brute[i];
    if (c.x >= 0.0f) ++hits;
    const bool both_miss = a.x < 0.0f && c.x < 0.0f;
    if (!both_miss && a.x != c.x) {
      if (a.x >= 0.0f && c.x >= 0.0f && a.y == c.y) {
        ++ties;  // two primitives at exactly the same distance: either is the nearest hit
      } else {
        ++other_prim;
        if (other_prim <= 5)
          std::printf("  ray %zu: BVH prim %d t %.9g, brute force prim %d t %.9g\n", i, int(a.x), a.y, int(c.x), c.y);
      }
    }
    if (!both_miss && std::abs(a.y - c.y) > 1e-6f * std::abs(c.y)) ++t_off;
    // Occluded before 0.999 t exactly when nothing is nearer; before 1.001 t when something is hit.
    const bool want_occ = c.x >= 0.0f && std::fmod(in[i].w, 1.0f) >= 0.5f;
    if ((a.w > 0.5f) != want_occ) ++shadow_wrong;
  }
  std::printf("%s: %zu rays, %d hit; different primitive %d, exact ties %d, t off by > 1e-6 %d, shadow answers wrong %d\n", what,
              in.size(), hits, other_prim, ties, t_off, shadow_wrong);
  CHECK(other_prim == 0);
  CHECK(t_off == 0);
  CHECK(shadow_wrong == 0);
  return hits;
}

}  // namespace

TEST_CASE("BVH traversal finds exactly the nearest hit of brute force, 10^6 random rays", "[gpu][bvh]") {
  test_gl();
  const Scene scene = mixed_scene(nullptr, nullptr);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-14.0f, 14.0f), w(0.0f, 1.0f);
  std::vector<glm::vec4> in(1000000);
  for (glm::vec4& x : in) x = glm::vec4(u(rng), u(rng), u(rng), w(rng));
  const int hits = compare(scene, in, 0, "random rays");
  CHECK(hits > 300000);
}

TEST_CASE("BVH traversal on rays aimed at a mesh's shared edges and vertices", "[gpu][bvh][hard]") {
  test_gl();
  std::vector<glm::vec3> v;
  int N = 0;
  const Scene scene = mixed_scene(&v, &N);
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  std::uniform_int_distribution<int> cell(1, N - 1);
  std::vector<glm::vec4> in;
  for (int i = 0; i < 200000; ++i) {
    const int x = cell(rng), y = cell(rng);
    const glm::vec3 p = v[size_t(y * (N + 1) + x)];
    glm::vec3 q;
    switch (i % 4) {
      case 0: q = p; break;
      case 1: q = p + u01(rng) * (v[size_t(y * (N + 1) + x + 1)] - p); break;
      case 2: q = p + u01(rng) * (v[size_t((y + 1) * (N + 1) + x)] - p); break;
      default: q = p + u01(rng) * (v[size_t((y + 1) * (N + 1) + x + 1)] - p); break;
    }
    in.emplace_back(q, u01(rng));
  }
  compare(scene, in, 1, "rays at mesh edges");
}

TEST_CASE("the shader is the same for 100 and for 10,000 objects", "[shadergen][bvh]") {
  auto scene = [](int n) {
    Scene s;
    const int m = add_material(s, Material{});
    for (int i = 0; i < n; ++i) {
      if (i % 2) add_sphere(s, glm::vec3(float(i % 100), float(i / 100), 0.0f), 0.4f, m);
      else add_box(s, glm::vec3(float(i % 100), float(i / 100), 0.0f), glm::vec3(float(i % 100) + 0.5f, float(i / 100) + 0.5f, 0.5f), m);
    }
    return s;
  };
  // (Above kFlatMaxPrimitives both: a smaller scene gets the flat loop's program, accel_choice.h.)
  const Scene a = scene(100), b = scene(10000);
  const std::string ta = generate_integrator(Features::of(a)).text, tb = generate_integrator(Features::of(b)).text;
  std::printf("shader for 100 objects: %zu bytes; for 10,000: %zu bytes\n", ta.size(), tb.size());
  REQUIRE(!Features::of(a).flat);
  CHECK(ta == tb);
  const PackedScene pb = pack_scene(b);
  CHECK(pb.prims.count() == 10000);
  CHECK(pb.bvh_depth <= kBvhStackSize + 1);
}
