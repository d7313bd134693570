// RAII float textures and framebuffers: the only GL objects the renderer owns.
#pragma once
#include <vector>
#include <utility>

#include "gpu/gl.h"
#include "gpu/gl_objects.h"

namespace pt {

class Texture {
 public:
  Texture() = default;
  // RGBA float texture, nearest filtering; `data` may be null: then the storage is
  // immutable (glTexStorage2D), so a compute kernel can bind it as an image.
  Texture(int w, int h, GLenum internal_format, const float* data);
  ~Texture() { reset(); }
  Texture(Texture&& o) noexcept : id_(std::exchange(o.id_, 0u)), w_(o.w_), h_(o.h_), made_in_(o.made_in_) {}
  Texture& operator=(Texture&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0u);
      w_ = o.w_;
      h_ = o.h_;
      made_in_ = o.made_in_;
    }
    return *this;
  }
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;
  GLuint id() const { return id_; }
  int width() const { return w_; }
  int height() const { return h_; }
  void bind(int unit) const;
  // Replaces the whole image of an RGBA32F texture (same size): no new GL object.
  void upload(const float* rgba) const;

 private:
  void reset();
  GLuint id_ = 0;
  int w_ = 0, h_ = 0;
  int made_in_ = gl_objects::generation();
};

class Framebuffer {
 public:
  Framebuffer() = default;
  explicit Framebuffer(const Texture& color);
  // Two colour attachments, both drawn to (multiple render targets).
  Framebuffer(const Texture& color0, const Texture& color1);
  // Three colour attachments, all drawn to.
  Framebuffer(const Texture& color0, const Texture& color1, const Texture& color2);
  // Attaches a depth texture (its internal format a depth format) to this framebuffer.
  void attach_depth(const Texture& depth) const;
  ~Framebuffer() { reset(); }
  Framebuffer(Framebuffer&& o) noexcept : id_(std::exchange(o.id_, 0u)), made_in_(o.made_in_) {}
  Framebuffer& operator=(Framebuffer&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0u);
      made_in_ = o.made_in_;
    }
    return *this;
  }
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;
  GLuint id() const { return id_; }
  bool complete() const;

 private:
  void reset();
  GLuint id_ = 0;
  int made_in_ = gl_objects::generation();
};

// The w x h RGBA float pixels of colour attachment `attachment` (0, 1, ...) of framebuffer
// `fbo`; leaves the default framebuffer bound and attachment 0 as the read buffer.
std::vector<float> read_rgba_float(GLuint fbo, int attachment, int w, int h);

}  // namespace pt
