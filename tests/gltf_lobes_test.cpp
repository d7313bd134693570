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
#include "render/renderer.h"
#include "render/uniform_tables.h"
#include "scene/xml_loader.h"
#include "render/renderer.h"
#include "test_paths.h"
#include "stats.h"

using namespace pt;

namespace {

// Every lobe, with the multiple-scattering compensation (the default: materials/gltf_ms.glsl).
Features lobe_features() { return gltf_lobe_features(); }
// The same without the compensation: the specification's single-scattering model (--gltf-ms off).
Features spec_features() {
  Features f = lobe_features();
  f.material_features &= ~feature_bit(MaterialFeature::GltfMs);
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
      // The multiple-scattering compensation (materials/gltf_ms.glsl): a rough coloured metal
      // (its lobe F_ms (1 - E) (1 - E) / (pi (1 - E_avg)), cosine-sampled) and a half metal.
      {"rough metal", mr(glm::vec3(0.9f, 0.6f, 0.3f), 1.0f, 0.9f, {})},
      {"half metal", mr(glm::vec3(0.7f, 0.8f, 0.9f), 0.5f, 0.6f, {})},
  };
}

constexpr double kLobesCos[] = {0.8, 0.2, 0.02};
const double kLobesAlpha = sidak_alpha(0.01, 9 * 3);

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

}  // namespace

TEST_CASE("glTF lobes: chi-square of the sampler with each extension lobe, grazing incidence too", "[gpu][sampling][gltf]") {
  test_gl();
  for (const LobeCase& c : lobe_cases())
    for (double cos_o : kLobesCos) {
      DirectionCase dc{material_glsl(c.mr, c.nc, c.transmission) + incident(cos_o) + kBsdfPdfHelper, kBsdfSample, kBsdfDensity};
      dc.features = lobe_features();
      const std::string name = std::string("gltf ") + c.name + " cos_o=" + std::to_string(cos_o).substr(0, 4);
      CHECK(direction_chi2(dc, name.c_str()).p_value >= kLobesAlpha);
    }
}

TEST_CASE("glTF lobes: sampled weights equal f cos / pdf of the evaluated BSDF", "[gpu][sampling][gltf]") {
  test_gl();
  for (const LobeCase& c : lobe_cases()) {
    const std::vector<double> cosines(std::begin(kLobesCos), std::end(kLobesCos));
    const std::vector<float> worst = sampled_weight_errors(material_glsl(c.mr, c.nc, c.transmission), lobe_features(), cosines);
    for (size_t i = 0; i < cosines.size(); ++i) {
      INFO(c.name << " cos_o " << cosines[i]);
      CHECK(worst[i] < 1e-4f);
    }
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

TEST_CASE("glTF lobes: the sheen lobe stays finite where a cosine rounds above 1", "[gpu][gltf][hard]") {
  test_gl();
  // A shading-frame cosine is a dot product of unit vectors and may round to 1 + a few ulp
  // (a view along the normal). The fitted Lambda takes pow(1 - cos, c): a negative base
  // is NaN. The H200 found it: about 2 samples in 10^9 of scenes/gltf/sheen.xml were NaN
  // (docs/reliability.md). wo.z and wi.z are 1 + k ulp, k = 0..7, for each sheen roughness
  // of the table's range, against wi (or wo) spread over the hemisphere.
  GlslKernel k(
      "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 9u), 0u);\n"
      "  float up = uintBitsToFloat(floatBitsToUint(1.0) + uint(i % 8));\n"
      "  float r = gltf_sheen_roughness(0.05 + 0.95 * float((i / 8) % 16) / 15.0);\n"
      "  vec3 w = sample_cosine_hemisphere(vec2(rand01(), rand01()));\n"
      "  vec3 n = vec3(0.0, 0.0, up);\n"
      "  return vec4(gltf_sheen_eval(r, n, w), gltf_sheen_eval(r, w, n), gltf_sheen_eval(r, n, n), up - 1.0);\n}\n",
      lobe_features());
  int bad = 0, above = 0;
  for (const glm::vec4& v : k.run(8 * 16 * 64)) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || v.x < 0 || v.y < 0 || v.z < 0) ++bad;
    if (v.w > 0) ++above;
  }
  CHECK(above > 0);  // the kernel did reach cosines above 1
  CHECK(bad == 0);
}

TEST_CASE("glTF lobes: the build-time GGX albedo table matches Monte Carlo", "[gpu][sampling][gltf]") {
  test_gl();
  // E(mu, r) = the integral of the shader's GGX lobe D G2 / (4 n.v n.l) times n.l (F = 1),
  // and E2 the same weighted by (1 - v.h)^5, estimated with the shader's visible-normal
  // sampling (weight f cos / pdf from ggx_d, ggx_g2, pdf_ggx_vndf), against gltf_ms_e's
  // bilinear lookup of tools/gen_ggx_ms_lut.py's table, on and between its nodes; and the
  // averages 2 int E mu dmu (mu drawn with density 2 mu) against gltf_ms_eavg. Tolerance:
  // 4 standard errors + 0.0005 on the nodes (mu = (i / 23)^2, r = j / 23: the generator's
  // quadrature, 3e-4; a uniform rule there, 0.0015 off at mu 0.5, r 0.23, failed this test)
  // and + 0.002 between them (the bilinear interpolation's error, at most 0.0013 at
  // mu >= 0.2 over r 0.035..1). mu < 0: the average at r.
  const double node = 0.0005, between = 0.002;
  const double cases[][3] = {{1.0, 1.0, node}, {324.0 / 529.0, 14.0 / 23.0, node}, {100.0 / 529.0, 5.0 / 23.0, node},
                             {36.0 / 529.0, 9.0 / 23.0, node}, {1.0, 2.0 / 23.0, node},
                             {1.0, 0.5, between}, {0.7, 0.45, between}, {0.4, 0.8, between}, {0.2, 0.3, between}, {0.5, 0.23, between},
                             {0.9, 0.1, between}, {-1, 1.0, between}, {-1, 0.5, between}, {-1, 0.23, between}};
  // One kernel (mu and r from the input: compiling is most of the time on llvmpipe).
  GlslKernel k("vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 6u), 0u);\n  float MU = x.x, R = x.y;\n"
                     "  float mu = MU < 0.0 ? sqrt(rand01()) : MU, alpha = R * R, a2 = alpha * alpha;\n"
                     "  vec3 wo = vec3(sqrt(max(0.0, 1.0 - mu * mu)), 0.0, mu);\n"
                     "  vec3 h = sample_ggx_vndf(wo, alpha, vec2(rand01(), rand01()));\n  vec3 wi = reflect(-wo, h);\n"
                     "  vec2 table = MU < 0.0 ? gltf_ms_eavg(R) : gltf_ms_e(MU, R);\n"
                     "  if (wi.z <= 0.0) return vec4(0.0, 0.0, table);\n"
                     "  float w = ggx_d(h.z, a2) * ggx_g2(wo.z, wi.z, a2) / (4.0 * wo.z) / pdf_ggx_vndf(wo, h, a2);\n"
                     "  float s = 1.0 - dot(wo, h);\n  return vec4(w, w * s * s * s * s * s, table);\n}\n",
               lobe_features());
  for (const auto& c : cases) {
    const int n = 200000;
    glm::dvec2 sum(0.0), sq(0.0), table(0.0);
    for (const glm::vec4& v : k.run(std::vector<glm::vec4>(n, glm::vec4(float(c[0]), float(c[1]), 0.0f, 0.0f)))) {
      const glm::dvec2 w(v.x, v.y);
      sum += w;
      sq += w * w;
      table = glm::dvec2(v.z, v.w);
    }
    const glm::dvec2 mean = sum / double(n), se = glm::sqrt(glm::max(glm::dvec2(0.0), sq / double(n) - mean * mean) / double(n));
    std::printf("GGX albedo mu %5.2f r %.2f: Monte Carlo E %.5f (se %.5f) E2 %.5f (se %.5f), table %.5f %.5f\n", c[0], c[1], mean.x, se.x,
                mean.y, se.y, table.x, table.y);
    INFO("mu " << c[0] << " r " << c[1]);
    CHECK(std::abs(table.x - mean.x) < 4 * se.x + c[2]);
    CHECK(std::abs(table.y - mean.y) < 4 * se.y + c[2]);
  }
}

TEST_CASE("glTF lobes: --gltf-ms off renders the specification's single-scattering model", "[gpu][sampling][gltf]") {
  test_gl();
  // A white rough metal head-on: the spec's lobe returns its albedo E(1, 1) = 0.307
  // (docs/gltf.md), the compensated one 1.
  const std::string white = material_glsl(MetallicRoughness{.baseColor = glm::vec3(1.0f), .metallic = 1.0f, .roughness = 1.0f});
  auto run = [&](const Features& f) {
    GlslKernel k(white + incident(1.0) +
                     "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 33u), 0u);\n  BsdfSample s;\n"
                     "  if (!material_sample(make_material(), WO, true, vec3(rand01(), rand01(), rand01()), s)) return vec4(0.0);\n"
                     "  return vec4(s.weight, 0.0);\n}\n",
                 f);
    double sum = 0;
    for (const glm::vec4& v : k.run(50000)) sum += v.x;
    return sum / 50000;
  };
  const double spec = run(spec_features()), ms = run(lobe_features());
  INFO("single scattering " << spec << ", compensated " << ms);
  CHECK(std::abs(spec - 0.307) < 0.01);
  CHECK(std::abs(ms - 1.0) < 0.01);
  // The renderer's setting drops the feature (render/renderer.cpp with_settings).
  const Scene s = load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects><Sphere center=\"0 0 0\" radius=\"1\"><MetallicRoughness/>"
                                  "</Sphere></Objects></SceneLevel>",
                                  repo_path("scenes/x.xml"));
  CHECK(Features::of(s).has(MaterialFeature::GltfMs));
  CHECK(generate_integrator(Features::of(s)).text.find("uniform GgxMsTable {") != std::string::npos);
  Renderer r;
  RenderSettings st;
  st.gltf_ms = false;
  CHECK(r.program_features(s).has(MaterialFeature::GltfMs));
  r.set_settings(st);
  CHECK_FALSE(r.program_features(s).has(MaterialFeature::GltfMs));
}

TEST_CASE("glTF lobes: furnace sweep of white materials never above 1", "[gpu][transport][gltf]") {
  test_gl();
  // The directional albedo (the white furnace of one bounce: what a convex object returns
  // under a sky of 1) of white materials at incidences cos 1, 0.7, 0.4 and 0.2, swept over
  // pairs of axes (5 values each) with the others at metallic 0, roughness 0.5, specular 1,
  // clearcoat 0 (its roughness = the base's), sheen 0 (sheen colour = the value, roughness
  // 0.5), transmission 0 (thin-walled: what passes counts too). One kernel per pair: each
  // invocation sets its record's fields from its input (configuration, incidence). With the
  // multiple-scattering compensation (materials/gltf_ms.glsl) every material returns at most
  // 1 at every incidence (the spec's single-scattering dielectric returns up to 1.30 at
  // oblique incidence: docs/gltf.md), and the white materials that absorb nothing (metallic,
  // roughness and specular of any value: no coat, sheen or transmission, whose own lobes are
  // single-scattering) return 1 within 1% at every incidence. Printed: the largest over the
  // incidences, and for those the smallest too (docs/gltf.md).
  const char* names[] = {"metallic", "roughness", "specular", "clearcoat", "sheen", "transmission"};
  const int pairs[][2] = {{0, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}, {3, 0}, {4, 0}, {4, 3}, {2, 3}, {5, 3}};
  const double cosines[] = {1.0, 0.7, 0.4, 0.2};
  constexpr int kPer = 40000;
  MetallicRoughness white{.baseColor = glm::vec3(1.0f)};
  white.lobes = GltfLobes{.specular = 0.5f, .clearcoat = 0.5f, .sheenColor = glm::vec3(0.5f)};
  // One kernel for every pair (its axes from the input: compiling is most of the time on llvmpipe).
  GlslKernel k(material_glsl(white) +
                     "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 31u), 0u);\n"
                     "  int cfg = int(x.x);\n  float cos_o = x.y;\n  int pa = int(x.z), pb = int(x.w);\n"
                     "  float v[6] = float[](0.0, 0.5, 1.0, 0.0, 0.0, 0.0);\n"
                     "  v[pa] = float(cfg / 5) / 4.0;\n  v[pb] = float(cfg % 5) / 4.0;\n"
                     "  MaterialRec m = make_material();\n  MetallicRoughnessRec q = metallic_roughness_rec(m);\n"
                     "  q.metallic = v[0];\n  q.roughness = v[1];\n  q.specular = v[2];\n"
                     "  q.coat = gltf_pack2(vec2(v[3], v[1]));\n  q.sheen_rg = gltf_pack2(vec2(v[4]));\n  q.sheen_br = gltf_pack2(vec2(v[4], 0.5));\n"
                     "  q.transmission = v[5];\n"
                     "  m = with_metallic_roughness_rec(m, q);\n"
                     "  vec3 wo = vec3(sqrt(1.0 - cos_o * cos_o), 0.0, cos_o);\n  BsdfSample s;\n"
                     "  vec4 r = vec4(0.0);\n"
                     "  if (material_sample(m, wo, true, vec3(rand01(), rand01(), rand01()), s)) r.x = s.weight.x;\n"
                     "  return r;\n}\n",
                 lobe_features());
  for (const auto& p : pairs) {
    std::vector<glm::vec4> in;
    for (int cfg = 0; cfg < 25; ++cfg)
      for (double c : cosines) in.insert(in.end(), kPer, glm::vec4(float(cfg), float(c), float(p[0]), float(p[1])));
    const std::vector<glm::vec4> out = k.run(in);
    const bool lossless = p[0] <= 2 && p[1] <= 2;  // metallic, roughness, specular: nothing absorbs
    std::printf("furnace sweep: rows %s, columns %s 0, .25, .5, .75, 1 (%s albedo over cos 1, .7, .4, .2; se)\n", names[p[0]],
                names[p[1]], lossless ? "largest / smallest" : "largest");
    for (int i = 0; i <= 4; ++i) {
      std::printf("  %s %.2f:", names[p[0]], i / 4.0);
      for (int j = 0; j <= 4; ++j) {
        double worst = 0, worst_se = 0, least = 2, least_se = 0;
        for (int a = 0; a < 4; ++a) {
          const size_t first = size_t(((i * 5 + j) * 4 + a) * kPer);
          double sum = 0, sq = 0;
          for (size_t t = first; t < first + kPer; ++t) sum += out[t].x, sq += double(out[t].x) * out[t].x;
          const double mean = sum / kPer, se = std::sqrt(std::max(0.0, sq / kPer - mean * mean) / kPer);
          INFO(names[p[0]] << " " << i / 4.0 << " " << names[p[1]] << " " << j / 4.0 << " cos " << cosines[a] << ": " << mean << " se " << se);
          CHECK(mean <= 1.0 + 3 * se + 1e-6);
          if (lossless) CHECK(std::abs(mean - 1.0) < 0.01);
          if (mean > worst) worst = mean, worst_se = se;
          if (mean < least) least = mean, least_se = se;
        }
        if (lossless) std::printf(" %.4f / %.4f (%.4f)", worst, least, std::max(worst_se, least_se));
        else std::printf(" %.4f (%.4f)", worst, worst_se);
      }
      std::printf("\n");
    }
  }
}

TEST_CASE("glTF lobes: the renderer's program reads each table from its own buffer", "[gpu][gltf]") {
  test_gl();
  // A MetallicRoughness sphere with sheen has both uniform blocks (render/uniform_tables.h).
  // Each must have its list index as binding point (a block left at GL's default, 0, reads
  // the GGX table: the sheen's albedo scaling wrong, the image only a little darker), a
  // buffer bound there, and the generated block as large as the generator's numbers.
  const Scene s = load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects><Sphere center=\"0 0 0\" radius=\"1\">"
                                  "<MetallicRoughness sheenColor=\"0.5 0.5 0.5\"/></Sphere></Objects></SceneLevel>",
                                  repo_path("scenes/x.xml"));
  Renderer r;
  r.resize(8, 8);
  RenderSettings st;
  st.sample_limit = 1;
  st.spp_per_pass = 1;
  r.set_settings(st);
  r.set_scene(s);
  while (!r.converged()) r.step();
  const GLuint id = r.program_id();
  REQUIRE(id != 0u);
  const auto& t = uniform_tables();
  REQUIRE(t.size() == 2);
  for (size_t i = 0; i < t.size(); ++i) {
    INFO(t[i].block);
    const GLuint index = glGetUniformBlockIndex(id, t[i].block);
    REQUIRE(index != GL_INVALID_INDEX);
    GLint binding = -1, size = 0, buffer = 0;
    glGetActiveUniformBlockiv(id, index, GL_UNIFORM_BLOCK_BINDING, &binding);
    glGetActiveUniformBlockiv(id, index, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, GLuint(i), &buffer);
    CHECK(binding == int(i));
    CHECK(size == int(t[i].floats * sizeof(float)));
    CHECK(buffer != 0);
  }
}

TEST_CASE("glTF lobes: each lobe is compiled in only where a material uses it", "[shadergen][gltf]") {
  auto program = [](const std::string& attrs) {
    const Scene s = load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects><Sphere center=\"0 0 0\" radius=\"1\"><MetallicRoughness " +
                                        attrs + "/></Sphere></Objects></SceneLevel>",
                                    repo_path("scenes/x.xml"));
    return generate_integrator(Renderer::scene_features(s)).text;  // a MetallicRoughness sphere, the constant sky (the renderer's program)
  };
  const std::string core = program(""), spec = program("specular=\"0.5\""), coat = program("clearcoat=\"0.5\""),
                    sheen = program("sheenColor=\"0.5 0.5 0.5\"");
  CHECK(core.find("float gltf_coat_eval(") == std::string::npos);
  CHECK(core.find("uniform SheenTable {") == std::string::npos);
  CHECK(core.find("#define HAS_GLTF_SPECULAR") == std::string::npos);
  CHECK(spec.find("#define HAS_GLTF_SPECULAR") != std::string::npos);
  CHECK(coat.find("float gltf_coat_eval(") != std::string::npos);
  CHECK(coat.find("uniform SheenTable {") == std::string::npos);
  CHECK(sheen.find("uniform SheenTable {") != std::string::npos);
  CHECK(sheen.find("float gltf_coat_eval(") == std::string::npos);
  auto gltf = [](const std::string& attrs) {
    const Scene s = load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects><Sphere center=\"0 0 0\" radius=\"1\"><GltfPbr doubleSided=\"true\" " +
                                        attrs + "/></Sphere></Objects></SceneLevel>",
                                    repo_path("scenes/x.xml"));
    return generate_integrator(Renderer::scene_features(s)).text;
  };
  const std::string pbr = gltf(""), thin = gltf("transmission=\"0.5\""),
                    vol = gltf("transmission=\"1\" volume=\"true\" attenuationColor=\"0.5 0.8 0.2\" attenuationDistance=\"1\"");
  CHECK(pbr.find("#define HAS_GLTF_TRANSMISSION") == std::string::npos);
  CHECK(thin.find("#define HAS_GLTF_TRANSMISSION") != std::string::npos);
  CHECK(thin.find("#define HAS_GLTF_VOLUME") == std::string::npos);
  CHECK(thin.find("#define HAS_MEDIA") == std::string::npos);
  CHECK(thin.find("vec3 ggx_dielectric_eval(") == std::string::npos);
  CHECK(vol.find("#define HAS_GLTF_VOLUME") != std::string::npos);
  CHECK(vol.find("#define HAS_MEDIA") != std::string::npos);
  CHECK(vol.find("vec3 ggx_dielectric_eval(") != std::string::npos);
  // docs/scenes.md's table of the program's size per extension set (regenerated here; the
  // current one is written to the build folder as lobes-table.md).
  const std::string all = program("specular=\"0.5\" clearcoat=\"0.5\" sheenColor=\"0.5 0.5 0.5\"");
  std::string table = "| glTF extensions in the scene | shader (bytes) |\n|---|---|\n";
  for (const auto& [name, text] : {std::pair<const char*, const std::string*>{"core (Appendix B, emissive_strength, ior)", &core},
                                   {"+ KHR_materials_specular", &spec}, {"+ KHR_materials_clearcoat", &coat},
                                   {"+ KHR_materials_sheen", &sheen}, {"+ specular, clearcoat and sheen", &all},
                                   {"GltfPbr (the same with maps)", &pbr}, {"GltfPbr + KHR_materials_transmission (thin-walled)", &thin},
                                   {"GltfPbr + KHR_materials_transmission + _volume (absorbing)", &vol}})
    table += std::string("| ") + name + " | " + std::to_string(text->size()) + " |\n";
  std::ofstream(std::string(PT_BINARY_DIR) + "/lobes-table.md") << table;
  const auto doc = read_file(repo_path("docs/scenes.md"));
  REQUIRE(doc);
  INFO("docs/scenes.md: the extension-set table differs; the current one is in " << PT_BINARY_DIR << "/lobes-table.md");
  CHECK(doc->find(table) != std::string::npos);
}
