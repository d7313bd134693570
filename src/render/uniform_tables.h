// The build's constant tables (tools/gen_ggx_ms_lut.py: the GGX albedos of the glTF
// BSDF's multiple-scattering compensation; tools/gen_sheen_lut.py: the sheen albedo) as
// uniform blocks, one list. A table a shader indexes at run time is never a constant array
// in the GLSL: NVIDIA's compiler keeps such an array in per-invocation local memory,
// written at the start of every invocation and read back through the cache, which made the
// glTF scenes 15-19x slower on the H200 (docs/benchmarks.md, "Constant tables out of local
// memory"). attach() gives a linked program's blocks their binding points (program state:
// once per program); bind() binds the buffers, made once per GL context, to those points.
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
  // Once a program is linked (and chosen): its blocks of the list get their binding
  // points, the list's index (glUniformBlockBinding is the program's state, kept).
  void attach(const Program& p);
  // Before a draw: every buffer bound to its point (context state, cheap).
  void bind();

 private:
  void make();  // the buffers, on first use and in a new context
  std::vector<UniformBuffer> buffers_;
};

}  // namespace pt
