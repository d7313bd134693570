// A linked GL program with cached uniform locations. Compile and link errors throw with
// the log mapped back to the GLSL snippet file and its own line.
#pragma once
#include <chrono>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include <glm/glm.hpp>

#include "gpu/gl.h"
#include "gpu/gl_objects.h"
#include "gpu/gl_check.h"
#include "core/shader_source.h"

namespace pt {

class Program {
 public:
  Program() = default;
  Program(const ShaderSource& vs, const ShaderSource& fs);  // start() then finish()
  // Hands the sources to the driver and returns without asking for the result: with
  // KHR_parallel_shader_compile the driver compiles in the background (a page keeps
  // drawing frames meanwhile); completed() says when finish() will not block.
  static Program start(const ShaderSource& vs, const ShaderSource& fs);
#ifndef __EMSCRIPTEN__
  // A compute program (GL ES 3.1+), started the same way.
  static Program start_compute(const ShaderSource& cs);
#endif
  bool completed() const;
  // finish() has run (or the program was built at once): no shaders or sources are held.
  bool finished() const { return vs_ == 0; }
  // Waits for the result; throws GlError with the mapped log if compiling or linking failed.
  void finish();
  static bool parallel_compile();  // the driver offers KHR_parallel_shader_compile
  ~Program();
  Program(Program&& o) noexcept;
  Program& operator=(Program&& o) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  GLuint id() const { return id_; }
  void use() const {
    glUseProgram(id_);
    PT_GL_CHECK("glUseProgram");
  }
  GLint loc(const char* name);
  // A uniform set with the wrong type is GL_INVALID_OPERATION: checked with its name.
  void set(const char* name, int v) {
    glUniform1i(loc(name), v);
    PT_GL_CHECK(name);
  }
  void set(const char* name, float v) {
    glUniform1f(loc(name), v);
    PT_GL_CHECK(name);
  }
  void set(const char* name, glm::vec2 v) {
    glUniform2f(loc(name), v.x, v.y);
    PT_GL_CHECK(name);
  }
  void set(const char* name, glm::vec3 v) {
    glUniform3f(loc(name), v.x, v.y, v.z);
    PT_GL_CHECK(name);
  }
  void set(const char* name, glm::ivec2 v) {
    glUniform2i(loc(name), v.x, v.y);
    PT_GL_CHECK(name);
  }
  double compile_ms() const { return compile_ms_; }

 private:
  GLuint id_ = 0;
  GLuint vs_ = 0, fs_ = 0;  // until finish(): their logs name the snippet files (compute: vs_ only)
  ShaderSource vs_src_, fs_src_;
  std::chrono::steady_clock::time_point started_;
  std::unordered_map<std::string, GLint> locs_;
  double compile_ms_ = 0;
  int made_in_ = gl_objects::generation();  // names of a lost context are not deleted
};

}  // namespace pt
