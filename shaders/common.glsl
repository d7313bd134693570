// common.glsl: constants and types that every program shares.
const float PI = 3.14159265358979;
const float INV_PI = 0.318309886183791;
const float TWO_PI = 6.28318530717959;
const float T_INF = 3.0e38;

struct Ray { vec3 o; vec3 d; };
// t: distance along the (unit) ray direction; id: shape index or -1; n: outward unit
// geometric normal of the shape at the hit; p: the hit point, put back onto the surface
// by the shape (pbrt-v4's re-projection), so that error does not compound bounce after
// bounce (a ray reflected inside a glass sphere otherwise drifts off its surface).
// prim: the BVH primitive that was hit (a triangle's vertex attributes hang off it).
struct Hit { float t; int id; vec3 n; vec3 p; int prim; };
Hit no_hit() { return Hit(T_INF, -1, vec3(0.0), vec3(0.0), -1); }

#ifdef PT_COUNT_OPS
int g_box_tests, g_prim_tests;  // this fragment's traversal work (render --count-ops)
#define COUNT_OPS(counter, n) counter += (n)
#else
#define COUNT_OPS(counter, n)
#endif
int g_rays;    // rays cast by this fragment (counted in trace_scene)
float g_time = 0.0;  // the camera sample's time in the shutter interval (motion blur; 0 in tests of a part)

float max3(vec3 v) { return max(max(v.x, v.y), v.z); }
float max_abs(vec3 v) { return max3(abs(v)); }
float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

// Spawns a ray at surface point p towards the side of n that dir leaves into. The
// offset grows with |p| because the rounding error of a computed hit point does
// (about a few ulps of its largest coordinate), so a ray never re-hits the surface it
// leaves, at any distance from the origin or scale of the scene.
vec3 offset_origin(vec3 p, vec3 n, vec3 dir) {
  float eps = max_abs(p) * 7.6e-6 + 1.0e-30;
  return p + (dot(n, dir) >= 0.0 ? eps : -eps) * n;
}

// A sampled scattering direction in the local shading frame (z = normal on the side the
// light leaves towards the viewer). weight = f * |cos(theta_i)| / pdf. Delta lobes have
// pdf = 0 for MIS purposes and carry their whole value in weight.
struct BsdfSample { vec3 wi; vec3 weight; float pdf; bool delta; };
