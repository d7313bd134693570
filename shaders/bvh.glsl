// bvh.glsl: ray traversal of the scene's BVH (accel/bvh.h, packed by render/packing.cpp).
// Binary nodes with adjacent children: at an interior node both children's boxes are
// fetched and tested together, the nearer is visited next and the farther pushed on a
// small stack (Aila and Laine 2009, without the persistent threads). Primitives are
// stored in leaf order; planes, having no bounds, sit before them and every ray tests
// them. The same loop answers nearest-hit queries and shadow queries (any hit before
// tmax ends it), which the compiler specialises since `any_hit` is constant at each call.
// HAS_FLAT (a small scene: accel/accel_choice.h): no traversal at all, every primitive in
// one loop; no node is read and there is no stack.
uniform int u_num_prims;      // every primitive record
#ifndef HAS_FLAT
uniform int u_num_unbounded;  // prims [0, n) are outside the hierarchy
uniform int u_num_nodes;      // 0: no bounded primitive

// Entry distance of the ray into [lo, hi] clamped to >= 0, or T_INF when it misses the box
// or enters beyond tmax. The far distance is widened by 1 + 2 gamma(3) (Ize, "Robust BVH
// Ray Traversal", JCGT 2013) so rounding never culls a box the ray grazes; boxes are also
// padded when built. inv has no infinities (zero direction components are replaced by a
// tiny value), so no 0 * inf makes a NaN.
float bvh_box_entry(vec3 lo, vec3 hi, vec3 o, vec3 inv, float tmax) {
  vec3 a = (lo - o) * inv;
  vec3 b = (hi - o) * inv;
  float tn = max(max3(min(a, b)), 0.0);
  vec3 fa = max(a, b);
  float tf = min(min(fa.x, fa.y), fa.z) * 1.00000036;
  return tn <= tf && tn <= tmax ? tn : T_INF;
}

// A stack entry: an interior node as the index of its first child (>= 0), a leaf as
// -1 - (first primitive * 16 + count - 1) (leaves hold 1..16 primitives).
#ifdef HAS_MOTION
// With motion blur, count's bits 5 and up mark a node whose primitives all belong to one
// moving shape (render/packing.h, node_mover): its box is at time 0, so the ray is moved
// by -velocity * g_time for its test, as the primitives' tests move it.
int bvh_entry(NodeRec n) { int c = n.count & 31; return c == 0 ? n.first : -1 - (n.first * 16 + c - 1); }
vec3 bvh_node_origin(NodeRec n, vec3 o) { return n.count >= 32 ? o - prim_velocity((n.count >> 5) - 1) * g_time : o; }
#else
int bvh_entry(NodeRec n) { return n.count == 0 ? n.first : -1 - (n.first * 16 + n.count - 1); }
#define bvh_node_origin(n, o) (o)
#endif
#endif  // !HAS_FLAT

void bvh_prim(int i, Ray r, RayPre pre, int skip, inout Hit h) {
  PrimRec p = load_prim(i);
  COUNT_OPS(g_prim_tests, 1);
  float before = h.t;
#ifdef HAS_HIT_CUTS
  Hit kept = h;
#endif
  if (p.tag >= 0) {
#ifdef HAS_PRIM_TRIANGLES
    if (p.tag != skip) triangle_prim(p, r, pre.triangle, h);
#endif
  } else if (-1 - p.tag != skip) {
    intersect_analytic(p, r, pre, h);
  }
#ifdef HAS_HIT_CUTS
  // A material may say the candidate is no surface (alpha, a culled back face: the
  // generated hit_present, materials/material.h kCutsHits); the traversal goes on past it.
  if (h.t < before && p.tag >= 0 && !hit_present(p.tag, i, r, h)) {
    h = kept;
    return;
  }
#endif
  if (h.t < before) h.prim = i;
}

#ifdef HAS_FLAT
// Every primitive, in leaf order: the nearest hit is the BVH's but for exact ties of t
// (the first tested wins, and the orders differ); a shadow query ends at its first hit.
Hit trace_scene(Ray r, float tmax, bool any_hit, int skip) {
  ++g_rays;
  Hit h = no_hit();
  h.t = tmax;
  RayPre pre = prepare_ray(r);
  for (int i = 0; i < u_num_prims; ++i) {
    bvh_prim(i, r, pre, skip, h);
    if (any_hit && h.id >= 0) break;
  }
  return h;
}
#else
const int BVH_STACK_SIZE = 48;  // = kBvhStackSize: the builder bounds the depth by it

#ifdef PT_COMPUTE
// The compute kernel keeps the stacks in shared memory, interleaved (entry k of
// invocation j at k * PT_GROUP_SIZE + j: a warp's accesses at one depth fall in distinct
// banks); a local array lives in cached device memory. One stack per invocation is
// enough: traversals never nest.
shared int s_bvh_stack[BVH_STACK_SIZE * PT_GROUP_SIZE];
#define BVH_STACK_DECL
#define BVH_PUSH(e) s_bvh_stack[(sp++) * PT_GROUP_SIZE + int(gl_LocalInvocationIndex)] = (e)
#define BVH_POP() s_bvh_stack[(--sp) * PT_GROUP_SIZE + int(gl_LocalInvocationIndex)]
#else
#define BVH_STACK_DECL int stack[BVH_STACK_SIZE];
#define BVH_PUSH(e) stack[sp++] = (e)
#define BVH_POP() stack[--sp]
#endif

// Nearest hit closer than tmax (any_hit: the first found), ignoring shape `skip`.
Hit trace_scene(Ray r, float tmax, bool any_hit, int skip) {
  ++g_rays;
  Hit h = no_hit();
  h.t = tmax;
  RayPre pre = prepare_ray(r);
  for (int i = 0; i < u_num_unbounded; ++i) bvh_prim(i, r, pre, skip, h);
  if ((any_hit && h.id >= 0) || u_num_nodes == 0) return h;
  vec3 inv = 1.0 / mix(r.d, vec3(1e-30), equal(r.d, vec3(0.0)));
  NodeRec root = load_node(0);
  COUNT_OPS(g_box_tests, 1);
  if (bvh_box_entry(root.lo, root.hi, bvh_node_origin(root, r.o), inv, h.t) == T_INF) return h;
  BVH_STACK_DECL
  int sp = 0;
  int cur = bvh_entry(root);
  for (;;) {
    if (cur >= 0) {
      NodeRec a = load_node(cur);
      NodeRec b = load_node(cur + 1);
      COUNT_OPS(g_box_tests, 2);
      float ta = bvh_box_entry(a.lo, a.hi, bvh_node_origin(a, r.o), inv, h.t);
      float tb = bvh_box_entry(b.lo, b.hi, bvh_node_origin(b, r.o), inv, h.t);
      // (Entries, not records, in the selections: WebGL has no ?: on structures.)
      int ea = bvh_entry(a), eb = bvh_entry(b);
      if (ta < T_INF && tb < T_INF) {
        bool a_first = ta <= tb;
        BVH_PUSH(a_first ? eb : ea);
        cur = a_first ? ea : eb;
        continue;
      }
      if (ta < T_INF || tb < T_INF) {
        cur = ta < T_INF ? ea : eb;
        continue;
      }
    } else {
      int code = -1 - cur;
      int first = code >> 4;
      int end = first + (code & 15) + 1;
      for (int i = first; i < end; ++i) bvh_prim(i, r, pre, skip, h);
      if (any_hit && h.id >= 0) return h;
    }
    if (sp == 0) break;
    cur = BVH_POP();
  }
  return h;
}
#endif  // HAS_FLAT

Hit scene_intersect(Ray r) { return trace_scene(r, T_INF, false, -1); }

// Whether anything but shape `skip` lies on the ray before tmax.
bool occluded(Ray r, float tmax, int skip) { return trace_scene(r, tmax, true, skip).id >= 0; }

// A shadow ray from surface point p (geometric normal n) along wi to a light `dist` away
// (T_INF: the environment; light_shape -1): whether nothing but the light is in between.
// The light itself is skipped, so its own surface never shadows; the distance keeps a
// relative margin of 1e-4 for what touches the light.
bool light_visible(vec3 p, vec3 n, vec3 wi, float dist, int light_shape) {
  return !occluded(Ray(offset_origin(p, n, wi), wi), dist * 0.9999, light_shape);
}
