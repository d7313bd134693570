// The direction chi-square test (direction_chi2.h), moved here from sampling_test.cpp.
#include "direction_chi2.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include "stats.h"

namespace pt {
namespace {

constexpr int kSamples = 1000000;
constexpr int kCosBins = 40, kPhiBins = 80, kSub = 5;

}  // namespace

Chi2Result direction_chi2(const DirectionCase& c, const char* name) {
  GlslKernel sampler(c.setup + "\nvec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 12345u), 0u);\n  vec3 wi = vec3(0.0);\n  bool ok = false;\n" +
                     c.sample + "\n  return ok ? vec4(wi, 1.0) : vec4(0.0);\n}\n",
                     c.features);
  GlslKernel density(c.setup + "\nvec4 kernel(vec4 x, int i) {\n  vec3 d = x.xyz;\n  return vec4(" + c.density + ");\n}\n", c.features);
  for (GlslKernel* k : {&sampler, &density}) {
    k->program().use();
    k->program().set("u_dot_weight", c.dot_weight);
    if (c.prepare) c.prepare(*k);
  }

  std::vector<double> observed(kCosBins * kPhiBins, 0.0), expected(kCosBins * kPhiBins, 0.0);
  for (const glm::vec4& s : sampler.run(kSamples)) {
    if (s.w == 0.0f) continue;
    const double z = std::clamp(double(s.z), -1.0, 1.0);
    double phi = std::atan2(double(s.y), double(s.x));
    if (phi < 0) phi += 2 * kPi;
    const int ci = std::min(kCosBins - 1, int((z + 1.0) * 0.5 * kCosBins));
    const int pi = std::min(kPhiBins - 1, int(phi / (2 * kPi) * kPhiBins));
    observed[size_t(ci * kPhiBins + pi)] += 1;
  }
  // Expected counts: integrate the density over each cell with a kSub x kSub midpoint rule;
  // cells where that is not enough (near a jump of the density to zero, such as a light's
  // silhouette, or where it varies by more than 2x, such as a grazing lobe) are integrated
  // again on a kFine x kFine grid: with 10^6 samples, a 1% error in a busy cell would fail.
  auto integrate = [&](const std::vector<int>& cells, int sub) {
    std::vector<glm::vec4> dirs;
    const double dc = 2.0 / kCosBins / sub, dp = 2 * kPi / kPhiBins / sub;
    for (int cell : cells)
      for (int a = 0; a < sub; ++a)
        for (int b = 0; b < sub; ++b) {
          const double z = -1.0 + ((cell / kPhiBins) * sub + a + 0.5) * dc;
          const double phi = ((cell % kPhiBins) * sub + b + 0.5) * dp, r = std::sqrt(std::max(0.0, 1 - z * z));
          dirs.emplace_back(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z), 0.0f);
        }
    const std::vector<glm::vec4> pdf = density.run(dirs);
    std::vector<glm::dvec3> out;  // per cell: integral, min, max of the samples
    for (size_t j = 0; j < cells.size(); ++j) {
      glm::dvec3 acc(0.0, INFINITY, 0.0);
      for (int k = 0; k < sub * sub; ++k) {
        const double v = pdf[j * size_t(sub * sub) + size_t(k)].x;
        acc.x += v * dc * dp;
        acc.y = std::min(acc.y, v);
        acc.z = std::max(acc.z, v);
      }
      out.push_back(acc);
    }
    return out;
  };
  constexpr int kFine = 128;
  std::vector<int> all(kCosBins * kPhiBins);
  for (int i = 0; i < int(all.size()); ++i) all[size_t(i)] = i;
  const std::vector<glm::dvec3> coarse = integrate(all, kSub);
  // A jump of the density (a light's silhouette, a bright texel of an environment map)
  // can hide between the midpoints of a cell: a cell is refined when its 3x3
  // neighbourhood is not uniform (its largest coarse value is over twice its smallest).
  // The cells of the first and last rows all meet at a pole, so there every cell of the
  // row is a neighbour (a density whose support ends near a pole, as a rough
  // dielectric's refraction, can leave a sliver in a cell whose own neighbours are empty).
  std::vector<int> refine;
  for (int i = 0; i < int(all.size()); ++i) {
    const int ci = i / kPhiBins, pi = i % kPhiBins;
    const int reach = ci == 0 || ci == kCosBins - 1 ? kPhiBins / 2 : 1;
    double lo = INFINITY, hi = 0.0;
    for (int dci = -1; dci <= 1; ++dci)
      for (int dpi = -reach; dpi <= reach; ++dpi) {
        const int nc = ci + dci;
        if (nc < 0 || nc >= kCosBins) continue;
        const glm::dvec3& n = coarse[size_t(nc * kPhiBins + (pi + dpi + kPhiBins) % kPhiBins)];
        lo = std::min(lo, n.y);
        hi = std::max(hi, n.z);
      }
    if (hi > 2.0 * lo && coarse[size_t(i)].z + hi > 0.0) refine.push_back(i);
    expected[size_t(i)] = coarse[size_t(i)].x * kSamples;
  }
  for (size_t first = 0; first < refine.size(); first += 128) {  // batches bound the memory
    const std::vector<int> batch(refine.begin() + long(first), refine.begin() + long(std::min(refine.size(), first + 128)));
    const std::vector<glm::dvec3> fine = integrate(batch, kFine);
    for (size_t k = 0; k < batch.size(); ++k) expected[size_t(batch[k])] = fine[k].x * kSamples;
  }
  if (std::getenv("PT_CHI2_DEBUG"))
    for (size_t j = 0; j < expected.size(); ++j)
      if (std::abs(observed[j] - expected[j]) > (std::getenv("PT_CHI2_DEBUG")[0] == '3' ? 3 : 5) * std::sqrt(expected[j] + 1))
        std::printf("  %s cell cos %zu phi %zu: observed %.0f expected %.1f\n", name, j / kPhiBins, j % kPhiBins, observed[j], expected[j]);
  if (std::getenv("PT_CHI2_DEBUG")) {
    double o = 0, e = 0;
    for (size_t j = 0; j < expected.size(); ++j) o += observed[j], e += expected[j];
    std::printf("  %s: observed %.0f expected %.1f in all\n", name, o, e);
  }
  const Chi2Result r = chi2_test(observed, expected);
  std::printf("chi2 %-42s stat %9.1f dof %4d pooled %4d refined %4zu p %.4f\n", name, r.stat, r.dof, r.pooled,
              refine.size(), r.p_value);
  // A sampler that never succeeds (or a density that is zero everywhere) leaves no cells
  // to test: that is a failure, not a pass.
  INFO(name << ": no samples or no density to compare");
  CHECK(r.dof > 0);
  return r;
}

std::string incident(double cos_theta) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "const vec3 WO = vec3(%.9f, 0.0, %.9f);\n", std::sqrt(1 - cos_theta * cos_theta), cos_theta);
  return buf;
}

const char* const kBsdfSample =
    "  BsdfSample s;\n  ok = material_sample(make_material(), WO, true, vec3(rand01(), rand01(), rand01()), s) && s.pdf > 0.0;\n"
    "  wi = s.wi;";
const char* const kBsdfDensity = "eval_pdf(d)";
const char* const kBsdfPdfHelper = "float eval_pdf(vec3 d) { float pdf; material_eval(make_material(), WO, d, true, pdf); return pdf; }\n";

}  // namespace pt
