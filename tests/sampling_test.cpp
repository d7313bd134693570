// Chi-square tests of every direction sampler against its own density, on the production
// GLSL through the harness (Mitsuba's and pbrt's method): 10^6 samples are binned into a
// (cos theta, phi) histogram over the whole sphere; each cell's expected count integrates
// the density (5x5 midpoint rule, on the GPU) over the cell; cells expecting fewer than 5
// are pooled; the test passes when p >= alpha, with alpha = 0.01 Sidak-corrected for
// kChi2Tests tests. Incident directions include grazing ones (cos theta = 1e-3).
#include <catch2/catch.hpp>

#include <limits>
#include <set>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>

#include "render/environment.h"

#include "gl_context.h"
#include "direction_chi2.h"
#include "glsl_harness.h"
#include "stats.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

constexpr int kChi2Tests = 30 + 2 * kNumMaterialKinds;  // every direction_chi2 call below (at most)

// A conductor of n = 0.2, k = 3 with the given glossiness and sampling strategy.
Material metal(float glossiness, float sampling) {
  return Metal{.iorComplex = glm::vec2(0.2f, 3.0f), .glossiness = glossiness, .montecarlo = sampling};
}

const double kSamplingAlpha = sidak_alpha(0.01, kChi2Tests);

}  // namespace

TEST_CASE("chi-square: diffuse, cosine-weighted and uniform", "[gpu][sampling]") {
  for (int dot : {1, 0})
    for (double c : {1.0, 0.5, 1e-3}) {
      DirectionCase dc{glsl_material(Diffuse{}) + incident(c) + kBsdfPdfHelper, kBsdfSample, kBsdfDensity, dot};
      const std::string name = std::string("diffuse ") + (dot ? "cosine" : "uniform") + " cos_o=" + std::to_string(c);
      CHECK(direction_chi2(dc, name.c_str()).p_value >= kSamplingAlpha);
    }
}

TEST_CASE("chi-square: GGX metal, visible-normal and cosine sampling", "[gpu][sampling]") {
  struct C {
    float glossiness, sampling;
    double cos_o;
  };
  for (const C& c : {C{0.5f, 1, 1.0}, C{0.5f, 1, 0.5}, C{0.5f, 1, 1e-3}, C{0.8f, 1, 0.7}, C{0.8f, 1, 1e-3}, C{0.3f, 1, 0.3},
                     C{0.5f, 0, 0.5}, C{0.8f, 0, 1e-3}}) {
    DirectionCase dc{glsl_material(metal(c.glossiness, c.sampling)) + incident(c.cos_o) + kBsdfPdfHelper, kBsdfSample,
                     kBsdfDensity};
    const std::string name = "metal g=" + std::to_string(c.glossiness).substr(0, 3) + (c.sampling > 0 ? " vndf" : " cosine") +
                             " cos_o=" + std::to_string(c.cos_o);
    CHECK(direction_chi2(dc, name.c_str()).p_value >= kSamplingAlpha);
  }
}

TEST_CASE("chi-square: Phong specular lobe", "[gpu][sampling]") {
  for (float n : {8.0f, 60.0f})
    for (double c : {0.9, 0.2}) {
      DirectionCase dc{glsl_material(PhongSpecular{.n = n}) + incident(c) + kBsdfPdfHelper, kBsdfSample, kBsdfDensity};
      const std::string name = "phong n=" + std::to_string(int(n)) + " cos_o=" + std::to_string(c);
      CHECK(direction_chi2(dc, name.c_str()).p_value >= kSamplingAlpha);
    }
}

TEST_CASE("chi-square: Textured, a Lambert and Phong mixture", "[gpu][sampling][textured]") {
  // The record as resolve_textured leaves it: tint = (1 - s) rho, the hit field spec = s.
  struct C {
    float diffuse, specular, n;
    double cos_o;
  };
  for (const C& c : {C{0.6f, 0.4f, 30.0f, 0.8}, C{0.9f, 0.1f, 8.0f, 0.3}, C{0.2f, 0.8f, 60.0f, 1e-3}, C{0.0f, 0.5f, 20.0f, 0.5}}) {
    char setup[300];
    std::snprintf(setup, sizeof setup,
                  "MaterialRec make_material() {\n  MaterialRec m = packed_textured();\n  TexturedRec q = textured_rec(m);\n"
                  "  q.spec = vec3(%.3f);\n  return with_textured_rec(m, q);\n}\n",
                  double(c.specular));
    DirectionCase dc{glsl_material(Material(Textured{.n = c.n}, glm::vec3(c.diffuse)), "packed_textured") + setup + incident(c.cos_o) +
                         kBsdfPdfHelper,
                     kBsdfSample, kBsdfDensity};
    const std::string name = "textured d=" + std::to_string(c.diffuse).substr(0, 3) + " s=" + std::to_string(c.specular).substr(0, 3) +
                             " cos_o=" + std::to_string(c.cos_o);
    CHECK(direction_chi2(dc, name.c_str()).p_value >= kSamplingAlpha);
  }
}

TEST_CASE("chi-square: every material kind's example that samples a lobe of its own", "[gpu][sampling]") {
  // Walks the list of kinds: a kind whose record (as packed) is not a delta lobe, does not
  // turn into another at the hit (textures: their Diffuse is tested above) and is not a
  // composite is sampled at two incident angles. A new BSDF kind is tested here with no
  // line added.
  int tested = 0;
  for (int k = 0; k < kNumMaterialKinds; ++k) {
    const MaterialTraits& t = kMaterialTraits[k];
    if (t.resolves_at_hit || t.composite) continue;
    const Scene s = load_scene_text(std::string("<SceneLevel><Camera position=\"0 0 5\"/><Objects><Sphere center=\"0 0 0\" radius=\"1\">") +
                                        t.example + "</Sphere></Objects></SceneLevel>",
                                    repo_path("assets/textures") + "/x.xml");
    const std::string rec = glsl_material(s.materials[size_t(s.shapes[0].material)]);
    GlslKernel delta(rec + "vec4 kernel(vec4 x, int i) { return vec4(material_is_delta(make_material()) ? 1.0 : 0.0); }\n");
    if (delta.run(1)[0].x != 0.0f) continue;
    for (double c : {0.7, 0.05}) {
      DirectionCase dc{rec + incident(c) + kBsdfPdfHelper, kBsdfSample, kBsdfDensity};
      const std::string name = std::string(kMaterialKinds[k].xml) + " example cos_o=" + std::to_string(c);
      CHECK(direction_chi2(dc, name.c_str()).p_value >= kSamplingAlpha);
    }
    ++tested;
  }
  CHECK(tested >= 3);  // Diffuse, Metal, PhongSpecular today
}

TEST_CASE("chi-square: light sampling of spheres, boxes, disks and triangles", "[gpu][sampling]") {
  // The density of a direction is only defined where the ray meets the light: the
  // density kernel intersects the shape to find the distance and normal there.
  const std::string density_helper =
      "float light_density(vec3 d) {\n  Hit h = no_hit();\n  ShapeRec s = make_light();\n"
      "  Ray r = Ray(P, d);\n  if (s.kind == SHAPE_SPHERE) intersect_sphere(s, 0, r, h);\n"
      "  if (s.kind == SHAPE_BOX) intersect_box(s, 0, r, prepare_box(r), h);\n  if (s.kind == SHAPE_TRIANGLE) intersect_triangle(s, 0, r, prepare_triangle(r), h);\n"
      "  if (s.kind == SHAPE_DISK) intersect_disk(s, 0, r, h);\n"
      "  if (h.id < 0 || dot(h.n, d) >= 0.0) return 0.0;\n  return light_pdf_shape(s, P, d, h.t, h.n);\n}\n";
  const char* sample = "  float pdf, dist;\n  ok = light_sample_shape(make_light(), P, vec2(rand01(), rand01()), wi, pdf, dist) && pdf > 0.0;";
  struct C {
    const char* name;
    const char* shape;
  };
  std::set<std::string> covered;  // the SHAPE_ names of the cases
  for (const C& c : {C{"sphere light (near, wide cone)", "s.kind = SHAPE_SPHERE; s = with_sphere_rec(s, SphereRec(vec3(0.3, -0.2, 1.5), 1.2, vec3(0.0)));"},
                     C{"sphere light (far, narrow cone)", "s.kind = SHAPE_SPHERE; s = with_sphere_rec(s, SphereRec(vec3(4.0, 0.3, 0.2), 1.0, vec3(0.0)));"},
                     C{"box light (one face visible)", "s.kind = SHAPE_BOX; s = with_box_rec(s, BoxRec(vec3(-1.0, -1.0, 0.5), vec3(1.0, 1.0, 2.0), vec3(0.0)));"},
                     C{"box light (two faces visible)", "s.kind = SHAPE_BOX; s = with_box_rec(s, BoxRec(vec3(-2.5, -1.0, 0.4), vec3(-0.4, 1.0, 2.0), vec3(0.0)));"},
                     C{"box light (three faces visible)", "s.kind = SHAPE_BOX; s = with_box_rec(s, BoxRec(vec3(0.3, 0.4, 0.5), vec3(2.0, 2.0, 2.0), vec3(0.0)));"},
                     C{"disk light (tilted)", "s.kind = SHAPE_DISK; s = with_disk_rec(s, DiskRec(vec3(0.4, -0.3, 1.2), 0.9, normalize(vec3(-0.2, 0.3, -1.0)), vec3(0.0)));"},
                     C{"triangle light", "s.kind = SHAPE_TRIANGLE; s = with_triangle_rec(s, TriangleRec(vec3(-1.0, -1.0, 1.0), vec3(0.0, 1.5, 1.0), vec3(1.0, -1.0, 0.6), vec3(0.0)));"}}) {
    const std::string setup = std::string("const vec3 P = vec3(0.0);\nShapeRec make_light() {\n  ShapeRec s;\n  s.material = 0; s.light = 0;\n  ") +
                              c.shape + "\n  return s;\n}\n" + density_helper;
    DirectionCase dc{setup, sample, "light_density(d)"};
    CHECK(direction_chi2(dc, c.name).p_value >= kSamplingAlpha);
    covered.insert(std::string(c.shape).substr(std::string(c.shape).find("SHAPE_") + 6, std::string(c.shape).find(';') - std::string(c.shape).find("SHAPE_") - 6));
  }
  // Every light-sampled kind of the list has its case here (a new one cannot be forgotten).
  for (const KindInfo& k : kShapeKinds) {
    if (!k.samplable) continue;
    std::string up = k.glsl;
    for (char& ch : up) ch = char(std::toupper(static_cast<unsigned char>(ch)));
    INFO("no light-sampling chi-square case for " << k.xml);
    CHECK(covered.count(up) == 1);
  }
}

TEST_CASE("sampled weights equal f cos / pdf of the evaluated BSDF", "[gpu][sampling]") {
  for (const char* kind : {"Diffuse", "Metal"})
    for (float sampling : {0.0f, 1.0f}) {
      const double c = 0.4;  // the incidence
      const float worst = sampled_weight_error(kind[0] == 'D' ? Material(Diffuse{}) : metal(0.6f, sampling),
                                               glm::vec3(float(std::sqrt(1 - c * c)), 0.0f, float(c)));
      INFO(kind << " sampling " << sampling);
      CHECK(worst < 1e-4f);
    }
}

TEST_CASE("chi-square: environment map importance sampling", "[gpu][sampling]") {
  // A 32x16 map: a dim gradient, a band of zeros and a few hot texels, under two rotations.
  EnvImage map;
  map.width = 32;
  map.height = 16;
  map.rgba.assign(size_t(map.width * map.height * 4), 0.0f);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      float* p = &map.rgba[size_t(y * map.width + x) * 4];
      const float v = y == 9 ? 0.0f : 0.05f + 0.02f * float(x) + ((x * 7 + y * 3) % 11 == 0 ? 40.0f : 0.0f);
      p[0] = v;
      p[1] = 0.5f * v;
      p[2] = 0.25f * v + 0.01f;
      p[3] = 1.0f;
    }
  const EnvDistribution d = build_env_distribution(map);
  test_gl();
  const Texture env(map.width, map.height, GL_RGBA32F, map.rgba.data());
  const Texture cdf(map.width + 1, map.height + 1, GL_RGBA32F, d.cdf_texels.data());
  for (float rotation : {0.0f, 2.1f}) {
    DirectionCase dc{"", "  float pdf;\n  vec3 radiance;\n  ok = env_sample(vec2(rand01(), rand01()), wi, pdf, radiance);", "env_pdf(d)"};
    dc.prepare = [&](GlslKernel& k) {
      k.bind("u_env_map", env);
      k.bind("u_env_cdf", cdf);
      k.program().set("u_env_size", glm::ivec2(map.width, map.height));
      k.program().set("u_env_rotation", rotation);
      k.program().set("u_env_intensity", 1.0f);
      k.program().set("u_env_integral", d.integral);
    };
    const std::string name = "environment map, rotation " + std::to_string(rotation).substr(0, 3);
    CHECK(direction_chi2(dc, name.c_str()).p_value >= kSamplingAlpha);
  }
}

TEST_CASE("the MIS weight stays in [0, 1] and sums to 1 at extreme densities", "[gpu][sampling][hard]") {
  // A far point's density towards a small emitter, t^2 / (cos A), passes 1.8e19, whose
  // square overflows: the weight was inf / inf (a NaN sample under a disk light over a plane
  // seen to its horizon, 1 in 10^7 samples).
  GlslKernel k("vec4 kernel(vec4 x, int i) { return vec4(power_heuristic(x.x, x.y), power_heuristic(x.y, x.x), 0.0, 0.0); }\n");
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<glm::vec4> in = {{1e20f, 1.0f, 0, 0}, {1e20f, 3e19f, 0, 0}, {3e38f, 3e38f, 0, 0}, {inf, 1.0f, 0, 0},
                                     {inf, inf, 0, 0},     {1e-30f, 1e-30f, 0, 0}, {2.0f, 1.0f, 0, 0}, {0.0f, 1.0f, 0, 0}};
  const std::vector<glm::vec4> out = k.run(in);
  for (size_t i = 0; i < in.size(); ++i) {
    INFO("pdf_a " << in[i].x << ", pdf_b " << in[i].y << ": " << out[i].x << " " << out[i].y);
    CHECK(std::isfinite(out[i].x));
    CHECK(out[i].x >= 0.0f);
    CHECK(out[i].x <= 1.0f);
    if (in[i].x > 0.0f && in[i].y > 0.0f) CHECK(std::abs(out[i].x + out[i].y - 1.0f) <= 1e-6f);
  }
  CHECK(out[0].x == 1.0f);
  CHECK(std::abs(out[1].x - 1.0f / (1.0f + 0.09f)) <= 1e-6f);
  CHECK(std::abs(out[6].x - 0.8f) <= 1e-6f);
  CHECK(out[7].x == 0.0f);
}
