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

void UniformTables::make() {
  if (!buffers_.empty() && !buffers_[0].stale()) return;
  buffers_.clear();
  for (const UniformTable& u : uniform_tables()) buffers_.emplace_back(u.data, u.floats * sizeof(float));
}

void UniformTables::attach(const Program& p) {
  const auto& t = uniform_tables();
  for (size_t i = 0; i < t.size(); ++i) {
    const GLuint index = glGetUniformBlockIndex(p.id(), t[i].block);
    if (index != GL_INVALID_INDEX) glUniformBlockBinding(p.id(), index, GLuint(i));
  }
  PT_GL_CHECK("glUniformBlockBinding");
}

void UniformTables::bind() {
  make();
  for (size_t i = 0; i < buffers_.size(); ++i) buffers_[i].bind(int(i));
}

}  // namespace pt
