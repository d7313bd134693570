// Tests that loop over every shape kind (shapes/kinds.h), each on its stem's kExample:
//  - its CPU intersection twin (shapes/<kind>.h, what picking casts) against the
//    production GLSL (scene_intersect over the packed scene: the shape record, the BVH,
//    <kind>.glsl) on random rays and on grazing rays (nearly tangent to the surface at a
//    point of it);
//  - its bounds (the BVH's box, shapes/shape.h) contain every point its intersection
//    returns, on the CPU and on the GPU; a moving sphere's over the shutter's times;
//  - its position and move agree (the panel's position field).
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "app/picking.h"
#include "app/selection.h"
#include "gl_context.h"
#include "glsl_harness.h"
#include "render/packing.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

// The kind's example inside a scene, with a Diffuse material inside it.
Scene example_scene(int kind) {
  std::string e = kShapeTraits[kind].example;
  REQUIRE(e.substr(e.size() - 2) == "/>");
  e = e.substr(0, e.size() - 2) + "><Diffuse/></" + kShapeKinds[kind].xml + ">";
  Scene s = load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects>" + e + "</Objects></SceneLevel>", repo_path("scenes") + "/x.xml");
  REQUIRE(s.shapes.size() == 1);
  REQUIRE(int(s.shapes[0].kind()) == kind);
  REQUIRE(int(s.shapes[0].params.index()) == kind);
  return s;
}

glm::vec3 unit(std::mt19937& rng) {
  std::normal_distribution<float> g;
  for (;;) {
    const glm::vec3 v(g(rng), g(rng), g(rng));
    if (glm::dot(v, v) > 1e-6f) return glm::normalize(v);
  }
}

// Random rays from a sphere of radius 3 towards points near the shape, and grazing rays:
// from a point p the random rays hit with normal n, along a tangent tilted by +-1e-3 rad,
// starting 2 units before p.
std::vector<Ray> rays_for(const Scene& s, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<Ray> rays;
  for (int i = 0; i < 1024; ++i) {
    const glm::vec3 o = 3.0f * unit(rng), target(u(rng), u(rng), u(rng));
    rays.push_back({o, glm::normalize(target - o)});
  }
  const size_t random = rays.size();
  for (size_t i = 0; i < random && rays.size() < random + 1024; ++i) {
    const Hit h = intersect_scene(s, rays[i]);
    if (h.id < 0) continue;
    glm::vec3 t = glm::cross(h.n, unit(rng));
    if (glm::dot(t, t) < 1e-6f) continue;
    t = glm::normalize(t);
    for (const float tilt : {1e-3f, -1e-3f}) {
      const glm::vec3 d = glm::normalize(t + tilt * h.n);
      rays.push_back({h.p - 2.0f * d, d});
    }
  }
  return rays;
}

bool within(glm::vec3 p, const ShapeBounds& b, float eps) {
  return glm::all(glm::greaterThanEqual(p, b.lo - eps)) && glm::all(glm::lessThanEqual(p, b.hi + eps));
}

}  // namespace

TEST_CASE("every shape kind's CPU twin agrees with its GLSL on random and grazing rays", "[gpu][shapes]") {
  test_gl();
  // Each kind through the BVH and through the flat loop (accel_choice.h: a one-shape scene
  // would otherwise be flat only, and the BVH's boxes are what grazing rays test).
  for (int run = 0; run < 2 * kNumShapeKinds; ++run) {
    const int kind = run / 2;
    Features f;
    INFO(kShapeKinds[kind].xml << (run % 2 ? ", flat" : ", bvh"));
    const Scene s = example_scene(kind);
    f = Features::of(s);
    f.flat = run % 2 == 1;
    const std::vector<Ray> rays = rays_for(s, 17u + uint32_t(kind));
    REQUIRE(rays.size() > 1024 + 200);  // every example is hit by enough rays to graze it
    GlslKernel k(
        "uniform sampler2D u_dirs;\n"
        "vec4 kernel(vec4 x, int i) {\n"
        "  vec3 d = texelFetch(u_dirs, ivec2(i % 4096, i / 4096), 0).xyz;\n"
        "  Hit h = scene_intersect(Ray(x.xyz, d));\n"
        "  return vec4(float(h.id), h.t, 0.0, 0.0);\n}\n",
        f);
    k.bind_scene(s, pack_scene(s));
    std::vector<glm::vec4> origins, dirs(size_t(4096) * ((rays.size() + 4095) / 4096), glm::vec4(0.0f));
    for (size_t i = 0; i < rays.size(); ++i) origins.emplace_back(rays[i].o, 0.0f), dirs[i] = glm::vec4(rays[i].d, 0.0f);
    const Texture dir_tex(4096, int(dirs.size() / 4096), GL_RGBA32F, &dirs[0].x);
    k.bind("u_dirs", dir_tex);
    const std::vector<glm::vec4> gpu = k.run(origins);
    const ShapeBounds b = bounds(s.shapes[0].params, ShapeContext{&s.meshes, 1.0f});
    const size_t random = 1024;
    int differ[2] = {0, 0}, hits[2] = {0, 0};
    for (size_t i = 0; i < rays.size(); ++i) {
      const int set = i < random ? 0 : 1;
      const Hit h = intersect_scene(s, rays[i]);
      const glm::vec4 g = gpu[i];
      hits[set] += h.id >= 0;
      if (h.id >= 0) CHECK(within(h.p, b, 1e-5f));  // the BVH's box holds every hit
      if (g.x >= 0.0f) CHECK(within(rays[i].o + g.y * rays[i].d, b, 1e-4f));
      if (int(g.x) == h.id) {
        // The same distance, or (a grazing ray: t is ill-conditioned) the same distance from
        // the surface: |dt cos| is the offset across it.
        const float dt = std::abs(g.y - h.t), m = std::max(1.0f, h.t);
        if (h.id >= 0) CHECK((dt <= 1e-5f * m || dt * std::abs(glm::dot(h.n, rays[i].d)) <= 1e-6f * m));
        continue;
      }
      ++differ[set];  // a hit on one side only: the ray is within rounding of an edge
      if (set == 0) WARN(kShapeKinds[kind].xml << " ray " << i << ": gpu " << g.x << " t " << g.y << ", cpu " << h.id << " t " << h.t);
    }
    INFO("random rays: " << hits[0] << " hits; grazing: " << hits[1] << " hits, " << differ[1] << " of " << rays.size() - random << " differ");
    CHECK(hits[0] > 100);
    CHECK(differ[0] <= 2);  // 0.2% of the random rays, as picking allows
    CHECK(differ[1] * 50 <= int(rays.size() - random));  // at most 2% of the grazing rays
  }
}

TEST_CASE("every shape kind's bounds hold its hits, and a moving sphere's its hits over the shutter", "[shapes]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int kind = 0; kind < kNumShapeKinds; ++kind) {
    INFO(kShapeKinds[kind].xml);
    Scene s = example_scene(kind);
    int hits = 0;
    const std::vector<Ray> rays = rays_for(s, 3u + uint32_t(kind));
    for (const Ray& r : rays) {
      const Hit h = intersect_scene(s, r);
      if (h.id < 0) continue;
      ++hits;
      CHECK(within(h.p, bounds(s.shapes[0].params, ShapeContext{&s.meshes, 1.0f}), 1e-5f));
    }
    CHECK(hits > 100);
    // The panel's position: moved towards p + d (a plane moves only along its normal), the
    // shape moves by the change of its position: the random rays moved by it hit at the
    // same distance.
    const Scene before = s;
    const glm::vec3 p = shape_position(s.shapes[0]), d(0.25f, -0.5f, 0.125f);
    move_shape(s, 0, p + d);
    const glm::vec3 moved = shape_position(s.shapes[0]) - p;
    CHECK(glm::length(moved) > 0.1f);
    CHECK(glm::distance(shape_position(s.shapes[0]), p + moved) < 1e-5f);
    for (size_t i = 0; i < 1024; ++i) {
      const Hit h0 = intersect_scene(before, rays[i]), h1 = intersect_scene(s, {rays[i].o + moved, rays[i].d});
      CHECK(h0.id == h1.id);
      if (h0.id >= 0 && h1.id >= 0) CHECK(std::abs(h0.t - h1.t) <= 1e-4f * std::max(1.0f, h0.t));
    }
  }
  // A moving sphere, seen at times in [0, motion_bound]: the swept box holds each.
  const Sphere moving{.center = glm::vec3(0.5f, 0.0f, -0.3f), .radius = 0.4f, .velocity = glm::vec3(1.0f, 0.5f, -2.0f)};
  const ShapeContext ctx{nullptr, 1.5f};
  const ShapeBounds swept = moving.bounds(ctx);
  int hits = 0;
  for (int i = 0; i < 4000; ++i) {
    Sphere at = moving;  // the shutter sees it at some time in [0, motion_bound]
    at.center += moving.velocity * (ctx.motion_bound * u(rng));
    const glm::vec3 o = 6.0f * unit(rng);
    const Ray r{o, glm::normalize(at.center + 0.5f * unit(rng) - o)};
    Hit h;
    intersect_sphere(at, 0, r, h);
    if (h.id < 0) continue;
    ++hits;
    CHECK(within(h.p, swept, 1e-5f));
  }
  CHECK(hits > 1000);
}

TEST_CASE("the panel's shape fields come from the kind's stem", "[shapes]") {
  struct Recorder {
    std::vector<std::string> labels;
    float set_to = -1.0f;
    bool drag(const char* label, float& v, float, float, float) {
      labels.push_back(label);
      if (set_to < 0.0f) return false;
      v = set_to;
      return true;
    }
  };
  for (int kind = 0; kind < kNumShapeKinds; ++kind) {
    Scene s = example_scene(kind);
    Recorder r;
    CHECK_FALSE(edit_shape(s, 0, r));
    INFO(kShapeKinds[kind].xml);
    const bool has_radius = ShapeKind(kind) == ShapeKind::Sphere || ShapeKind(kind) == ShapeKind::Disk;
    CHECK(r.labels == (has_radius ? std::vector<std::string>{"radius"} : std::vector<std::string>{}));
  }
  // A light's sphere: the radius reaches its Light; a radius <= 0 is refused.
  Scene s = load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Light position=\"1 2 3\" radius=\"0.5\"/></SceneLevel>", "x.xml");
  Recorder r;
  r.set_to = 2.0f;
  CHECK(edit_shape(s, 0, r));
  CHECK(s.lights[0].radius == 2.0f);
  CHECK(s.shapes[0].as<Sphere>()->radius == 2.0f);
  r.set_to = 0.0f;
  CHECK_FALSE(edit_shape(s, 0, r));
  CHECK(s.shapes[0].as<Sphere>()->radius == 2.0f);
}
