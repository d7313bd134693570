#include "core/sobol.h"

namespace pt {

std::array<uint32_t, kSobolDims * 32> sobol_directions() {
  // Dimension 0 is van der Corput; 1..3 follow new-joe-kuo-6.21201: (s, a, m_1..m_s).
  struct Poly {
    int s;
    uint32_t a;
    uint32_t m[3];
  };
  const Poly polys[3] = {{1, 0, {1, 0, 0}}, {2, 1, {1, 3, 0}}, {3, 1, {1, 3, 1}}};
  std::array<uint32_t, kSobolDims * 32> v{};
  for (int k = 0; k < 32; ++k) v[size_t(k)] = 1u << (31 - k);
  for (int d = 1; d < kSobolDims; ++d) {
    const Poly& p = polys[d - 1];
    uint32_t* vd = &v[size_t(d) * 32];
    for (int k = 0; k < 32; ++k) {
      if (k < p.s) {
        vd[k] = p.m[k] << (31 - k);
        continue;
      }
      vd[k] = vd[k - p.s] ^ (vd[k - p.s] >> p.s);
      for (int j = 1; j < p.s; ++j)
        if ((p.a >> (p.s - 1 - j)) & 1u) vd[k] ^= vd[k - j];
    }
  }
  return v;
}

uint32_t sobol_sample(uint32_t index, int dim) {
  static const auto v = sobol_directions();
  uint32_t x = 0;
  for (int bit = 0; index != 0; ++bit, index >>= 1)
    if (index & 1u) x ^= v[size_t(dim) * 32 + size_t(bit)];
  return x;
}

std::string glsl_sobol_dims() {
  const auto v = sobol_directions();
  // As immediates, never an array: a GPU compiler that keeps a loop over a constant array
  // puts the array in per-invocation local memory (NVIDIA's does: 128 words written at the
  // start of every invocation and read back from cache; docs/benchmarks.md, "Constant
  // tables out of local memory").
  std::string s = "uvec3 sobol_dims123(uint index) {\n  uvec3 x = uvec3(0u);\n";
  for (int bit = 0; bit < 32; ++bit) {
    s += "  x ^= (0u - ((index >> " + std::to_string(bit) + "u) & 1u)) & uvec3(";
    for (int d = 1; d < 4; ++d) s += std::to_string(v[size_t(d) * 32 + size_t(bit)]) + (d < 3 ? "u, " : "u);\n");
  }
  return s + "  return x;\n}\n";
}

}  // namespace pt
