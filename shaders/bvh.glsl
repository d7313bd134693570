// bvh.glsl: ray traversal of the scene's 4-wide BVH (accel/bvh_wide.h, packed by
// render/packing.cpp). At an interior node the four children's boxes are fetched and
// tested together, sorted by entry distance; the nearest is visited next and the others
// pushed on a small stack, nearest last (Aila and Laine 2009 order, without the
// persistent threads). Primitives are stored in leaf order; planes, having no bounds, sit
// before them and every ray tests them. The same loop answers nearest-hit queries and
// shadow queries (any hit before tmax ends it), which the compiler specialises since
// `any_hit` is constant at each call.
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

// A stack entry: an interior child as its node index (>= 0), a leaf as
// -1 - (first primitive * 16 + count - 1) (leaves hold 1..16 primitives).
int bvh_entry(int first, int count) { return count == 0 ? first : -1 - (first * 16 + count - 1); }

// Entry distance of child slot (lo, hi, count): T_INF for an empty slot (count < 0).
float bvh_child_entry(vec3 lo, vec3 hi, int count, vec3 o, vec3 inv, float tmax) {
  return count < 0 ? T_INF : bvh_box_entry(lo, hi, o, inv, tmax);
}

// One compare-exchange of the sorting network over (distance, entry) pairs.
void bvh_order(inout float ta, inout int ea, inout float tb, inout int eb) {
  if (tb < ta) {
    float t = ta;
    ta = tb;
    tb = t;
    int e = ea;
    ea = eb;
    eb = e;
  }
}

void bvh_prim(int i, Ray r, RayPre pre, int skip, inout Hit h) {
  PrimRec p = load_prim(i);
  float before = h.t;
  if (p.tag >= 0) {
#ifdef HAS_PRIM_TRIANGLES
    if (p.tag != skip) triangle_prim(p, r, pre.triangle, h);
#endif
  } else if (-1 - p.tag != skip) {
    intersect_analytic(p, r, pre, h);
  }
  if (h.t < before) h.prim = i;
}

const int BVH_STACK_SIZE = 64;  // = kBvhStackSize: the builder bounds the depth by it

// Nearest hit closer than tmax (any_hit: the first found), ignoring shape `skip`.
Hit trace_scene(Ray r, float tmax, bool any_hit, int skip) {
  ++g_rays;
  Hit h = no_hit();
  h.t = tmax;
  RayPre pre = prepare_ray(r);
  for (int i = 0; i < u_num_unbounded; ++i) bvh_prim(i, r, pre, skip, h);
  if ((any_hit && h.id >= 0) || u_num_nodes == 0) return h;
  vec3 inv = 1.0 / mix(r.d, vec3(1e-30), equal(r.d, vec3(0.0)));
  int stack[BVH_STACK_SIZE];
  int sp = 0;
  int cur = 0;  // the root
  for (;;) {
    if (cur >= 0) {
      NodeRec n = load_node(cur);
      float t0 = bvh_child_entry(n.lo0, n.hi0, n.count0, r.o, inv, h.t);
      float t1 = bvh_child_entry(n.lo1, n.hi1, n.count1, r.o, inv, h.t);
      float t2 = bvh_child_entry(n.lo2, n.hi2, n.count2, r.o, inv, h.t);
      float t3 = bvh_child_entry(n.lo3, n.hi3, n.count3, r.o, inv, h.t);
      int e0 = bvh_entry(n.first0, n.count0), e1 = bvh_entry(n.first1, n.count1);
      int e2 = bvh_entry(n.first2, n.count2), e3 = bvh_entry(n.first3, n.count3);
      // Sorting network for four: nearest in slot 0.
      bvh_order(t0, e0, t1, e1);
      bvh_order(t2, e2, t3, e3);
      bvh_order(t0, e0, t2, e2);
      bvh_order(t1, e1, t3, e3);
      bvh_order(t1, e1, t2, e2);
      if (t0 < T_INF) {
        if (t3 < T_INF) stack[sp++] = e3;
        if (t2 < T_INF) stack[sp++] = e2;
        if (t1 < T_INF) stack[sp++] = e1;
        cur = e0;
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
    cur = stack[--sp];
  }
  return h;
}

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
