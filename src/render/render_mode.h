// Render modes, one list (like the tone maps). Each is its own generated program: the
// shader generator picks the mode's root GLSL file, which includes camera_pass.glsl and
// defines trace_path. The mode is part of the program cache key (Features::mode).
#pragma once
#include <cstring>

//  X(Enum, CLI and panel name, root GLSL file)
#define PT_RENDER_MODES(X)                      \
  X(PathTracer, "path", "integrator.glsl")      \
  X(Whitted, "whitted", "whitted.glsl")         \
  X(SphericalHarmonics, "sh", "sh_irradiance.glsl")

namespace pt {

enum class RenderMode : int {
#define PT_X(e, n, f) e,
  PT_RENDER_MODES(PT_X)
#undef PT_X
};

inline constexpr const char* kRenderModeNames[] = {
#define PT_X(e, n, f) n,
    PT_RENDER_MODES(PT_X)
#undef PT_X
};
inline constexpr const char* kRenderModeRoots[] = {
#define PT_X(e, n, f) f,
    PT_RENDER_MODES(PT_X)
#undef PT_X
};
inline constexpr int kNumRenderModes = int(sizeof(kRenderModeNames) / sizeof(kRenderModeNames[0]));

inline bool render_mode_from_name(const char* name, RenderMode* out) {
  for (int i = 0; i < kNumRenderModes; ++i)
    if (!std::strcmp(name, kRenderModeNames[i])) return *out = RenderMode(i), true;
  return false;
}

}  // namespace pt
