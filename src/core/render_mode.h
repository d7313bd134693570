// Render modes, one list (like the tone maps). Each is its own generated program: the
// shader generator picks the mode's root GLSL file, which includes camera_pass.glsl and
// defines trace_path. The mode is part of the program cache key (Features::mode).
#pragma once
#include <cstring>

//  X(Enum, CLI name, root GLSL file, panel label)
#define PT_RENDER_MODES(X)                                             \
  X(PathTracer, "path", "integrator.glsl", "path tracer")              \
  X(Whitted, "whitted", "whitted.glsl", "ray tracer (Whitted)")        \
  X(SphericalHarmonics, "sh", "sh_irradiance.glsl", "SH irradiance")

namespace pt {

enum class RenderMode : int {
#define PT_X(e, n, f, l) e,
  PT_RENDER_MODES(PT_X)
#undef PT_X
};

inline constexpr const char* kRenderModeNames[] = {
#define PT_X(e, n, f, l) n,
    PT_RENDER_MODES(PT_X)
#undef PT_X
};
inline constexpr const char* kRenderModeRoots[] = {
#define PT_X(e, n, f, l) f,
    PT_RENDER_MODES(PT_X)
#undef PT_X
};
inline constexpr const char* kRenderModeLabels[] = {
#define PT_X(e, n, f, l) l,
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
