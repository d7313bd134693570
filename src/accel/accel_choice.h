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
// steps (issue 17)"), bvh against flat: on the H200 (1080p, 8 bounces, 5 s each) flat was
// faster on scene2 (10 primitives: fragment 1.51x, compute 1.12x) and slower on scene0
// (13: 0.83x, 0.85x) and the Cornell box (32 triangles: 0.79x, 0.64x); in SwiftShader's
// page (loaded machine) scene2 1.0-1.8x, scene0 0.75-0.89x; on llvmpipe flat won up to
// ~24-64 primitives of scene2's room. A count cannot tell a room whose every wall each ray
// overlaps (scene2: the BVH culls little) from one where it culls well (scene0), so 12 is
// fitted to these three scenes; a rule from the BVH's own SAH cost against the flat
// loop's is the next step.
inline constexpr long kFlatMaxPrimitives = 12;

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
