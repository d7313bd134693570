#include "gpu/uniform_buffer.h"

#include "gpu/gl_check.h"

namespace pt {

UniformBuffer::UniformBuffer(const void* data, size_t bytes) {
  glGenBuffers(1, &id_);
  if (id_) gl_objects::created(gl_objects::kBuffer);
  glBindBuffer(GL_UNIFORM_BUFFER, id_);
  glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(bytes), data, GL_STATIC_DRAW);
  glBindBuffer(GL_UNIFORM_BUFFER, 0);
  PT_GL_CHECK("glBufferData (uniform buffer)");
}

void UniformBuffer::bind(int binding) const {
  glBindBufferBase(GL_UNIFORM_BUFFER, GLuint(binding), id_);
  PT_GL_CHECK("glBindBufferBase");
}

void UniformBuffer::reset() {
  if (id_) {
    if (!gl_objects::stale(made_in_)) glDeleteBuffers(1, &id_);
    gl_objects::deleted(gl_objects::kBuffer);
  }
  id_ = 0;
}

}  // namespace pt
