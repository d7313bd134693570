// GL error checks and resource limits.
//
// PT_GL_CHECK(what) after a GL call that can fail: in debug builds (no NDEBUG) and when
// PT_GL_CHECKS is defined (the native-asan preset, so CI runs every test with it), it
// reads glGetError and throws GlError naming the call, the source file and line. In
// release builds it is nothing: on WebGL glGetError is a round trip to the GPU process.
//
// GlLimits: what this context allows, queried once per context, never assumed; the
// renderer checks textures, units and draw buffers against it before creating them.
#pragma once
#include <stdexcept>
#include <string>

#include "gpu/gl.h"

namespace pt {

class GlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

#if !defined(NDEBUG) || defined(PT_GL_CHECKS)
inline constexpr bool kGlChecks = true;
#define PT_GL_CHECK(what) ::pt::gl_check(what, __FILE__, __LINE__)
#else
inline constexpr bool kGlChecks = false;
#define PT_GL_CHECK(what) ((void)0)
#endif

// Throws GlError if glGetError reports anything (all pending errors are drained).
void gl_check(const char* what, const char* file, int line);
const char* gl_error_name(GLenum e);

struct GlLimits {
  int max_texture_size = 0;   // GL_MAX_TEXTURE_SIZE
  int max_texture_units = 0;  // GL_MAX_TEXTURE_IMAGE_UNITS (fragment shader)
  int max_draw_buffers = 0;   // min(GL_MAX_DRAW_BUFFERS, GL_MAX_COLOR_ATTACHMENTS)
  int max_viewport[2] = {0, 0};
  static GlLimits query();  // needs a current context
  // Throws GlError naming the resource when a request exceeds a limit.
  void require_texture(int w, int h, const std::string& what) const;
  void require_units(int units, const std::string& what) const;
  void require_draw_buffers(int n, const std::string& what) const;
};

}  // namespace pt
