// RAII GL_TEXTURE_2D_ARRAY of RGBA16F layers with bilinear filtering and wrap = repeat:
// the storage of image maps (see render/image_maps.h).
#pragma once
#include <utility>

#include "gpu/gl.h"
#include "gpu/gl_objects.h"

namespace pt {

class TextureArray {
 public:
  TextureArray() = default;
  // `rgba` holds layers * height rows of width RGBA floats (converted to half floats).
  TextureArray(int width, int height, int layers, const float* rgba);
  ~TextureArray() { reset(); }
  TextureArray(TextureArray&& o) noexcept : id_(std::exchange(o.id_, 0u)), made_in_(o.made_in_) {}
  TextureArray& operator=(TextureArray&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0u);
      made_in_ = o.made_in_;
    }
    return *this;
  }
  TextureArray(const TextureArray&) = delete;
  TextureArray& operator=(const TextureArray&) = delete;
  GLuint id() const { return id_; }
  void bind(int unit) const;

  // The current context's limits (GL_MAX_TEXTURE_SIZE, GL_MAX_ARRAY_TEXTURE_LAYERS).
  static int max_size();
  static int max_layers();

 private:
  void reset();
  GLuint id_ = 0;
  int made_in_ = gl_objects::generation();
};

}  // namespace pt
