// The acceleration a scene's program traverses: its BVH (accel/bvh.h), or none - every ray
// tests every primitive in one plain loop (shaders/bvh.glsl, HAS_FLAT). A program
// feature (shadergen.h: Features::flat), chosen per scene by the rule below unless
// the user says (--accel, the page's accel=). The packing is the same either way: the
// primitives stay in the BVH's leaf order, so the two loops differ only in the order they
// test them (the same nearest hit but for exact ties of t).
#pragma once
#include <cstring>

namespace pt {

enum class Accel { Auto, Bvh, Flat };
inline constexpr const char* kAccelNames[] = {"auto", "bvh", "flat"};

// `auto`'s rule, from the scene's own BVH: flat when the loop's cost per ray (every
// bounded primitive tested: `bounded`, the BVH's primitives; planes are tested by every ray
// either way) is at most kFlatPerSah times the BVH's expected cost per ray in the SAH model
// (Bvh::sah_cost: the surface-area-weighted node visits and primitive tests; PackedScene::
// bvh_sah_cost), and the scene has at most kFlatMaxConsidered such primitives (beyond it
// the loop never pays, and the rule need not pack the scene to decide). A count alone
// cannot tell a room whose every wall each ray overlaps (scene2: its BVH culls little, SAH
// cost 8.5 for 9 bounded primitives) from one where it culls well (scene0, the Cornell box).
// kFlatPerSah is fitted to the measurements in docs/benchmarks.md ("Fragment-pass steps
// (issue 17)"), each scene's SAH cost beside its bvh/flat speeds.
inline constexpr long kFlatMaxConsidered = 64;

// A flat loop over at most this many primitives (planes included) goes kind by kind
// (shaders/bvh.glsl, HAS_FLAT_ORDER): one loop per kind over that kind's primitives, from
// an order in uniforms (render/packing.h: flat_order), so that no primitive runs another
// kind's test. A software rasteriser runs every side of a branch for every lane, so the
// one loop that dispatches on each primitive's kind ran every kind's test each time
// (docs/benchmarks.md, "The flat loop kind by kind"). Above it (a loop forced onto a large
// scene: --accel flat), the one loop stays.
inline constexpr long kFlatOrderMax = 128;
inline constexpr double kFlatPerSah = 2.2;

inline bool auto_flat(long bounded, double sah_cost) {
  return bounded <= kFlatMaxConsidered && double(bounded) <= kFlatPerSah * sah_cost;
}

inline const char* accel_name(Accel a) { return kAccelNames[int(a)]; }
inline bool accel_from_name(const char* s, Accel* out) {
  for (int i = 0; i < 3; ++i)
    if (!std::strcmp(s, kAccelNames[i])) return *out = Accel(i), true;
  return false;
}

}  // namespace pt
