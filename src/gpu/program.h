// A linked GL program with cached uniform locations. Compile and link errors throw with
// the log mapped back to the GLSL snippet file and its own line.
#pragma once
#include <stdexcept>
#include <string>
#include <unordered_map>

#include <glm/glm.hpp>

#include "gpu/gl.h"
#include "gpu/gl_check.h"
#include "shadergen/shadergen.h"

namespace pt {

class Program {
 public:
  Program() = default;
  Program(const ShaderSource& vs, const ShaderSource& fs);
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
  std::unordered_map<std::string, GLint> locs_;
  double compile_ms_ = 0;
};

}  // namespace pt
