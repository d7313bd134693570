#include "render/uniform_tables.h"

#include "gpu/gl_check.h"

namespace pt {
namespace {

// The generated initialisers (cmake/EmbedGlsl.cmake, in the build's generated/ folder).
const float kGgxMs[] = {
#include "materials/gltf_ms_lut.inc"
};
const float kSheen[] = {
#include "materials/gltf_sheen_lut.inc"
};

}  // namespace

const std::vector<UniformTable>& uniform_tables() {
  static const std::vector<UniformTable> t = {
      {"GgxMsTable", kGgxMs, sizeof(kGgxMs) / sizeof(float)},
      {"SheenTable", kSheen, sizeof(kSheen) / sizeof(float)},
  };
  return t;
}

void UniformTables::bind(const Program& p) {
  const auto& t = uniform_tables();
  if (buffers_.empty() || buffers_[0].stale()) {  // first use, or a new context
    buffers_.clear();
    for (const UniformTable& u : t) buffers_.emplace_back(u.data, u.floats * sizeof(float));
  }
  for (size_t i = 0; i < t.size(); ++i) {
    const GLuint index = glGetUniformBlockIndex(p.id(), t[i].block);
    if (index != GL_INVALID_INDEX) glUniformBlockBinding(p.id(), index, GLuint(i));
    buffers_[i].bind(int(i));
  }
  PT_GL_CHECK("glUniformBlockBinding");
}

}  // namespace pt
