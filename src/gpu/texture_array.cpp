#include "gpu/texture_array.h"

#include "gpu/gl_objects.h"

namespace pt {

TextureArray::TextureArray(int width, int height, int layers, const float* rgba) {
  glGenTextures(1, &id_);
  if (id_) gl_objects::created(gl_objects::kTexture);
  glBindTexture(GL_TEXTURE_2D_ARRAY, id_);
  // No mipmaps: a path tracer's secondary rays have no screen-space footprint to pick a
  // level from; the progressive average over the pixel does the filtering.
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA16F, width, height, layers, 0, GL_RGBA, GL_FLOAT, rgba);
}

void TextureArray::bind(int unit) const {
  glActiveTexture(GLenum(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D_ARRAY, id_);
}

void TextureArray::reset() {
  if (id_) {
    if (!gl_objects::stale(made_in_)) glDeleteTextures(1, &id_);
    gl_objects::deleted(gl_objects::kTexture);
  }
  id_ = 0;
}

int TextureArray::max_size() {
  GLint v = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &v);
  return v;
}

int TextureArray::max_layers() {
  GLint v = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &v);
  return v;
}

}  // namespace pt
