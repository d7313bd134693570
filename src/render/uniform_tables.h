// The build's constant tables (tools/gen_ggx_ms_lut.py: the GGX albedos of the glTF
// BSDF's multiple-scattering compensation; tools/gen_sheen_lut.py: the sheen albedo) as
// uniform blocks, one list. A table a shader indexes at run time is never a constant array
// in the GLSL: NVIDIA's compiler keeps such an array in per-invocation local memory,
// written at the start of every invocation and read back through the cache, which cost the
// glTF BSDF's rough lobes 20-40x on the H200 (docs/benchmarks.md, "Constant tables out of
// local memory"). bind() gives each block of a program its binding point and binds the
// buffers, made once per GL context.
#pragma once
#include <vector>

#include "gpu/program.h"
#include "gpu/uniform_buffer.h"

namespace pt {

struct UniformTable {
  const char* block;  // the GLSL uniform block's name
  const float* data;  // std140: vec4 arrays, so plain floats in order
  size_t floats;
};
const std::vector<UniformTable>& uniform_tables();

class UniformTables {
 public:
  // Before a draw with program p (in use or not): its blocks of the list get their
  // binding points (the list's index) and every buffer is bound to its point.
  void bind(const Program& p);

 private:
  std::vector<UniformBuffer> buffers_;
};

}  // namespace pt
