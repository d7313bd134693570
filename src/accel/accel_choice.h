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
// steps (issue 17)"): bvh against flat, interleaved, 256x256, 8 bounces, llvmpipe's
// fragment pass on a loaded machine, on scene2's room with small boxes and spheres added
// (tools/gen_accel_scenes.py): flat 1.1-1.6x faster at 24 primitives, even at 64 (0.7 and
// 1.1x), 1.7-2.3x slower at 128, 2.4-3.4x at 384; on scene2 (10) 1.4-2.7x faster. 32 stays below the break-even;
// the lead measures the H200's fragment pass and compute kernel with --accel.
inline constexpr long kFlatMaxPrimitives = 32;

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
