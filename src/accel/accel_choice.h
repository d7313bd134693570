// The acceleration a scene's program traverses: its BVH (accel/bvh.h), or none - every ray
// tests every primitive in one plain loop (shaders/bvh.glsl, HAS_FLAT). A program
// feature (shadergen.h: Features::flat), chosen per scene by its primitive count unless
// the user says (--accel, the page's accel=). The packing is the same either way: the
// primitives stay in the BVH's leaf order, so the two loops differ only in the order they
// test them (the same nearest hit but for exact ties of t).
#pragma once
#include <cstring>

namespace pt {

enum class Accel { Auto, Bvh, Flat };
inline constexpr const char* kAccelNames[] = {"auto", "bvh", "flat"};

// `auto`'s rule: flat for a scene of at most this many primitives (each triangle of a mesh
// counts, and each plane), else the BVH. Measured (docs/benchmarks.md, "Fragment-pass
// steps (issue 17)"): bvh against flat at 256x256, 8 bounces, interleaved, on llvmpipe
// (fragment and compute kernels) and SwiftShader (the page), on scenes of N random boxes
// and spheres in a closed room; flat was faster up to about this N on both.
inline constexpr long kFlatMaxPrimitives = 64;

inline bool auto_flat(long primitives) { return primitives <= kFlatMaxPrimitives; }

// Whether a program traverses nothing: `a`, or the rule for `primitives` when a is Auto.
inline bool choose_flat(Accel a, long primitives) { return a == Accel::Auto ? auto_flat(primitives) : a == Accel::Flat; }

inline const char* accel_name(Accel a) { return kAccelNames[int(a)]; }
inline bool accel_from_name(const char* s, Accel* out) {
  for (int i = 0; i < 3; ++i)
    if (!std::strcmp(s, kAccelNames[i])) return *out = Accel(i), true;
  return false;
}

}  // namespace pt
