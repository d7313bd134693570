// A uniform buffer object holding constant data (render/uniform_tables.h: the build's
// tables), bound to a uniform-block binding point. Counted and generation-stamped as the
// other wrappers of gpu/ (gl_objects.h).
#pragma once
#include <cstddef>
#include <utility>

#include "gpu/gl.h"
#include "gpu/gl_objects.h"

namespace pt {

class UniformBuffer {
 public:
  UniformBuffer() = default;
  UniformBuffer(const void* data, size_t bytes);  // GL_STATIC_DRAW
  ~UniformBuffer() { reset(); }
  UniformBuffer(UniformBuffer&& o) noexcept : id_(std::exchange(o.id_, 0u)), made_in_(o.made_in_) {}
  UniformBuffer& operator=(UniformBuffer&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0u);
      made_in_ = o.made_in_;
    }
    return *this;
  }
  UniformBuffer(const UniformBuffer&) = delete;
  UniformBuffer& operator=(const UniformBuffer&) = delete;
  GLuint id() const { return id_; }
  bool stale() const { return gl_objects::stale(made_in_); }
  void bind(int binding) const;  // glBindBufferBase(GL_UNIFORM_BUFFER, binding, ...)

 private:
  void reset();
  GLuint id_ = 0;
  int made_in_ = gl_objects::generation();
};

}  // namespace pt
