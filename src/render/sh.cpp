#include "render/sh.h"

#include <cmath>
#include <vector>

namespace pt {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Normalisations of the real SH basis up to l = 2.
constexpr double k00 = 0.28209479177387814;  // 1 / (2 sqrt(pi))
constexpr double k1 = 0.48860251190291992;   // sqrt(3 / (4 pi))
constexpr double k2 = 1.09254843059207907;   // sqrt(15 / (4 pi))
constexpr double k20 = 0.31539156525252001;  // sqrt(5 / (16 pi))
constexpr double k22 = 0.54627421529603954;  // sqrt(15 / (16 pi))

}  // namespace

std::array<float, 9> sh_basis(glm::vec3 d) {
  const double x = d.x, y = d.y, z = d.z;
  return {float(k00),           float(k1 * y),     float(k1 * z),
          float(k1 * x),        float(k2 * x * y), float(k2 * y * z),
          float(k20 * (3 * z * z - 1)), float(k2 * x * z), float(k22 * (x * x - y * y))};
}

ShCoeffs project_sh(const Environment& env) {
  ShCoeffs out;
  out.fill(glm::vec3(0.0f));
  if (!env.map) {  // constant radiance: only L00 = 4 pi Y00 L
    out[0] = env.color * float(4.0 * kPi * k00);
    return out;
  }
  const EnvImage& m = *env.map;
  const int w = m.width, h = m.height;
  // Directions as in shaders/environment.glsl: d = (sin t cos p, cos t, sin t sin p),
  // texel (i, j) spans t in [pi j / h, pi (j + 1) / h], p in 2 pi [i, i + 1] / w + rotation.
  // Every monomial of degree <= 2 integrates over a texel in closed form as a product of
  // a theta factor and a phi factor (each with the sin t of the solid angle).
  const double rot = env.rotation * kPi / 180.0;
  enum { P0, Pc, Ps, Pcc, Pss, Pcs, NP };
  std::vector<double> P(size_t(w) * NP);
  for (int i = 0; i < w; ++i) {
    const double a = 2 * kPi * i / w + rot, b = 2 * kPi * (i + 1) / w + rot;
    double* p = &P[size_t(i) * NP];
    p[P0] = b - a;
    p[Pc] = std::sin(b) - std::sin(a);
    p[Ps] = std::cos(a) - std::cos(b);
    p[Pcc] = (b - a) / 2 + (std::sin(2 * b) - std::sin(2 * a)) / 4;
    p[Pss] = (b - a) / 2 - (std::sin(2 * b) - std::sin(2 * a)) / 4;
    p[Pcs] = (std::sin(b) * std::sin(b) - std::sin(a) * std::sin(a)) / 2;
  }
  double c[9][3] = {};
  for (int j = 0; j < h; ++j) {
    const double t0 = kPi * j / h, t1 = kPi * (j + 1) / h;
    const double c0 = std::cos(t0), c1 = std::cos(t1), s0 = std::sin(t0), s1 = std::sin(t1);
    const double T0 = c0 - c1;                                           // sin
    const double Tc = (s1 * s1 - s0 * s0) / 2;                           // cos sin
    const double Ts = (t1 - t0) / 2 - (std::sin(2 * t1) - std::sin(2 * t0)) / 4;  // sin^2
    const double Tss = (-c1 + c1 * c1 * c1 / 3) - (-c0 + c0 * c0 * c0 / 3);       // sin^3
    const double Tcs = (s1 * s1 * s1 - s0 * s0 * s0) / 3;               // cos sin^2
    const double Tcc = (c0 * c0 * c0 - c1 * c1 * c1) / 3;               // cos^2 sin
    for (int ch = 0; ch < 3; ++ch) {
      double S[NP] = {};  // sum over the row of radiance * phi factor
      for (int i = 0; i < w; ++i) {
        const double L = m.rgba[(size_t(j) * w + size_t(i)) * 4 + size_t(ch)];
        const double* p = &P[size_t(i) * NP];
        for (int q = 0; q < NP; ++q) S[q] += L * p[q];
      }
      // Integrals of L times 1, x, y, z, xy, yz, xz, x^2, y^2, z^2 over the row.
      const double one = T0 * S[P0], x = Ts * S[Pc], y = Tc * S[P0], z = Ts * S[Ps];
      const double xy = Tcs * S[Pc], yz = Tcs * S[Ps], xz = Tss * S[Pcs];
      const double xx = Tss * S[Pcc], yy = Tcc * S[P0], zz = Tss * S[Pss];
      c[0][ch] += k00 * one;
      c[1][ch] += k1 * y;
      c[2][ch] += k1 * z;
      c[3][ch] += k1 * x;
      c[4][ch] += k2 * xy;
      c[5][ch] += k2 * yz;
      c[6][ch] += k20 * (3 * zz - one);
      c[7][ch] += k2 * xz;
      c[8][ch] += k22 * (xx - yy);
    }
  }
  for (int k = 0; k < 9; ++k) out[size_t(k)] = glm::vec3(float(c[k][0]), float(c[k][1]), float(c[k][2])) * env.intensity;
  return out;
}

glm::vec3 sh_irradiance(const ShCoeffs& c, glm::vec3 n) {
  const std::array<float, 9> y = sh_basis(n);
  glm::vec3 e(0.0f);
  for (int i = 0; i < 9; ++i) e += kShA[sh_band(i)] * c[size_t(i)] * y[size_t(i)];
  return e;
}

}  // namespace pt
