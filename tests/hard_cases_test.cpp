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
#include "render/camera.h"
#include "render/packing.h"
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
      "  ShapeRec s; s.kind = SHAPE_BOX; s = with_box_rec(s, BoxRec(vec3(-1.0), vec3(1.0), vec3(0.0)));\n"
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
      "  for (int k = 0; k < NT; ++k) {\n    ShapeRec s; s.kind = SHAPE_TRIANGLE; s = with_triangle_rec(s, TriangleRec(V[3 * k], V[3 * k + 1], V[3 * k + 2], vec3(0.0)));\n"
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

// Non-finite samples (issue 15), each on the exact inputs that produced NaN or Inf before
// its fix (the fix is named in each case; docs/reliability.md, "Non-finite samples").

TEST_CASE("a sphere light seen from 1e4 to 1e12 radii away: its sample, density and MIS weight are finite", "[gpu][hard][nan]") {
  // A light seen from 1e4 to 1e12 of its radii away: the density reaches 1e24, and its
  // square overflowed in power_heuristic (inf / inf: NaN; fixed by the ratio form). The
  // H200's cases: a light of radius 8 and points of an infinite (Perlin) plane that a
  // nearly horizontal ray meets 1e10 away; and tiny lights (radius 1e-9) nearby.
  GlslKernel k(
      "uniform float u_r;\n"
      "vec4 kernel(vec4 x, int i) {\n"
      "  rng_init(uvec2(uint(i), 11u), 0u);\n"
      "  vec3 c = vec3(0.0, 2.0, 0.0);\n"
      "  ShapeRec s; s.kind = SHAPE_SPHERE; s = with_sphere_rec(s, SphereRec(c, u_r, vec3(0.0)));\n"
      "  vec3 p = c + u_r * pow(10.0, 4.0 + 8.0 * rand01()) * normalize(vec3(rand01() - 0.5, -rand01(), rand01() - 0.5));\n"
      "  vec3 wi; float pdf, dist;\n"
      "  vec2 u = vec2(rand01(), rand01());\n"
      "  if (!sample_light_sphere(s, p, u, wi, pdf, dist)) return vec4(-1.0);\n"
      "  float w = power_heuristic(pdf, wi.y * INV_PI) / pdf;\n"
      "  return vec4(pdf, dist, length(wi), w);\n}\n");
  for (float r : {8.0f, 1e-3f, 1e-6f, 1e-9f}) {
    k.program().use();
    glUniform1f(k.program().loc("u_r"), r);
    const std::vector<glm::vec4> out = k.run(4096);
    int bad = 0, none = 0;
    for (const glm::vec4& o : out) {
      if (o.x == -1.0f) { ++none; continue; }
      if (!(std::isfinite(o.x) && std::isfinite(o.y) && std::isfinite(o.z) && std::isfinite(o.w) && o.x > 0.0f)) {
        if (bad++ < 3) std::printf("r %g: pdf %g dist %g |wi| %g w/pdf %g\n", double(r), double(o.x), double(o.y), double(o.z), double(o.w));
      }
    }
    std::printf("sphere light of radius %g: %d of 4096 samples non-finite, %d refused\n", double(r), bad, none);
    CHECK(bad == 0);
  }
}

namespace {

// The path tracer's first hit and its next-event estimate (integrator.glsl's steps) for
// camera rays of scene s: per ray (L from NEE, pdf of the light sample, MIS weight / pdf).
std::vector<glm::vec4> first_bounce_nee(const Scene& s, int w, int h, int spp) {
  const CameraBasis cb = camera_basis(s.camera, float(w) / float(h));
  GlslKernel k(
      "uniform vec3 u_cam_pos; uniform vec3 u_cam_fwd; uniform vec3 u_cam_right; uniform vec3 u_cam_up;\n"
      "uniform vec2 u_size; uniform int u_spp;\n"
      "#include \"surface.glsl\"\n"
      "vec4 kernel(vec4 x, int i) {\n"
      "  int w = int(u_size.x), px = i / u_spp;\n"
      "  rng_init(uvec2(uint(px), 3u), uint(i % u_spp));\n"
      "  vec2 ndc = (vec2(float(px % w), float(px / w)) + vec2(rand01(), rand01())) / u_size * 2.0 - 1.0;\n"
      "  Ray r = Ray(u_cam_pos, normalize(u_cam_fwd + ndc.x * u_cam_right + ndc.y * u_cam_up));\n"
      "  Hit h = scene_intersect(r);\n"
      "  if (h.id < 0) return vec4(0.0);\n"
      "  Surface sf = surface_hit(r, h);\n"
      "  surface_resolve(sf, r, h, rand01());\n"
      "  LightSample ls;\n"
      "  if (!light_sample(h.p, vec3(rand01(), rand01(), rand01()), ls)) return vec4(0.0);\n"
      "  float pdf_b;\n"
      "  vec3 wl = to_local(sf.fr, ls.wi);\n"
      "  vec3 f = material_eval(sf.m, sf.wo, wl, sf.entering, pdf_b);\n"
      "  if (max3(f) <= 0.0) return vec4(0.0, ls.pdf, 0.0, 0.0);\n"
      "  float wp = power_heuristic(ls.pdf, pdf_b) / ls.pdf;\n"
      "  vec3 L = f * ls.radiance * wp;\n"
      "  return vec4(max3(L), ls.pdf, wp, pdf_b);\n}\n",
      Features::of(s));
  k.bind_scene(s, pack_scene(s));
  k.program().set("u_cam_pos", cb.position);
  k.program().set("u_cam_fwd", cb.forward);
  k.program().set("u_cam_right", cb.right);
  k.program().set("u_cam_up", cb.up);
  k.program().set("u_size", glm::vec2(float(w), float(h)));
  k.program().set("u_spp", spp);
  k.program().set("u_dot_weight", 1);
  return k.run(w * h * spp);
}

int count_non_finite(const std::vector<glm::vec4>& v, const char* what) {
  int bad = 0;
  for (const glm::vec4& o : v)
    if (!(std::isfinite(o.x) && std::isfinite(o.y) && std::isfinite(o.z) && std::isfinite(o.w)) && bad++ < 3)
      std::printf("%s: L %g pdf %g w/pdf %g pdf_b %g\n", what, double(o.x), double(o.y), double(o.z), double(o.w));
  return bad;
}

}  // namespace

// The H200's case (issue 15, generated scene 14 here): a light of radius 1e-6 or 1e-9 over a
// floor, the next-event estimate of the first hit as the integrator computes it.
TEST_CASE("tiny lights over a floor: every next-event estimate is finite", "[gpu][hard][nan]") {
  for (const char* r : {"1e-3", "1e-6", "1e-9"}) {
    const Scene s = load_scene_text(std::string("<SceneLevel><Camera position=\"0 2 6\" yaw=\"90\" pitch=\"-15\"/>"
                                                "<Light position=\"0 2 0\" radius=\"") + r + "\" intensity=\"1e9\"/>"
                                                "<Objects><Plane normal=\"0 1 0\" d=\"0\"><Diffuse/></Plane></Objects></SceneLevel>",
                                    "tiny.xml");
    const int bad = count_non_finite(first_bounce_nee(s, 32, 24, 16), r);
    std::printf("light of radius %s over a floor: %d of %d next-event estimates non-finite\n", r, bad, 32 * 24 * 16);
    CHECK(bad == 0);
  }
}

TEST_CASE("PhongSpecular of exponent 0: the lobe is finite where wi is 90 degrees or more from the mirror direction", "[gpu][hard][nan]") {
  // cos^0 at a cosine of 0 was pow(0, 0), which GLSL leaves undefined (pow is commonly
  // exp2(y log2 x): 0 * -inf); the lobe lives where the cosine is positive: 0 outside,
  // 1 / (2 pi) inside. Textured's Phong lobe is this function. llvmpipe happens to give
  // pow(0, 0) = 0, so here this passed before the fix too; it prints the driver's value
  // (the last column), and fails on a driver that gives NaN or 1 without the fix.
  GlslKernel k(glsl_material(PhongSpecular{.n = 0.0f}) +
               "vec4 kernel(vec4 x, int i) {\n"
               "  float a = 1.0471976;  // wo 60 degrees from the normal\n"
               "  vec3 wo = vec3(sin(a), 0.0, cos(a));\n"
               "  vec3 wi = normalize(x.xyz);\n"
               "  float pdf;\n  vec3 f = eval_phong_specular(make_material(), wo, wi, true, pdf);\n"
               "  return vec4(f.x, pdf, dot(wi, vec3(-wo.x, -wo.y, wo.z)), pow(max(dot(wi, vec3(-wo.x, -wo.y, wo.z)), 0.0), 0.0));\n}\n");
  // wi about 90 degrees from the mirror direction; beyond it; inside the lobe.
  const std::vector<glm::vec4> out = k.run({{0.5f, 0.0f, 0.8660254f, 0}, {0.5f, 0.3f, 0.8660254f, 0}, {0.9f, 0.0f, 0.436f, 0},
                                            {-0.8f, 0.1f, 0.6f, 0}, {0.0f, 0.0f, 1.0f, 0}});
  for (const glm::vec4& o : out) {
    std::printf("phong n=0: f %g pdf %g cos to the mirror %g, pow(max(cos, 0), 0) here %g\n", double(o.x), double(o.y), double(o.z), double(o.w));
    CHECK(std::isfinite(o.x));
    CHECK(std::isfinite(o.y));
    if (o.z <= 0.0f) CHECK(o.y == 0.0f);
    if (o.z > 1e-3f) CHECK(o.y == Approx(0.5 / 3.14159265).epsilon(1e-5));
  }
}

TEST_CASE("mesh barycentrics of a tiny triangle are finite", "[gpu][hard][nan]") {
  // A mesh scaled to 1e-3 with a sliver of 1e-7 has edges of 1e-10: |n|^2 of its normal
  // (n = e1 x e2) was 1e-40, below float's normal range, and 1 / |n|^2 was inf, so the
  // barycentrics (and the uv and normal interpolated with them) were NaN.
  GlslKernel k(
      "vec4 kernel(vec4 x, int i) {\n"
      "  PrimRec t;\n"
      "  t.v0 = x.w * vec3(1.0, 2.0, 3.0);\n"
      "  t.v1 = t.v0 + x.w * vec3(1.0, 0.0, 0.0);\n"
      "  t.v2 = t.v0 + x.w * vec3(0.3, 1.0, 0.2);\n"
      "  vec3 p = (t.v0 + t.v1 + t.v2) / 3.0;\n"
      "  vec3 b = mesh_barycentrics(t, p);\n"
      "  return vec4(b, b.x + b.y + b.z);\n}\n");
  const std::vector<glm::vec4> out = k.run({{0, 0, 0, 1.0f}, {0, 0, 0, 1e-5f}, {0, 0, 0, 1e-8f}, {0, 0, 0, 1e-10f}, {0, 0, 0, 1e-15f}});
  for (const glm::vec4& o : out) {
    std::printf("tiny triangle barycentrics: %g %g %g (sum %g)\n", double(o.x), double(o.y), double(o.z), double(o.w));
    CHECK(std::isfinite(o.x + o.y + o.z));
    CHECK(o.w == Approx(1.0).epsilon(1e-4));
    CHECK(o.x == Approx(1.0 / 3.0).epsilon(1e-3));
  }
}

TEST_CASE("a lone triangle's barycentrics (its uv) are finite when it is tiny", "[gpu][hard][nan]") {
  // The Gram determinant d00 d11 - d01^2 is of the fourth power of the size: below edges of
  // about 1e-10 it left float's normal range and v, w were x / 0 (NaN uv, NaN texture).
  GlslKernel k(
      "vec4 kernel(vec4 x, int i) {\n"
      "  ShapeRec s; s.kind = SHAPE_TRIANGLE;\n"
      "  vec3 v0 = x.w * vec3(1.0, 2.0, 3.0), v1 = v0 + x.w * vec3(1.0, 0.0, 0.0), v2 = v0 + x.w * vec3(0.3, 1.0, 0.2);\n"
      "  s = with_triangle_rec(s, TriangleRec(v0, v1, v2, vec3(0.0)));\n"
      "  vec3 b = barycentric_triangle(s, (v0 + v1 + v2) / 3.0);\n"
      "  return vec4(b, b.x + b.y + b.z);\n}\n");
  const std::vector<glm::vec4> out = k.run({{0, 0, 0, 1.0f}, {0, 0, 0, 1e-5f}, {0, 0, 0, 1e-9f}, {0, 0, 0, 1e-11f}, {0, 0, 0, 1e-15f}});
  for (const glm::vec4& o : out) {
    std::printf("tiny lone triangle barycentrics: %g %g %g (sum %g)\n", double(o.x), double(o.y), double(o.z), double(o.w));
    CHECK(std::isfinite(o.x + o.y + o.z));
    CHECK(o.w == Approx(1.0).epsilon(1e-4));
    CHECK(o.x == Approx(1.0 / 3.0).epsilon(1e-3));
  }
}
