#pragma once
// Live GL objects made through the wrappers of gpu/ (and the renderer's vertex array):
// created minus deleted, per kind. The page reports them (App::stats_json, "glObjects")
// so that the long-use browser test (tests/browser/endurance_test.mjs) can check that
// loads, context losses and edits do not leak GL objects. Each wrapper also keeps the
// context generation its name was made in (below).
#include <array>

namespace pt::gl_objects {

enum Kind { kTexture, kFramebuffer, kProgram, kShader, kVertexArray, kBuffer, kKinds };
inline constexpr std::array<const char*, kKinds> kNames = {"textures", "framebuffers", "programs", "shaders", "vertexArrays", "buffers"};

inline std::array<int, kKinds>& live() {
  static std::array<int, kKinds> counts{};
  return counts;
}
inline void created(Kind k) { ++live()[k]; }
inline void deleted(Kind k) { --live()[k]; }

// The GL context's generation: a lost and restored context (the page) starts a new one.
// A name made in an earlier generation is stale: deleting it is not passed to GL (WebGL
// warns "object does not belong to this context" for each), only counted.
inline int& generation() {
  static int g = 0;
  return g;
}
inline void context_replaced() { ++generation(); }
inline bool stale(int made_in) { return made_in != generation(); }

}  // namespace pt::gl_objects
