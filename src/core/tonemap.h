// Tone maps, in the order of the ids in shaders/tonemap.glsl.
#pragma once
#include <cstring>

#define PT_TONEMAPS(X) \
  X(None, "none")      \
  X(Linear, "linear")  \
  X(Reinhard, "reinhard") \
  X(Filmic, "filmic")  \
  X(Srgb, "srgb")      \
  X(Uncharted2, "uncharted2") \
  X(Aces, "aces")

namespace pt {

enum class ToneMap : int {
#define PT_X(e, n) e,
  PT_TONEMAPS(PT_X)
#undef PT_X
};

inline constexpr const char* kToneMapNames[] = {
#define PT_X(e, n) n,
    PT_TONEMAPS(PT_X)
#undef PT_X
};
inline constexpr int kNumToneMaps = int(sizeof(kToneMapNames) / sizeof(kToneMapNames[0]));

inline bool tonemap_from_name(const char* name, ToneMap* out) {
  for (int i = 0; i < kNumToneMaps; ++i)
    if (!std::strcmp(name, kToneMapNames[i])) return *out = ToneMap(i), true;
  return false;
}

}  // namespace pt
