#include "gpu/gl_check.h"

namespace pt {

const char* gl_error_name(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown GL error";
  }
}

void gl_check(const char* what, const char* file, int line) {
  std::string errors;
  // A lost context reports GL_CONTEXT_LOST forever on WebGL: bound the drain.
  for (int i = 0; i < 8; ++i) {
    const GLenum e = glGetError();
    if (e == GL_NO_ERROR) break;
    errors += (errors.empty() ? "" : ", ") + std::string(gl_error_name(e));
  }
  if (!errors.empty()) throw GlError(std::string(file) + ":" + std::to_string(line) + ": " + what + ": " + errors);
}

GlLimits GlLimits::query() {
  GlLimits l;
  GLint attachments = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &l.max_texture_size);
  glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &l.max_texture_units);
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &l.max_draw_buffers);
  glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &attachments);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, l.max_viewport);
  if (attachments < l.max_draw_buffers) l.max_draw_buffers = attachments;
  return l;
}

void GlLimits::require_texture(int w, int h, const std::string& what) const {
  if (w < 1 || h < 1 || w > max_texture_size || h > max_texture_size)
    throw GlError(what + " needs a " + std::to_string(w) + "x" + std::to_string(h) +
                  " texture; this GPU allows at most " + std::to_string(max_texture_size) + " (GL_MAX_TEXTURE_SIZE)");
}

void GlLimits::require_units(int units, const std::string& what) const {
  if (units > max_texture_units)
    throw GlError(what + " needs " + std::to_string(units) + " texture units; this GPU has " +
                  std::to_string(max_texture_units) + " (GL_MAX_TEXTURE_IMAGE_UNITS)");
}

void GlLimits::require_draw_buffers(int n, const std::string& what) const {
  if (n > max_draw_buffers)
    throw GlError(what + " needs " + std::to_string(n) + " draw buffers; this GPU has " + std::to_string(max_draw_buffers) +
                  " (GL_MAX_DRAW_BUFFERS / GL_MAX_COLOR_ATTACHMENTS)");
}

}  // namespace pt
