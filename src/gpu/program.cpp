#include "gpu/program.h"

#include <chrono>
#include <vector>

namespace pt {
namespace {

// The info log of a shader or program object (the two GL families share a shape).
template <typename GetIv, typename GetLog>
std::string info_log(GLuint object, GetIv get_iv, GetLog get_log) {
  GLint len = 0;
  get_iv(object, GL_INFO_LOG_LENGTH, &len);
  std::vector<char> log(size_t(len > 1 ? len : 1), '\0');
  get_log(object, GLsizei(log.size()), nullptr, log.data());
  return log.data();
}

GLuint compile(GLenum type, const ShaderSource& src) {
  GLuint s = glCreateShader(type);
  const char* text = src.text.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  PT_GL_CHECK("glShaderSource/glCompileShader");
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(s, glGetShaderiv, glGetShaderInfoLog);
    glDeleteShader(s);
    throw GlError("GLSL compile error:\n" + src.map_log(log));
  }
  return s;
}

}  // namespace

Program::Program(const ShaderSource& vs, const ShaderSource& fs) {
  const auto t0 = std::chrono::steady_clock::now();
  GLuint v = compile(GL_VERTEX_SHADER, vs);
  GLuint f = 0;
  try {
    f = compile(GL_FRAGMENT_SHADER, fs);
  } catch (...) {
    glDeleteShader(v);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, v);
  glAttachShader(id_, f);
  glLinkProgram(id_);
  PT_GL_CHECK("glAttachShader/glLinkProgram");
  glDeleteShader(v);
  glDeleteShader(f);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(id_, glGetProgramiv, glGetProgramInfoLog);
    glDeleteProgram(id_);
    id_ = 0;
    throw GlError("GLSL link error:\n" + fs.map_log(log));
  }
  compile_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

Program::Program(Program&& o) noexcept : id_(o.id_), locs_(std::move(o.locs_)), compile_ms_(o.compile_ms_) { o.id_ = 0; }

Program& Program::operator=(Program&& o) noexcept {
  if (this != &o) {
    if (id_) glDeleteProgram(id_);
    id_ = o.id_;
    locs_ = std::move(o.locs_);
    compile_ms_ = o.compile_ms_;
    o.id_ = 0;
  }
  return *this;
}

GLint Program::loc(const char* name) {
  auto it = locs_.find(name);
  if (it != locs_.end()) return it->second;
  const GLint l = glGetUniformLocation(id_, name);
  locs_.emplace(name, l);
  return l;
}

}  // namespace pt
