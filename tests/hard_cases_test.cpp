// Numerical hard cases, as tests: rays in box faces and slab planes, rays aimed exactly
// at shared triangle edges and vertices (no cracks), the Cornell box far from the origin
// and at extreme scales (the same image within noise), and MSE falling as 1/spp.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "gl_context.h"
#include "glsl_harness.h"
#include "scene/xml_loader.h"
#include "scene_builders.h"
#include "test_paths.h"

using namespace pt;

namespace {

std::string vec3_glsl(glm::vec3 v) {
  char b[128];
  std::snprintf(b, sizeof b, "vec3(%.9g, %.9g, %.9g)", double(v.x), double(v.y), double(v.z));
  return b;
}

// Returns (t or -1, normal.xyz) of the unit box [-1,1]^3 for ray (x.xyz, dir from x.w index).
GlslKernel box_kernel() {
  return GlslKernel(
      "uniform vec3 u_dir[8];\n"
      "vec4 kernel(vec4 x, int i) {\n"
      "  ShapeRec s; s.kind = SHAPE_BOX; s = with_box_rec(s, BoxRec(vec3(-1.0), vec3(1.0)));\n"
      "  Hit h = no_hit();\n"
      "  Ray r = Ray(x.xyz, u_dir[int(x.w)]);\n  intersect_box(s, 0, r, prepare_box(r), h);\n"
      "  return h.id < 0 ? vec4(-1.0, 0.0, 0.0, 0.0) : vec4(h.t, h.n);\n}\n");
}

}  // namespace

TEST_CASE("box: rays lying in faces and along slab planes", "[gpu][hard]") {
  GlslKernel k = box_kernel();
  const glm::vec3 dirs[8] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, 0, -1},
                             glm::normalize(glm::vec3(1, 1, 0)), glm::normalize(glm::vec3(1, 0, 1)), {0, -1, 0}, {0, 0, 1}};
  k.program().use();
  glUniform3fv(k.program().loc("u_dir"), 8, &dirs[0].x);
  struct C {
    glm::vec4 in;  // origin, direction index
    float t;       // expected t, -1 for a miss
  };
  // A ray lying in a face plane of the closed box touches the face: it hits where it
  // enters the box's extent, whichever face (min or max) it lies in.
  const std::vector<C> cases = {
      {{-5, 1, 0, 0}, 4},     // in the top face plane (y = max)
      {{-5, -1, 0, 0}, 4},    // in the bottom face plane (y = min)
      {{-5, 0, 1, 0}, 4},     // in the z = max plane
      {{5, 1, -1, 1}, 4},     // along an edge (y = max, z = min), going -x
      {{0, -5, 1, 2}, 4},     // along x = 0 / z = max, going +y
      {{-5, 1.5f, 0, 0}, -1}, // parallel, outside the slab
      {{-3, -2, 0, 4}, 2 * std::sqrt(2.0f)},  // diagonal through the edge (x=-1,y=0)? enters at x=-1, y=0
      {{0, 0, 0, 0}, 1},      // from the centre, out through +x
      {{1, 0, 0, 1}, 2},      // on the +x face, going in: exits at x = -1
      {{-1, -1, -1, 5}, std::sqrt(2.0f) * 2},  // from a corner along the face diagonal (y = -1 plane)
  };
  std::vector<glm::vec4> in;
  for (const C& c : cases) in.push_back(c.in);
  const std::vector<glm::vec4> out = k.run(in);
  for (size_t i = 0; i < cases.size(); ++i) {
    INFO("case " << i << ": t = " << out[i].x << ", n = " << out[i].y << " " << out[i].z << " " << out[i].w);
    CHECK(std::isfinite(out[i].x));
    if (cases[i].t < 0) {
      CHECK(out[i].x == -1.0f);
    } else {
      CHECK(out[i].x == Approx(cases[i].t).epsilon(1e-5));
      CHECK(std::abs(glm::length(glm::vec3(out[i].y, out[i].z, out[i].w)) - 1.0f) < 1e-5f);
    }
  }
}

TEST_CASE("triangles: rays aimed exactly at shared edges and vertices find no crack", "[gpu][hard]") {
  // A creased 6x6 grid of 72 triangles (slopes below 0.4); 2*10^5 rays, each aimed exactly
  // (in float) at a point on a shared edge or at a shared vertex, from a random point
  // above it within 45 degrees of the vertical. Rays steeper than every facet cannot
  // meet a silhouette (where two facets face opposite ways along the ray and a ray may
  // rightly pass between them), so every miss would be a crack.
  const int N = 6;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
  std::vector<glm::vec3> v((N + 1) * (N + 1));
  for (int y = 0; y <= N; ++y)
      for (int x = 0; x <= N; ++x)
      v[size_t(y * (N + 1) + x)] = glm::vec3(x + 0.7f * jitter(rng), y + 0.7f * jitter(rng), jitter(rng) / 3.0f);
  std::vector<glm::ivec3> tris;
  for (int y = 0; y < N; ++y)
    for (int x = 0; x < N; ++x) {
      const int a = y * (N + 1) + x, b = a + 1, c = a + N + 1, d = c + 1;
      tris.push_back({a, b, d});
      tris.push_back({a, d, c});
    }
  std::string body = "const int NT = " + std::to_string(tris.size()) + ";\nconst vec3 V[" + std::to_string(tris.size() * 3) + "] = vec3[](";
  for (size_t i = 0; i < tris.size(); ++i)
    for (int j = 0; j < 3; ++j) body += (i || j ? ", " : "") + vec3_glsl(v[size_t(tris[i][j])]);
  body +=
      ");\nvec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 5u), 0u);\n"
      "  float hgt = 1.0 + 3.0 * rand01(), rad = hgt * sqrt(rand01()), phi = TWO_PI * rand01();\n"
      "  vec3 o = x.xyz + vec3(rad * cos(phi), rad * sin(phi), hgt);\n"
      "  Ray r = Ray(o, normalize(x.xyz - o));\n  Hit h = no_hit();\n"
      "  for (int k = 0; k < NT; ++k) {\n    ShapeRec s; s.kind = SHAPE_TRIANGLE; s = with_triangle_rec(s, TriangleRec(V[3 * k], V[3 * k + 1], V[3 * k + 2]));\n"
      "    intersect_triangle(s, k, r, prepare_triangle(r), h);\n  }\n  return vec4(float(h.id), h.t, 0.0, 0.0);\n}\n";
  GlslKernel k(body);
  // Targets: points on interior edges (shared by two triangles) and interior vertices.
  std::vector<glm::vec4> targets;
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  std::uniform_int_distribution<int> cell(1, N - 1);
  for (int i = 0; i < 200000; ++i) {
    const int x = cell(rng), y = cell(rng);
    const glm::vec3 p = v[size_t(y * (N + 1) + x)];
    glm::vec3 q;
    switch (i % 4) {
      case 0: q = p; break;                                                        // a vertex
      case 1: q = p + u01(rng) * (v[size_t(y * (N + 1) + x + 1)] - p); break;      // a horizontal edge
      case 2: q = p + u01(rng) * (v[size_t((y + 1) * (N + 1) + x)] - p); break;    // a vertical edge
      default: q = p + u01(rng) * (v[size_t((y + 1) * (N + 1) + x + 1)] - p); break;  // a diagonal
    }
    targets.emplace_back(q, 0.0f);
  }
  int misses = 0, by_kind[4] = {0, 0, 0, 0};
  const std::vector<glm::vec4> hits = k.run(targets);
  for (size_t i = 0; i < hits.size(); ++i)
    if (hits[i].x < 0.0f) ++misses, ++by_kind[i % 4];
  std::printf("misses by target: vertex %d, horizontal edge %d, vertical edge %d, diagonal %d\n", by_kind[0], by_kind[1],
              by_kind[2], by_kind[3]);
  std::printf("watertight: %d of %zu rays aimed at shared edges/vertices missed\n", misses, targets.size());
  CHECK(misses == 0);
}

namespace {

Scene transformed(Scene s, float scale, glm::vec3 offset) {
  auto pt = [&](glm::vec3 p) { return p * scale + offset; };
  for (Shape& sh : s.shapes) {
    if (Plane* p = sh.as<Plane>()) p->d = p->d * scale + glm::dot(p->normal, offset);
    if (Sphere* p = sh.as<Sphere>()) p->center = pt(p->center), p->radius *= scale;
    if (Box* p = sh.as<Box>()) p->min = pt(p->min), p->max = pt(p->max);
    if (Triangle* p = sh.as<Triangle>()) p->v0 = pt(p->v0), p->v1 = pt(p->v1), p->v2 = pt(p->v2);
  }
  for (Light& l : s.lights) {
    l.position = pt(l.position);
    l.radius *= scale;
  }
  s.camera.position = pt(s.camera.position);
  return s;
}

}  // namespace

TEST_CASE("Cornell box far from the origin and at extreme scales: same image within noise", "[gpu][hard]") {
  test_gl();
  const Scene base = load_scene_file(repo_path("scenes/reference/scene2.xml"));
  const int W = 48, T = 8, spp = 128;
  auto tiles = [&](const RenderResult& r) {
    std::vector<Estimate> e;
    for (int ty = 0; ty < W / T; ++ty)
      for (int tx = 0; tx < W / T; ++tx) e.push_back(region_mean(r, tx * T, ty * T, (tx + 1) * T, (ty + 1) * T));
    return e;
  };
  const RenderResult ref = render_scene(base, W, W, spp);
  const std::vector<Estimate> a = tiles(ref);
  struct C {
    const char* name;
    float scale;
    glm::vec3 offset;
  };
  for (const C& c : {C{"translated by 1e4", 1.0f, glm::vec3(1e4f, -1e4f, 1e4f)}, C{"translated by 1e5", 1.0f, glm::vec3(1e5f, 1e5f, -1e5f)},
                     C{"scaled by 1e-3", 1e-3f, glm::vec3(0.0f)}, C{"scaled by 1e5", 1e5f, glm::vec3(0.0f)}}) {
    const RenderResult r = render_scene(transformed(base, c.scale, c.offset), W, W, spp);
    CHECK(r.counters.bad_samples == 0);
    const std::vector<Estimate> b = tiles(r);
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i)
      worst = std::max(worst, std::abs(a[i].mean - b[i].mean) / std::sqrt(a[i].se * a[i].se + b[i].se * b[i].se));
    std::printf("Cornell box %-18s worst tile |z| = %.2f over %zu tiles\n", c.name, worst, a.size());
    INFO(c.name << ": worst |z| " << worst);
    CHECK(worst < 5.0);
  }
}

TEST_CASE("unbiased and converging: log MSE against log spp has slope -1", "[gpu][hard]") {
  test_gl();
  // The emitting closed room has a known answer, Le / (1 - rho) at unlimited bounces.
  // Independent samples must give MSE ~ 1/spp exactly (slope -1: no bias floor, no
  // correlation); scrambled Sobol points may do better (quasi-Monte Carlo), never worse.
  Material wall;
  wall.tint = glm::vec3(0.5f);
  wall.emission = glm::vec3(1.0f);
  const Scene s = closed_room(wall);
  const double exact = 1.0 / (1.0 - 0.5);
  for (int sampler : {0, 3, 1 << 20}) {
    RenderSettings st;
    st.max_bounces = 64;
    st.sampler = sampler;
    std::vector<double> lx, ly;
    for (int spp : {2, 8, 32, 128}) {
      const RenderResult r = render_scene(s, 32, 32, spp, st);
      double mse = 0;
      for (size_t i = 0; i < r.rgba.size(); i += 4) mse += (r.rgba[i + 1] - exact) * (r.rgba[i + 1] - exact);
      mse /= double(r.rgba.size() / 4);
      lx.push_back(std::log(double(spp)));
      ly.push_back(std::log(mse));
    }
    double mx = 0, my = 0;
    for (size_t i = 0; i < lx.size(); ++i) mx += lx[i] / double(lx.size()), my += ly[i] / double(ly.size());
    double sxy = 0, sxx = 0;
    for (size_t i = 0; i < lx.size(); ++i) sxy += (lx[i] - mx) * (ly[i] - my), sxx += (lx[i] - mx) * (lx[i] - mx);
    const double slope = sxy / sxx;
    std::printf("log MSE vs log spp, %d Sobol blocks: slope %.3f\n", sampler, slope);
    if (sampler == 0) {
      CHECK(std::abs(slope + 1.0) < 0.1);
    } else {
      CHECK(slope < -0.9);
    }
  }
}
