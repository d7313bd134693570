#include "gpu/texture.h"

#include "gpu/gl_check.h"
#include "gpu/gl_objects.h"

namespace pt {

Texture::Texture(int w, int h, GLenum internal_format, const float* data) : w_(w), h_(h) {
  glGenTextures(1, &id_);
  if (id_) gl_objects::created(gl_objects::kTexture);
  glBindTexture(GL_TEXTURE_2D, id_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  const GLenum type = internal_format == GL_RGBA8 ? GL_UNSIGNED_BYTE
                      : internal_format == GL_RGBA16F ? GL_HALF_FLOAT
                                                       : GL_FLOAT;
  if (!data && w > 0 && h > 0) {
    glTexStorage2D(GL_TEXTURE_2D, 1, internal_format, w, h);
    PT_GL_CHECK("glTexStorage2D");  // GL_OUT_OF_MEMORY, or a size over the limit
    return;
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal_format), w, h, 0, GL_RGBA, type,
               type == GL_FLOAT ? data : nullptr);
  PT_GL_CHECK("glTexImage2D");  // GL_OUT_OF_MEMORY, or a size over the limit
}

void Texture::bind(int unit) const {
  glActiveTexture(GLenum(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, id_);
  PT_GL_CHECK("glActiveTexture/glBindTexture");
}

void Texture::upload(const float* rgba) const {
  glBindTexture(GL_TEXTURE_2D, id_);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w_, h_, GL_RGBA, GL_FLOAT, rgba);
  PT_GL_CHECK("glTexSubImage2D");
}

void Texture::reset() {
  if (id_) {
    if (!gl_objects::stale(made_in_)) glDeleteTextures(1, &id_);
    gl_objects::deleted(gl_objects::kTexture);
  }
  id_ = 0;
}

Framebuffer::Framebuffer(const Texture& color) {
  glGenFramebuffers(1, &id_);
  if (id_) gl_objects::created(gl_objects::kFramebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, id_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
  PT_GL_CHECK("glFramebufferTexture2D");
}

Framebuffer::Framebuffer(const Texture& color0, const Texture& color1) : Framebuffer(color0) {
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, color1.id(), 0);
  const GLenum bufs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, bufs);
  PT_GL_CHECK("glFramebufferTexture2D/glDrawBuffers");
}

Framebuffer::Framebuffer(const Texture& color0, const Texture& color1, const Texture& color2) : Framebuffer(color0) {
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, color1.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_TEXTURE_2D, color2.id(), 0);
  const GLenum bufs[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glDrawBuffers(3, bufs);
  PT_GL_CHECK("glFramebufferTexture2D/glDrawBuffers");
}

void Framebuffer::attach_depth(const Texture& depth) const {
  glBindFramebuffer(GL_FRAMEBUFFER, id_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth.id(), 0);
  PT_GL_CHECK("glFramebufferTexture2D (depth)");
}

bool Framebuffer::complete() const {
  glBindFramebuffer(GL_FRAMEBUFFER, id_);
  return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

void Framebuffer::reset() {
  if (id_) {
    if (!gl_objects::stale(made_in_)) glDeleteFramebuffers(1, &id_);
    gl_objects::deleted(gl_objects::kFramebuffer);
  }
  id_ = 0;
}

std::vector<float> read_rgba_float(GLuint fbo, int attachment, int w, int h) {
  std::vector<float> out(size_t(w) * size_t(h) * 4);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + attachment));
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, out.data());
  PT_GL_CHECK("glReadPixels (float attachment)");
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return out;
}

}  // namespace pt
