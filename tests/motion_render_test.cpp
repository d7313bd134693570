// Motion blur in images (issue 15), on kinds other than the sphere (camera_test.cpp has
// the moving sphere light):
//  - a moving box, disk and triangle light over a white plane: the plane's radiance,
//    tile by tile, against the closed form averaged over the shutter in this file
//    (Lambert's formula for the projected solid angle of a polygon; a box: its faces that
//    face the point; a disk: a polygon of 96 sides with the disk's area), independent of
//    the renderer, once with next-event estimation (mostly light sampling) and once
//    without (only paths that hit the light: its intersection); both must see the light
//    where it is at the path's time;
//  - a moving mesh instance: its image equals the mean of static renders (no motion
//    compiled in) with the mesh placed at kTimes midpoints of the shutter, tile by tile,
//    within 5 standard errors of the sample noise of both. The static renders draw the
//    same sample sequence (each restarts it), so their noise is correlated: the standard
//    error of their mean is bounded by the mean of their standard errors (the bound is
//    reached where the mesh is not seen), which is what the test takes.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <functional>

#include "gl_context.h"
#include "render/camera.h"
#include "scene/xml_loader.h"
#include "scene_builders.h"
#include "test_paths.h"

using namespace pt;

namespace {

using Polygon = std::vector<glm::dvec3>;

// Projected solid angle (about the normal +y) of a planar polygon seen from p, wholly
// above p's horizon: Lambert's formula, 1/2 |sum_i theta_i (n . unit(a_i x a_i+1))|.
double projected_solid_angle(glm::dvec3 p, const Polygon& v) {
  double sum = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    const glm::dvec3 a = glm::normalize(v[i] - p), b = glm::normalize(v[(i + 1) % v.size()] - p);
    const glm::dvec3 g = glm::cross(a, b);
    const double len = glm::length(g);
    if (len > 0) sum += std::atan2(len, glm::dot(a, b)) * g.y / len;
  }
  return 0.5 * std::abs(sum);
}

// The emitting polygons of a light at one time that face p (one-sided emitters: their
// front; a box: the faces p is outside of).
struct MovingLight {
  const char* name;
  Shape shape;
  glm::dvec3 center;  // at time 0, and a radius that holds it (to leave out pixels that see it)
  double radius;
  std::function<std::vector<Polygon>(glm::dvec3 p, glm::dvec3 offset)> facing;
};

MovingLight box_light(glm::vec3 lo, glm::vec3 hi, glm::vec3 v) {
  return {"box", Shape(Box{.min = lo, .max = hi, .velocity = v}, -1), glm::dvec3(lo + hi) * 0.5, glm::length(hi - lo) * 0.5,
          [lo, hi](glm::dvec3 p, glm::dvec3 off) {
            std::vector<Polygon> out;
            const glm::dvec3 l = glm::dvec3(lo) + off, h = glm::dvec3(hi) + off;
            for (int k = 0; k < 3; ++k)
              for (int side = 0; side < 2; ++side) {
                if (side == 0 ? !(p[k] < l[k]) : !(p[k] > h[k])) continue;
                const int i = (k + 1) % 3, j = (k + 2) % 3;
                Polygon f(4);
                for (int c = 0; c < 4; ++c) {
                  f[size_t(c)][k] = side ? h[k] : l[k];
                  f[size_t(c)][i] = (c == 1 || c == 2) ? h[i] : l[i];
                  f[size_t(c)][j] = c >= 2 ? h[j] : l[j];
                }
                out.push_back(f);
              }
            return out;
          }};
}

MovingLight disk_light(glm::vec3 c, float r, glm::vec3 v) {
  return {"disk", Shape(Disk{.center = c, .normal = glm::vec3(0, -1, 0), .radius = r, .velocity = v}, -1), glm::dvec3(c), r,
          [c, r](glm::dvec3 p, glm::dvec3 off) {
            // A regular 96-gon of the disk's area (radius scaled by sqrt(2 pi / (n sin(2 pi / n)))).
            constexpr int n = 96;
            const double rr = r * std::sqrt(2.0 * M_PI / (n * std::sin(2.0 * M_PI / n)));
            const glm::dvec3 cc = glm::dvec3(c) + off;
            if (!(p.y < cc.y)) return std::vector<Polygon>{};
            Polygon f;
            for (int i = 0; i < n; ++i) f.push_back(cc + rr * glm::dvec3(std::cos(2 * M_PI * i / n), 0.0, std::sin(2 * M_PI * i / n)));
            return std::vector<Polygon>{f};
          }};
}

MovingLight triangle_light(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 v) {
  const glm::vec3 m = (a + b + c) / 3.0f;
  const float r = std::max({glm::distance(a, m), glm::distance(b, m), glm::distance(c, m)});
  return {"triangle", Shape(Triangle{.v0 = a, .v1 = b, .v2 = c, .velocity = v}, -1), glm::dvec3(m), r,
          [a, b, c](glm::dvec3 p, glm::dvec3 off) {
            const Polygon f = {glm::dvec3(a) + off, glm::dvec3(b) + off, glm::dvec3(c) + off};
            const glm::dvec3 n = glm::cross(f[1] - f[0], f[2] - f[0]);  // emits on this side
            return glm::dot(n, p - f[0]) > 0 ? std::vector<Polygon>{f} : std::vector<Polygon>{};
          }};
}

}  // namespace

TEST_CASE("motion blur: moving box, disk and triangle lights over a plane give the time-averaged closed form", "[gpu][camera][motion]") {
  test_gl();
  const float L = 10.0f, shutter = 0.8f;
  const MovingLight lights[] = {
      box_light(glm::vec3(-1.45f, 1.6f, -0.25f), glm::vec3(-0.95f, 2.0f, 0.25f), glm::vec3(3.0f, 0.0f, 0.5f)),
      disk_light(glm::vec3(-1.0f, 1.8f, 0.2f), 0.35f, glm::vec3(2.5f, 0.2f, -0.6f)),
      // Front side (v1 - v0) x (v2 - v0) down, towards the plane.
      triangle_light(glm::vec3(-1.3f, 1.8f, -0.3f), glm::vec3(-0.7f, 1.8f, -0.4f), glm::vec3(-0.9f, 1.9f, 0.3f), glm::vec3(2.8f, 0.0f, 0.4f)),
  };
  for (const bool nee : {true, false})
  for (const MovingLight& light : lights) {
    INFO(light.name << (nee ? ", NEE" : ", no NEE"));
    Scene s = sphere_light_over_plane(glm::vec3(0.0f), 1.0f, L);  // the plane, camera, black sky
    s.shapes.back() = light.shape;
    s.shapes.back().material = int(s.materials.size()) - 1;  // the emitter
    s.camera.shutter = shutter;
    RenderSettings st;
    st.max_bounces = 1;
    st.nee = nee;
    const int W = 48, T = 8;
    const RenderResult r = render_scene(s, W, W, 512, st);
    CHECK(r.counters.bad_samples == 0);
    const CameraBasis cb = camera_basis(s.camera, 1.0f);
    const glm::dvec3 velocity = glm::dvec3(pt::velocity(light.shape.params));
    constexpr int kSub = 3, kTimes = 32;
    // Per pixel: the exact mean over the pixel and the shutter, or -1 for a pixel whose
    // rays (with a margin of a pixel) pass near the light at some time.
    std::vector<double> exact(size_t(W) * W, -1.0);
    for (int y = 0; y < W; ++y)
      for (int x = 0; x < W; ++x) {
        bool near = false;
        double e = 0;
        for (int a = -kSub; a < 2 * kSub && !near; ++a)
          for (int b = -kSub; b < 2 * kSub && !near; ++b) {
            const glm::vec2 ndc = (glm::vec2(x + (a + 0.5f) / kSub, y + (b + 0.5f) / kSub) / float(W)) * 2.0f - 1.0f;
            const glm::dvec3 d = glm::normalize(glm::dvec3(cb.forward + ndc.x * cb.right + ndc.y * cb.up)), o(cb.position);
            const bool inside = a >= 0 && a < kSub && b >= 0 && b < kSub;
            const glm::dvec3 p = o + (-o.y / d.y) * d;
            for (int k = 0; k < kTimes; ++k) {
              const glm::dvec3 off = velocity * (shutter * (k + 0.5) / kTimes);
              const glm::dvec3 oc = light.center + off - o;
              const double tc = glm::dot(oc, d);
              if (tc > 0 && glm::dot(oc, oc) - tc * tc < light.radius * light.radius * 1.1) near = true;
              if (inside)
                for (const Polygon& f : light.facing(p, off)) e += L / M_PI * projected_solid_angle(p, f) / (kSub * kSub * kTimes);
            }
          }
        if (!near) exact[size_t(y) * W + x] = e;
      }
    double worst = 0, sum = 0, sum_exact = 0, var_all = 0;
    int tiles = 0;
    for (int ty = 0; ty < W / T; ++ty)
      for (int tx = 0; tx < W / T; ++tx) {
        double m = 0, ex = 0, var = 0;
        int n = 0;
        for (int y = ty * T; y < (ty + 1) * T; ++y)
          for (int x = tx * T; x < (tx + 1) * T; ++x) {
            const double e = exact[size_t(y) * W + x];
            if (e < 0) continue;
            const float* px = &r.rgba[(size_t(y) * W + x) * 4];
            m += px[1];
            ex += e;
            var += double(px[3]) / r.spp;  // alpha: the luminance variance of the samples
            ++n;
          }
        if (n < T * T / 2) continue;
        ++tiles;
        sum += m, sum_exact += ex, var_all += var;
        const double z = (m - ex) / std::sqrt(var + 1e-12);
        if (std::abs(z) > std::abs(worst)) worst = z;
      }
    std::printf("motion blur, moving %s light over a plane (%s): %d tiles, worst z %+.2f; all: %.5f exact %.5f (%+.2f se)\n", light.name,
                nee ? "NEE" : "no NEE", tiles, worst, sum, sum_exact, (sum - sum_exact) / std::sqrt(var_all));
    CHECK(tiles >= 20);
    CHECK(std::abs(worst) < 5.0);
    CHECK(std::abs(sum - sum_exact) < 4.0 * std::sqrt(var_all) + 1e-4 * sum_exact);
  }
}

TEST_CASE("motion blur: a moving mesh's image is the mean of static renders at shutter times", "[gpu][camera][motion]") {
  test_gl();
  const Scene moving = load_scene_text(R"(<SceneLevel><Camera position="0 2.2 3.2" yaw="90" pitch="-30" shutter="0.75"/>
  <Light position="0.5 3 1.5" radius="0.4" intensity="25"/><Objects>
  <Plane normal="0 1 0" d="0"><Attenuate color="0.8 0.8 0.8"><Diffuse/></Attenuate></Plane>
  <Mesh generate="icosphere" level="2" scale="0.45" position="-0.75 0.5 0" velocity="2 0 0.3"><Attenuate color="0.9 0.5 0.2"><Diffuse/></Attenuate></Mesh>
</Objects></SceneLevel>)",
                                       repo_path("scenes") + "/x.xml");
  const int W = 40, T = 8, kSpp = 512, kTimes = 12, kStaticSpp = 96;
  RenderSettings st;
  st.max_bounces = 3;
  const RenderResult m = render_scene(moving, W, W, kSpp, st);
  CHECK(m.counters.bad_samples == 0);
  // The static renders: the mesh still, at the midpoints of kTimes equal parts of the shutter.
  constexpr int kTiles = 5;  // W / T
  std::vector<double> mean(size_t(W) * W, 0.0), tile_se(kTiles * kTiles, 0.0);
  RenderResult first{};
  for (int k = 0; k < kTimes; ++k) {
    Scene s = moving;
    REQUIRE(s.shapes.back().kind() == ShapeKind::Mesh);
    Mesh& mesh = *s.shapes.back().as<Mesh>();
    REQUIRE(mesh.velocity != glm::vec3(0.0f));
    mesh.transform[3] += glm::vec4(mesh.velocity * (moving.camera.shutter * (k + 0.5f) / kTimes), 0.0f);
    mesh.velocity = glm::vec3(0.0f);
    const RenderResult r = render_scene(s, W, W, kStaticSpp, st);
    if (k == 0) first = r;
    for (size_t i = 0; i < mean.size(); ++i) {
      const float* px = &r.rgba[i * 4];
      mean[i] += (0.2126 * px[0] + 0.7152 * px[1] + 0.0722 * px[2]) / kTimes;
    }
    for (int t = 0; t < kTiles * kTiles; ++t)
      tile_se[size_t(t)] += region_mean(r, t % kTiles * T, t / kTiles * T, (t % kTiles + 1) * T, (t / kTiles + 1) * T).se / kTimes;
  }
  double worst = 0, moved = 0;
  for (int ty = 0; ty < kTiles; ++ty)
    for (int tx = 0; tx < kTiles; ++tx) {
      const Estimate a = region_mean(m, tx * T, ty * T, (tx + 1) * T, (ty + 1) * T);
      const Estimate f = region_mean(first, tx * T, ty * T, (tx + 1) * T, (ty + 1) * T);
      double b = 0;
      for (int y = ty * T; y < (ty + 1) * T; ++y)
        for (int x = tx * T; x < (tx + 1) * T; ++x) b += mean[size_t(y) * W + x];
      b /= T * T;
      const double se_b = tile_se[size_t(ty * kTiles + tx)];
      const double z = (a.mean - b) / std::sqrt(a.se * a.se + se_b * se_b + 1e-12);
      if (std::abs(z) > std::abs(worst)) worst = z;
      // Against the mesh still at its first position: the motion must show.
      moved = std::max(moved, std::abs(a.mean - f.mean) / std::sqrt(a.se * a.se + f.se * f.se + 1e-12));
    }
  std::printf("motion blur, moving mesh vs the mean of %d static renders: worst tile z %+.2f (vs the first position alone: %.1f)\n", kTimes,
              worst, moved);
  CHECK(std::abs(worst) < 5.0);
  CHECK(moved > 10.0);
}
