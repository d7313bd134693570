#include "gpu/program.h"

#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "core/file_io.h"
#include "gpu/gl_objects.h"

namespace pt {
namespace {

constexpr GLenum kCompletionStatus = 0x91B1;  // GL_COMPLETION_STATUS_KHR

#ifndef __EMSCRIPTEN__
// A diagnostic of the native build (docs/benchmarks.md, "What limits speed now"): with
// PT_DUMP_PROGRAMS=DIR every linked program writes DIR/program-N.glsl (its fragment or
// compute source as compiled) and DIR/program-N.bin (the driver's program binary, where
// NVIDIA's holds its compiled code and resource counts). Off (null) unless set.
const char* dump_dir() {
  const char* d = std::getenv("PT_DUMP_PROGRAMS");
  return d && *d ? d : nullptr;
}

void dump_program(GLuint id, const ShaderSource& src) {
  static int n = 0;
  const std::string stem = std::string(dump_dir()) + "/program-" + std::to_string(n++);
  write_file_atomic(stem + ".glsl", src.text.data(), src.text.size());
  GLint len = 0;
  glGetProgramiv(id, GL_PROGRAM_BINARY_LENGTH, &len);
  if (len <= 0) return;
  std::vector<char> bin(static_cast<size_t>(len));
  GLenum format = 0;
  glGetProgramBinary(id, len, nullptr, &format, bin.data());
  write_file_atomic(stem + ".bin", bin.data(), bin.size());
}
#endif

// The info log of a shader or program object (the two GL families share a shape).
template <typename GetIv, typename GetLog>
std::string info_log(GLuint object, GetIv get_iv, GetLog get_log) {
  GLint len = 0;
  get_iv(object, GL_INFO_LOG_LENGTH, &len);
  std::vector<char> log(size_t(len > 1 ? len : 1), '\0');
  get_log(object, GLsizei(log.size()), nullptr, log.data());
  return log.data();
}

GLuint start_shader(GLenum type, const ShaderSource& src) {
  GLuint s = glCreateShader(type);
  if (s) gl_objects::created(gl_objects::kShader);
  const char* text = src.text.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  PT_GL_CHECK("glShaderSource/glCompileShader");
  return s;
}

// Throws with the mapped log if the shader did not compile.
void check_shader(GLuint s, const ShaderSource& src) {
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) throw GlError("GLSL compile error:\n" + src.map_log(info_log(s, glGetShaderiv, glGetShaderInfoLog)));
}

}  // namespace

bool Program::parallel_compile() {
  static const bool has = [] {
    GLint n = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; i < n; ++i) {
      const char* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
      if (e && !std::strcmp(e, "GL_KHR_parallel_shader_compile")) return true;
    }
    return false;
  }();
  return has;
}

Program::Program(const ShaderSource& vs, const ShaderSource& fs) : Program(start(vs, fs)) { finish(); }

Program Program::start(const ShaderSource& vs, const ShaderSource& fs) {
  Program p;
  p.started_ = std::chrono::steady_clock::now();
  p.vs_src_ = vs;
  p.fs_src_ = fs;
  p.vs_ = start_shader(GL_VERTEX_SHADER, vs);
  p.fs_ = start_shader(GL_FRAGMENT_SHADER, fs);
  p.id_ = glCreateProgram();
  if (p.id_) gl_objects::created(gl_objects::kProgram);
  glAttachShader(p.id_, p.vs_);
  glAttachShader(p.id_, p.fs_);
#ifndef __EMSCRIPTEN__
  if (dump_dir()) glProgramParameteri(p.id_, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
#endif
  glLinkProgram(p.id_);
  PT_GL_CHECK("glAttachShader/glLinkProgram");
  return p;
}

#ifndef __EMSCRIPTEN__
Program Program::start_compute(const ShaderSource& cs) {
  Program p;
  p.started_ = std::chrono::steady_clock::now();
  p.vs_src_ = cs;
  p.vs_ = start_shader(GL_COMPUTE_SHADER, cs);
  p.id_ = glCreateProgram();
  if (p.id_) gl_objects::created(gl_objects::kProgram);
  glAttachShader(p.id_, p.vs_);
  if (dump_dir()) glProgramParameteri(p.id_, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
  glLinkProgram(p.id_);
  PT_GL_CHECK("glAttachShader/glLinkProgram (compute)");
  return p;
}
#endif

bool Program::completed() const {
  if (!vs_ || !parallel_compile()) return true;  // finished, or finish() is the only way to know
  GLint done = 0;
  glGetProgramiv(id_, kCompletionStatus, &done);
  return done != 0;
}

void Program::finish() {
  if (!vs_) return;
  const GLuint v = std::exchange(vs_, 0u), f = std::exchange(fs_, 0u);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  std::string error;
  if (!ok) {
    // The shaders' own logs first (a compile error names the snippet file), else the link log.
    try {
      check_shader(v, vs_src_);
      if (f) check_shader(f, fs_src_);
      error = "GLSL link error:\n" + (f ? fs_src_ : vs_src_).map_log(info_log(id_, glGetProgramiv, glGetProgramInfoLog));
    } catch (const GlError& e) {
      error = e.what();
    }
  }
#ifndef __EMSCRIPTEN__
  if (error.empty() && dump_dir()) dump_program(id_, f ? fs_src_ : vs_src_);
#endif
  glDeleteShader(v);
  gl_objects::deleted(gl_objects::kShader);
  if (f) glDeleteShader(f), gl_objects::deleted(gl_objects::kShader);
  vs_src_ = fs_src_ = ShaderSource{};
  if (!error.empty()) {
    glDeleteProgram(id_);
    gl_objects::deleted(gl_objects::kProgram);
    id_ = 0;
    throw GlError(error);
  }
  compile_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started_).count();
}

Program::~Program() {
  const bool live = !gl_objects::stale(made_in_);
  for (const GLuint s : {vs_, fs_})
    if (s) {
      if (live) glDeleteShader(s);
      gl_objects::deleted(gl_objects::kShader);
    }
  if (id_) {
    if (live) glDeleteProgram(id_);
    gl_objects::deleted(gl_objects::kProgram);
  }
}

Program::Program(Program&& o) noexcept
    : id_(std::exchange(o.id_, 0u)), vs_(std::exchange(o.vs_, 0u)), fs_(std::exchange(o.fs_, 0u)),
      vs_src_(std::move(o.vs_src_)), fs_src_(std::move(o.fs_src_)), started_(o.started_),
      locs_(std::move(o.locs_)), compile_ms_(o.compile_ms_), made_in_(o.made_in_) {}

Program& Program::operator=(Program&& o) noexcept {
  if (this != &o) {
    Program old(std::move(*this));  // deletes what this held, on return
    id_ = std::exchange(o.id_, 0u);
    vs_ = std::exchange(o.vs_, 0u);
    fs_ = std::exchange(o.fs_, 0u);
    vs_src_ = std::move(o.vs_src_);
    fs_src_ = std::move(o.fs_src_);
    started_ = o.started_;
    locs_ = std::move(o.locs_);
    compile_ms_ = o.compile_ms_;
    made_in_ = o.made_in_;
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
