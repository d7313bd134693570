// The glTF BSDF's extension lobes (materials/gltf_lobes.h; KHR_materials_specular,
// _clearcoat, _sheen) on the production GLSL through the harness: each lobe's sampler
// against its mixture density (chi-square, grazing incidence too), sampled weights equal
// to f cos / pdf, reciprocity, closed forms (the specular's coloured Schlick, the coat's
// Fresnel, the coat over a white mirror returning exactly 1), the build-time sheen albedo
// table against Monte Carlo, the furnace sweep (docs/gltf.md has the table this prints),
// and each lobe compiled in only where a material uses it.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>

#include "direction_chi2.h"
#include "gl_context.h"
#include "core/file_io.h"
#include "glsl_harness.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

Features lobe_features() {
  Features f = all_features();
  f.material_features |= feature_bit(MaterialFeature::GltfSpecular) | feature_bit(MaterialFeature::GltfClearcoat) |
                         feature_bit(MaterialFeature::GltfSheen) | feature_bit(MaterialFeature::GltfTransmission);
  return f;
}

// GLSL of make_material(): MetallicRoughness `mr` as packed, with the clearcoat's normal
// `nc` (shading frame; the hit field GltfPbr sets) when it is not +z.
// `transmission`: the thin-walled transmission (a hit field too: GltfPbr's).
std::string material_glsl(const MetallicRoughness& mr, glm::vec3 nc = glm::vec3(0.0f, 0.0f, 1.0f), float transmission = 0.0f) {
  std::string s = glsl_material(Material(mr), "packed_material");
  char buf[640];
  std::snprintf(buf, sizeof buf,
                "MaterialRec make_material() {\n  MaterialRec m = packed_material();\n  vec3 nc = normalize(vec3(%.9g, %.9g, %.9g));\n"
                "  MetallicRoughnessRec q = metallic_roughness_rec(m);\n"
                "  if (nc.z < 1.0) q.coat_normal = 1.0 + gltf_pack2((nc.xy + 1.0) * (2047.0 / 4095.0));\n"
                "  q.transmission = %.9f;\n  return with_metallic_roughness_rec(m, q);\n}\n",
                double(nc.x), double(nc.y), double(nc.z), double(transmission));
  return s + buf;
}

struct LobeCase {
  const char* name;
  MetallicRoughness mr;
  glm::vec3 nc{0.0f, 0.0f, 1.0f};
  float transmission = 0.0f;
};

std::vector<LobeCase> lobe_cases() {
  auto mr = [](glm::vec3 base, float metallic, float roughness, GltfLobes l) {
    MetallicRoughness m{.baseColor = base, .metallic = metallic, .roughness = roughness};
    m.lobes = l;
    return m;
  };
  const glm::vec3 tilt = glm::normalize(glm::vec3(0.3f, 0.15f, 0.94f));
  return {
      {"specular", mr(glm::vec3(0.8f, 0.5f, 0.3f), 0.0f, 0.4f, {.specular = 0.5f, .specularColor = glm::vec3(1.0f, 0.3f, 0.6f)})},
      {"clearcoat", mr(glm::vec3(0.7f), 0.5f, 0.6f, {.clearcoat = 0.8f, .clearcoatRoughness = 0.25f}), tilt},
      {"smooth clearcoat", mr(glm::vec3(0.6f, 0.2f, 0.2f), 0.0f, 0.5f, {.clearcoat = 1.0f, .clearcoatRoughness = 0.0f})},
      {"sheen", mr(glm::vec3(0.5f), 0.0f, 0.5f, {.sheenColor = glm::vec3(0.9f, 0.7f, 0.8f), .sheenRoughness = 0.4f})},
      {"all lobes", mr(glm::vec3(0.6f, 0.4f, 0.3f), 0.3f, 0.3f,
                       {.specular = 0.7f, .specularColor = glm::vec3(0.8f, 1.0f, 0.9f), .clearcoat = 0.6f, .clearcoatRoughness = 0.4f,
                        .sheenColor = glm::vec3(0.5f), .sheenRoughness = 0.7f}),
       tilt},
      {"thin transmission", mr(glm::vec3(0.8f, 0.9f, 0.6f), 0.1f, 0.4f, {}), glm::vec3(0.0f, 0.0f, 1.0f), 0.8f},
      {"smooth thin transmission", mr(glm::vec3(0.8f, 0.9f, 0.6f), 0.0f, 0.0f, {.sheenColor = glm::vec3(0.3f), .sheenRoughness = 0.5f}),
       glm::vec3(0.0f, 0.0f, 1.0f), 0.6f},
  };
}

constexpr double kCos[] = {0.8, 0.2, 0.02};
const double kAlpha = sidak_alpha(0.01, 7 * 3);

// The mean sampled weight (rgb) and its standard error (max over channels) at incidence cos_o.
struct Albedo {
  glm::dvec3 mean;
  double se;
};
Albedo albedo(const std::string& material, double cos_o, int n = 200000) {
  GlslKernel k(material + incident(cos_o) +
                   "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 31u), 0u);\n  BsdfSample s;\n"
                   "  if (!material_sample(make_material(), WO, true, vec3(rand01(), rand01(), rand01()), s)) return vec4(0.0);\n"
                   "  return vec4(s.weight, 0.0);\n}\n",
               lobe_features());
  glm::dvec3 sum(0.0), sq(0.0);
  for (const glm::vec4& v : k.run(n)) {
    const glm::dvec3 w(v);
    sum += w;
    sq += w * w;
  }
  const glm::dvec3 mean = sum / double(n), var = glm::max(glm::dvec3(0.0), sq / double(n) - mean * mean) / double(n);
  return {mean, std::sqrt(std::max({var.x, var.y, var.z}))};
}

double schlick(double f0, double c) { return f0 + (1 - f0) * std::pow(1 - c, 5); }

}  // namespace

TEST_CASE("glTF lobes: chi-square of the sampler with each extension lobe, grazing incidence too", "[gpu][sampling][gltf]") {
  test_gl();
  for (const LobeCase& c : lobe_cases())
    for (double cos_o : kCos) {
      DirectionCase dc{material_glsl(c.mr, c.nc, c.transmission) + incident(cos_o) + kBsdfPdfHelper, kBsdfSample, kBsdfDensity};
      dc.features = lobe_features();
      const std::string name = std::string("gltf ") + c.name + " cos_o=" + std::to_string(cos_o).substr(0, 4);
      CHECK(direction_chi2(dc, name.c_str()).p_value >= kAlpha);
    }
}

TEST_CASE("glTF lobes: sampled weights equal f cos / pdf of the evaluated BSDF", "[gpu][sampling][gltf]") {
  test_gl();
  for (const LobeCase& c : lobe_cases())
    for (double cos_o : kCos) {
      GlslKernel k(material_glsl(c.mr, c.nc, c.transmission) + incident(cos_o) +
                       "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 99u), 0u);\n  BsdfSample s;\n"
                       "  if (!material_sample(make_material(), WO, true, vec3(rand01(), rand01(), rand01()), s) || s.delta) return vec4(0.0);\n"
                       "  float pdf;\n  vec3 f = material_eval(make_material(), WO, s.wi, true, pdf);\n"
                       "  return vec4(abs(s.weight - f / pdf) / max(f / pdf, vec3(1e-6)), abs(pdf - s.pdf) / pdf);\n}\n",
                   lobe_features());
      k.program().use();
      k.program().set("u_dot_weight", 1);
      float worst = 0;
      for (const glm::vec4& v : k.run(20000)) worst = std::max({worst, v.x, v.y, v.z, v.w});
      INFO(c.name << " cos_o " << cos_o);
      CHECK(worst < 1e-4f);
    }
}

TEST_CASE("glTF lobes: reciprocity of the specular and sheen lobes and of the coat's microfacet lobe", "[gpu][sampling][gltf]") {
  test_gl();
  const char* dir =
      "vec3 dir(float a, float b) { float z = max(a, 1e-3); float r = sqrt(1.0 - z * z); return vec3(r * cos(6.2831853 * b), r * sin(6.2831853 * b), z); }\n";
  // The whole BSDF where its layering is reciprocal (no coat): f(a, b) = f(b, a).
  for (const LobeCase& c : lobe_cases()) {
    if (c.mr.lobes.clearcoat > 0.0f || c.transmission > 0.0f) continue;
    for (float roughness : {0.1f, 0.5f, 1.0f}) {
      MetallicRoughness mr = c.mr;
      mr.roughness = roughness;
      GlslKernel k(material_glsl(mr) + dir +
                       "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 7u), 0u);\n"
                       "  vec3 a = dir(rand01(), rand01()), b = dir(rand01(), rand01());\n  float p;\n"
                       "  vec3 fab = material_eval(make_material(), a, b, true, p) / b.z;\n"
                       "  vec3 fba = material_eval(make_material(), b, a, true, p) / a.z;\n"
                       "  return vec4(fab.r, fba.r, fab.b, fba.b);\n}\n",
                   lobe_features());
      float worst = 0.0f;
      for (const glm::vec4& v : k.run(20000))
        for (int ch : {0, 2}) worst = std::max(worst, std::abs(v[ch] - v[ch + 1]) / std::max(1e-3f, std::max(v[ch], v[ch + 1])));
      INFO(c.name << " roughness " << roughness);
      CHECK(worst < 1e-3f);
    }
  }
  // The thin-walled transmission: f(a, b) = f(-b, -a)... seen from either side, a light
  // path a -> b through the sheet is the path b -> a reversed: f(a, b) / |b.z| = f(b', a') / |a.z|
  // with b' = -b and a' = -a mirrored onto the viewer's side (b' above, a' below).
  {
    GlslKernel t(material_glsl(lobe_cases()[5].mr, glm::vec3(0.0f, 0.0f, 1.0f), 0.8f) + dir +
                     "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 9u), 0u);\n"
                     "  vec3 a = dir(rand01(), rand01()), b = -dir(rand01(), rand01());\n  float p;\n"
                     "  vec3 fab = material_eval(make_material(), a, b, true, p) / abs(b.z);\n"
                     "  vec3 fba = material_eval(make_material(), -b, -a, true, p) / abs(a.z);\n"
                     "  return vec4(fab.r, fba.r, fab.b, fba.b);\n}\n",
                 lobe_features());
    float worst_t = 0.0f;
    for (const glm::vec4& v : t.run(20000))
      for (int ch : {0, 2}) worst_t = std::max(worst_t, std::abs(v[ch] - v[ch + 1]) / std::max(1e-3f, std::max(v[ch], v[ch + 1])));
    CHECK(worst_t < 1e-3f);
  }
  // The coat's own lobe D G2 / (4 |n_c.l| |n_c.v|) around a tilted normal. (Its weight
  // clearcoat F_c(n_c.v) is the extension's fresnel_coat, of v alone: docs/gltf.md.)
  GlslKernel k(material_glsl(lobe_cases()[1].mr) + dir +
                   "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 8u), 0u);\n"
                   "  vec3 a = dir(rand01(), rand01()), b = dir(rand01(), rand01()), nc = normalize(vec3(0.3, 0.15, 0.94));\n  float p;\n"
                   "  float fab = gltf_coat_eval(nc, 0.3, a, b, p) / max(dot(nc, b), 1e-9);\n"
                   "  float fba = gltf_coat_eval(nc, 0.3, b, a, p) / max(dot(nc, a), 1e-9);\n"
                   "  return vec4(fab, fba, 0.0, 0.0);\n}\n",
               lobe_features());
  float worst = 0.0f;
  for (const glm::vec4& v : k.run(20000)) worst = std::max(worst, std::abs(v.x - v.y) / std::max(1e-3f, std::max(v.x, v.y)));
  CHECK(worst < 1e-3f);
}

TEST_CASE("glTF lobes: closed forms of the specular and clearcoat Fresnel terms", "[gpu][sampling][gltf]") {
  test_gl();
  for (double c : {1.0, 0.5, 0.1}) {
    // KHR_materials_specular on a smooth dielectric over a black base: reflectance
    // specular (F0 + (1 - F0) (1 - c)^5) per channel, F0 = 0.04 specularColor.
    MetallicRoughness spec{.baseColor = glm::vec3(0.0f), .metallic = 0.0f, .roughness = 0.0f};
    spec.lobes.specular = 0.5f;
    spec.lobes.specularColor = glm::vec3(1.0f, 0.5f, 0.25f);
    const Albedo a = albedo(material_glsl(spec), c);
    for (int ch = 0; ch < 3; ++ch) {
      const double want = 0.5 * schlick(0.04 * double(spec.lobes.specularColor[ch]), c);
      INFO("specular, cos " << c << " channel " << ch << ": " << a.mean[ch] << " vs " << want << " (se " << a.se << ")");
      CHECK(std::abs(a.mean[ch] - want) < 4 * a.se + 1e-5);
    }
    // A smooth clearcoat over a black base without specular: only the coat reflects,
    // clearcoat F_c(c), F_c = Schlick of f0 0.04 (ior 1.5).
    MetallicRoughness coat{.baseColor = glm::vec3(0.0f), .metallic = 0.0f, .roughness = 0.5f};
    coat.lobes.specular = 0.0f;
    coat.lobes.clearcoat = 0.5f;
    const Albedo b = albedo(material_glsl(coat), c);
    const double want = (2048.0 / 4095.0) * schlick(0.04, c);  // clearcoat 0.5 as packed (12 bits)
    INFO("clearcoat, cos " << c << ": " << b.mean.x << " vs " << want << " (se " << b.se << ")");
    CHECK(std::abs(b.mean.x - want) < 4 * b.se + 1e-5);
    // A smooth clearcoat over a smooth white metal: (1 - w) 1 + w = 1 exactly.
    MetallicRoughness mirror{.baseColor = glm::vec3(1.0f), .metallic = 1.0f, .roughness = 0.0f};
    mirror.lobes.clearcoat = 1.0f;
    const Albedo m = albedo(material_glsl(mirror), c);
    INFO("coated mirror, cos " << c << ": " << m.mean.x << " (se " << m.se << ")");
    CHECK(std::abs(m.mean.x - 1.0) < 4 * m.se + 1e-5);
    // A smooth white thin sheet of transmission 1: it reflects F and passes 1 - F
    // straight through (F = Schlick of 0.04): 1 in all, 1 - F of it below the surface.
    const std::string sheet = material_glsl(MetallicRoughness{.baseColor = glm::vec3(1.0f), .metallic = 0.0f, .roughness = 0.0f},
                                            glm::vec3(0.0f, 0.0f, 1.0f), 1.0f);
    const Albedo t = albedo(sheet, c);
    GlslKernel below(sheet + incident(c) +
                         "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 32u), 0u);\n  BsdfSample s;\n"
                         "  if (!material_sample(make_material(), WO, true, vec3(rand01(), rand01(), rand01()), s) || s.wi.z >= 0.0) return vec4(0.0);\n"
                         "  return vec4(s.weight, distance(s.wi, -WO));\n}\n",
                     lobe_features());
    double sum = 0, sq = 0, off = 0;
    const int n = 200000;
    for (const glm::vec4& v : below.run(n)) sum += v.x, sq += double(v.x) * v.x, off = std::max(off, double(v.w));
    const double through = sum / n, through_se = std::sqrt(std::max(0.0, sq / n - through * through) / n);
    INFO("thin sheet, cos " << c << ": " << t.mean.x << " (se " << t.se << "), through " << through << " vs " << 1 - schlick(0.04, c)
                            << " (se " << through_se << ")");
    CHECK(std::abs(t.mean.x - 1.0) < 4 * t.se + 1e-5);
    CHECK(std::abs(through - (1 - schlick(0.04, c))) < 4 * through_se + 1e-5);
    CHECK(off < 1e-6);  // no bending
  }
}

TEST_CASE("glTF lobes: the build-time sheen albedo table matches Monte Carlo", "[gpu][sampling][gltf]") {
  test_gl();
  // E(mu, r) = the integral of the sheen lobe times n.l, estimated with cosine-weighted
  // directions: (f cos) / (cos / pi), against gltf_sheen_albedo's bilinear table lookup,
  // on and between the table's nodes (1.5%: the table's interpolation error).
  const double cases[][2] = {{1.0, 1.0}, {0.5, 0.5}, {0.9, 0.3}, {0.2, 1.0}, {0.7, 0.8}, {0.35, 0.62}, {0.1, 0.4}};
  for (const auto& c : cases) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "const float MU = %.9f, R = %.9f;\n", c[0], c[1]);
    GlslKernel k(std::string(buf) + incident(c[0]) +
                     "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 5u), 0u);\n"
                     "  vec3 wi = sample_cosine_hemisphere(vec2(rand01(), rand01()));\n"
                     "  return vec4(gltf_sheen_eval(gltf_sheen_roughness(R), WO, wi) * PI / wi.z, gltf_sheen_albedo(MU, gltf_sheen_roughness(R)), 0.0, 0.0);\n}\n",
                 lobe_features());
    const int n = 400000;
    double sum = 0, sq = 0, table = 0;
    for (const glm::vec4& v : k.run(n)) {
      sum += v.x;
      sq += double(v.x) * v.x;
      table = v.y;
    }
    const double mean = sum / n, se = std::sqrt(std::max(0.0, sq / n - mean * mean) / n);
    std::printf("sheen albedo mu %.2f r %.2f: Monte Carlo %.5f (se %.5f), table %.5f\n", c[0], c[1], mean, se, table);
    INFO("mu " << c[0] << " r " << c[1]);
    CHECK(std::abs(table - mean) < 4 * se + 0.015 * mean);
  }
}

TEST_CASE("glTF lobes: furnace sweep of white materials never above 1", "[gpu][transport][gltf]") {
  test_gl();
  // The directional albedo (the white furnace of one bounce: what a convex object returns
  // under a sky of 1) of white materials at incidences cos 1, 0.7, 0.4 and 0.2, swept over
  // pairs of axes (5 values each) with the others at metallic 0, roughness 0.5, specular 1,
  // clearcoat 0 (its roughness = the base's), sheen 0 (sheen colour = the value, roughness
  // 0.5), transmission 0 (thin-walled: what passes counts too). One kernel per pair: each invocation sets its record's fields from its input
  // (configuration, incidence) and also samples the core material of the same metallic
  // and roughness. Head-on every material returns at most 1; at oblique incidence the
  // core glTF BSDF itself returns more than 1 (Appendix B's Lambertian weighted by
  // 1 - F(v.h), docs/gltf.md), so there an extension must return at most max(1, core):
  // its layering adds no energy. Printed: the largest over the incidences (docs/gltf.md).
  const char* names[] = {"metallic", "roughness", "specular", "clearcoat", "sheen", "transmission"};
  const int pairs[][2] = {{0, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}, {3, 0}, {4, 0}, {4, 3}, {2, 3}, {5, 3}};
  const double cosines[] = {1.0, 0.7, 0.4, 0.2};
  constexpr int kPer = 40000;
  MetallicRoughness white{.baseColor = glm::vec3(1.0f)};
  white.lobes = GltfLobes{.specular = 0.5f, .clearcoat = 0.5f, .sheenColor = glm::vec3(0.5f)};
  for (const auto& p : pairs) {
    char consts[128];
    std::snprintf(consts, sizeof consts, "const int PA = %d, PB = %d;\n", p[0], p[1]);
    GlslKernel k(material_glsl(white) + consts +
                     "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 31u), 0u);\n"
                     "  int cfg = int(x.x);\n  float cos_o = x.y;\n"
                     "  float v[6] = float[](0.0, 0.5, 1.0, 0.0, 0.0, 0.0);\n"
                     "  v[PA] = float(cfg / 5) / 4.0;\n  v[PB] = float(cfg % 5) / 4.0;\n"
                     "  MaterialRec m = make_material();\n  MetallicRoughnessRec q = metallic_roughness_rec(m);\n"
                     "  q.metallic = v[0];\n  q.roughness = v[1];\n  q.specular = v[2];\n"
                     "  q.coat = gltf_pack2(vec2(v[3], v[1]));\n  q.sheen_rg = gltf_pack2(vec2(v[4]));\n  q.sheen_br = gltf_pack2(vec2(v[4], 0.5));\n"
                     "  q.transmission = v[5];\n"
                     "  MaterialRec core = with_metallic_roughness_rec(m, MetallicRoughnessRec(v[0], v[1], q.f0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0));\n"
                     "  m = with_metallic_roughness_rec(m, q);\n"
                     "  vec3 wo = vec3(sqrt(1.0 - cos_o * cos_o), 0.0, cos_o);\n  BsdfSample s, c;\n"
                     "  vec4 r = vec4(0.0);\n"
                     "  if (material_sample(m, wo, true, vec3(rand01(), rand01(), rand01()), s)) r.x = s.weight.x;\n"
                     "  if (material_sample(core, wo, true, vec3(rand01(), rand01(), rand01()), c)) r.y = c.weight.x;\n"
                     "  return r;\n}\n",
                 lobe_features());
    std::vector<glm::vec4> in;
    for (int cfg = 0; cfg < 25; ++cfg)
      for (double c : cosines) in.insert(in.end(), kPer, glm::vec4(float(cfg), float(c), 0.0f, 0.0f));
    const std::vector<glm::vec4> out = k.run(in);
    std::printf("furnace sweep: rows %s, columns %s 0, .25, .5, .75, 1 (largest albedo over cos 1, .7, .4, .2; se)\n", names[p[0]],
                names[p[1]]);
    for (int i = 0; i <= 4; ++i) {
      std::printf("  %s %.2f:", names[p[0]], i / 4.0);
      for (int j = 0; j <= 4; ++j) {
        double worst = 0, worst_se = 0;
        for (int a = 0; a < 4; ++a) {
          const size_t first = size_t(((i * 5 + j) * 4 + a) * kPer);
          glm::dvec2 sum(0.0), sq(0.0);
          for (size_t t = first; t < first + kPer; ++t) {
            const glm::dvec2 w(out[t].x, out[t].y);
            sum += w;
            sq += w * w;
          }
          const glm::dvec2 mean = sum / double(kPer), se = glm::sqrt(glm::max(glm::dvec2(0.0), sq / double(kPer) - mean * mean) / double(kPer));
          INFO(names[p[0]] << " " << i / 4.0 << " " << names[p[1]] << " " << j / 4.0 << " cos " << cosines[a] << ": " << mean.x << " se "
                           << se.x << " (core " << mean.y << " se " << se.y << ")");
          if (a == 0) CHECK(mean.x <= 1.0 + 3 * se.x + 1e-6);
          if (mean.x > std::max(1.0, mean.y)) CHECK(mean.x <= std::max(1.0, mean.y) + 3 * std::hypot(se.x, se.y) + 1e-6);
          if (mean.x > worst) worst = mean.x, worst_se = se.x;
        }
        std::printf(" %.4f (%.4f)", worst, worst_se);
      }
      std::printf("\n");
    }
  }
}

TEST_CASE("glTF lobes: each lobe is compiled in only where a material uses it", "[shadergen][gltf]") {
  auto program = [](const std::string& attrs) {
    const Scene s = load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects><Sphere center=\"0 0 0\" radius=\"1\"><MetallicRoughness " +
                                        attrs + "/></Sphere></Objects></SceneLevel>",
                                    repo_path("scenes/x.xml"));
    return generate_integrator(Features::of(s)).text;  // a MetallicRoughness sphere, the constant sky
  };
  const std::string core = program(""), spec = program("specular=\"0.5\""), coat = program("clearcoat=\"0.5\""),
                    sheen = program("sheenColor=\"0.5 0.5 0.5\"");
  CHECK(core.find("float gltf_coat_eval(") == std::string::npos);
  CHECK(core.find("const float SHEEN_E[") == std::string::npos);
  CHECK(core.find("#define HAS_GLTF_SPECULAR") == std::string::npos);
  CHECK(spec.find("#define HAS_GLTF_SPECULAR") != std::string::npos);
  CHECK(coat.find("float gltf_coat_eval(") != std::string::npos);
  CHECK(coat.find("const float SHEEN_E[") == std::string::npos);
  CHECK(sheen.find("const float SHEEN_E[") != std::string::npos);
  CHECK(sheen.find("float gltf_coat_eval(") == std::string::npos);
  auto gltf = [](const std::string& attrs) {
    const Scene s = load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects><Sphere center=\"0 0 0\" radius=\"1\"><GltfPbr doubleSided=\"true\" " +
                                        attrs + "/></Sphere></Objects></SceneLevel>",
                                    repo_path("scenes/x.xml"));
    return generate_integrator(Features::of(s)).text;
  };
  const std::string pbr = gltf(""), thin = gltf("transmission=\"0.5\"");
  CHECK(pbr.find("#define HAS_GLTF_TRANSMISSION") == std::string::npos);
  CHECK(thin.find("#define HAS_GLTF_TRANSMISSION") != std::string::npos);
  // docs/scenes.md's table of the program's size per extension set (regenerated here; the
  // current one is written to the build folder as lobes-table.md).
  const std::string all = program("specular=\"0.5\" clearcoat=\"0.5\" sheenColor=\"0.5 0.5 0.5\"");
  std::string table = "| glTF extensions in the scene | shader (bytes) |\n|---|---|\n";
  for (const auto& [name, text] : {std::pair<const char*, const std::string*>{"core (Appendix B, emissive_strength, ior)", &core},
                                   {"+ KHR_materials_specular", &spec}, {"+ KHR_materials_clearcoat", &coat},
                                   {"+ KHR_materials_sheen", &sheen}, {"+ specular, clearcoat and sheen", &all},
                                   {"GltfPbr (the same with maps)", &pbr}, {"GltfPbr + KHR_materials_transmission (thin-walled)", &thin}})
    table += std::string("| ") + name + " | " + std::to_string(text->size()) + " |\n";
  std::ofstream(std::string(PT_BINARY_DIR) + "/lobes-table.md") << table;
  const auto doc = read_file(repo_path("docs/scenes.md"));
  REQUIRE(doc);
  INFO("docs/scenes.md: the extension-set table differs; the current one is in " << PT_BINARY_DIR << "/lobes-table.md");
  CHECK(doc->find(table) != std::string::npos);
}
