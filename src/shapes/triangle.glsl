// Triangle: <Triangle v0=".." v1=".." v2="..">, two-sided; the outward normal is
// normalize((v1 - v0) x (v2 - v0)). Watertight intersection (Woop, Benthin and Wald,
// "Watertight Ray/Triangle Intersection", JCGT 2013): vertices are sheared into a frame
// where the ray is the +z axis and the 2D edge functions decide, so a ray through an
// edge or vertex shared by several triangles hits at least one of them. An edge
// function of exactly zero counts as inside on both sides (GLSL ES has no double to
// resolve the sign; a double hit is harmless, a crack is not).
//
// Each edge function is evaluated with its two vertices in a canonical order (by their
// world coordinates) and negated when the triangle lists them the other way round: the
// two triangles sharing an edge then run the very same arithmetic on the very same
// inputs and get exactly opposite values, even where the compiler contracts a*b - c*d
// into a fused multiply-add (GLSL ES 3.00 has no 'precise' to forbid it).
bool vertex_before(vec3 p, vec3 q) {
  return p.x < q.x || (p.x == q.x && (p.y < q.y || (p.y == q.y && p.z < q.z)));
}

// The edge function of (p, q) from the 2D points; `before`: vertex_before(p, q).
float edge_function(bool before, vec2 ps, vec2 qs) {
  return before ? ps.x * qs.y - ps.y * qs.x : -(qs.x * ps.y - qs.y * ps.x);
}

// Bits 0, 1, 2: whether the edges (c, b), (a, c), (b, a) run in canonical order. The
// BVH's triangle primitives carry them (packed once: shapes/triangle.h), so the
// traversal's tests make no vertex comparisons.
int triangle_edge_order(vec3 va, vec3 vb, vec3 vc) {
  return (vertex_before(vc, vb) ? 1 : 0) | (vertex_before(va, vc) ? 2 : 0) | (vertex_before(vb, va) ? 4 : 0);
}

// Per ray, once: the permutation and shear as three rows (so no vector is indexed by a
// run-time value, which GPUs compile to slow local memory): for p relative to the ray
// origin, (dot(x, p), dot(y, p)) are the 2D coordinates and dot(z, p) the scaled depth.
struct TriangleRay { vec3 x; vec3 y; vec3 z; };
TriangleRay prepare_triangle(Ray r) {
  vec3 ad = abs(r.d);
  vec3 ez = ad.x > ad.y ? (ad.x > ad.z ? vec3(1, 0, 0) : vec3(0, 0, 1)) : (ad.y > ad.z ? vec3(0, 1, 0) : vec3(0, 0, 1));
  vec3 ex = ez.zxy;  // the next axis after kz: (1,0,0) -> (0,1,0) -> (0,0,1) -> (1,0,0)
  vec3 ey = ex.zxy;
  float dz = dot(r.d, ez);
  if (dz < 0.0) {  // keep the winding
    vec3 tmp = ex;
    ex = ey;
    ey = tmp;
  }
  float sz = 1.0 / dz;
  return TriangleRay(ex - dot(r.d, ex) * sz * ez, ey - dot(r.d, ey) * sz * ez, sz * ez);
}

void intersect_triangle_verts(vec3 va, vec3 vb, vec3 vc, int order, int id, Ray r, TriangleRay tr, inout Hit h) {
  vec3 a = va - r.o, b = vb - r.o, c = vc - r.o;
  vec2 a2 = vec2(dot(tr.x, a), dot(tr.y, a));
  vec2 b2 = vec2(dot(tr.x, b), dot(tr.y, b));
  vec2 c2 = vec2(dot(tr.x, c), dot(tr.y, c));
  float u = edge_function((order & 1) != 0, c2, b2);  // cx * by - cy * bx
  float v = edge_function((order & 2) != 0, a2, c2);  // ax * cy - ay * cx
  float w = edge_function((order & 4) != 0, b2, a2);  // bx * ay - by * ax
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return;
  float det = u + v + w;
  if (det == 0.0) return;
  float t = (u * dot(tr.z, a) + v * dot(tr.z, b) + w * dot(tr.z, c)) / det;
  if (!(t > 0.0) || t >= h.t) return;
  h.t = t;
  h.id = id;
  h.n = normalize(cross(vb - va, vc - va));
  h.p = (u * va + v * vb + w * vc) / det;  // barycentric: on the triangle's plane by construction
}

// Motion blur (HAS_MOTION): a moving Triangle or mesh instance is a translation
// velocity * g_time of its vertices at time 0; the ray is translated by the opposite
// (tr depends on the direction only) and the hit point back. Its primitives are marked
// (extra = 1, render/packing.cpp) and only they fetch their shape's velocity
// (prim_velocity: generated over the kinds whose primitives are triangles).
#ifdef HAS_MOTION
vec3 prim_offset(PrimRec p) { return p.extra != 0.0 ? prim_velocity(p.tag) * g_time : vec3(0.0); }

void intersect_triangle_moving(vec3 va, vec3 vb, vec3 vc, int order, int id, vec3 off, Ray r, TriangleRay tr, inout Hit h) {
  float before = h.t;
  r.o -= off;
  intersect_triangle_verts(va, vb, vc, order, id, r, tr, h);
  if (h.t < before) h.p += off;
}
#endif

// A triangle primitive of the BVH (a lone Triangle or a mesh's): vertices and edge order
// inline. With motion, one test for still and moving ones (a still one's offset is 0).
void triangle_prim(PrimRec p, Ray r, TriangleRay tr, inout Hit h) {
#ifdef HAS_MOTION
  intersect_triangle_moving(p.v0, p.v1, p.v2, p.kind, p.tag, prim_offset(p), r, tr, h);
#else
  intersect_triangle_verts(p.v0, p.v1, p.v2, p.kind, p.tag, r, tr, h);
#endif
}

void intersect_triangle(ShapeRec s, int id, Ray r, TriangleRay tr, inout Hit h) {
  TriangleRec k = triangle_rec(s);
#ifdef HAS_MOTION
  intersect_triangle_moving(k.v0, k.v1, k.v2, triangle_edge_order(k.v0, k.v1, k.v2), id, k.velocity * g_time, r, tr, h);
#else
  intersect_triangle_verts(k.v0, k.v1, k.v2, triangle_edge_order(k.v0, k.v1, k.v2), id, r, tr, h);
#endif
}

// The triangle at the path's time (light sampling, image maps).
TriangleRec triangle_at(ShapeRec s) {
  TriangleRec k = triangle_rec(s);
#ifdef HAS_MOTION
  vec3 off = k.velocity * g_time;
  k.v0 += off;
  k.v1 += off;
  k.v2 += off;
#endif
  return k;
}

#ifdef HAS_LIGHT_TRIANGLE
// Emissive triangle: uniform by area (square-root barycentrics), emitting from its
// front side only, solid-angle density t^2 / (cos A).
bool sample_light_triangle(ShapeRec s, vec3 p, vec2 u, out vec3 wi, out float pdf, out float dist) {
  TriangleRec k = triangle_at(s);
  vec3 c = cross(k.v1 - k.v0, k.v2 - k.v0);
  float area = 0.5 * length(c);
  vec3 n = c / (2.0 * area);
  pdf = 0.0;
  dist = 0.0;
  if (dot(n, p - k.v0) <= 0.0) return false;  // p sees the back side
  float r = sqrt(u.x);
  vec3 q = k.v0 * (1.0 - r) + k.v1 * (r * (1.0 - u.y)) + k.v2 * (r * u.y);
  vec3 d = q - p;
  float t2 = dot(d, d);
  wi = d * inversesqrt(t2);
  dist = sqrt(t2);
  float cos_l = -dot(n, wi);
  if (cos_l <= 0.0) return false;
  pdf = t2 / (cos_l * area);
  return true;
}

float pdf_light_triangle(ShapeRec s, vec3 p, vec3 wi, float t, vec3 n) {
  TriangleRec k = triangle_rec(s);
  float area = 0.5 * length(cross(k.v1 - k.v0, k.v2 - k.v0));
  float cos_l = abs(dot(n, wi));
  return cos_l > 0.0 ? t * t / (cos_l * area) : 0.0;
}
#endif

#ifdef HAS_IMAGE_MAPS
// Image maps: the vertices' uv (XML uv0, uv1, uv2; default (0,0), (1,0), (0,1)) in a
// UvRec (core/records.h), interpolated with the barycentric weights of p.
// barycentric_triangle is the hook for meshes: a mesh hit carries its weights and skips it.
vec3 barycentric_triangle(ShapeRec s, vec3 p) {
  TriangleRec k = triangle_at(s);
  vec3 e1 = k.v1 - k.v0, e2 = k.v2 - k.v0, q = p - k.v0;
  float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2), d20 = dot(q, e1), d21 = dot(q, e2);
  float den = d00 * d11 - d01 * d01;
  if (!(abs(den) >= 1e-30)) {
    // A tiny triangle: the Gram determinant (size^4) leaves float's normal range below
    // edges of about 1e-8 (x / 0: NaN uv). In units of its longest edge it does not.
    float l = max(max_abs(e1), max_abs(e2));
    if (!(l > 0.0)) return vec3(1.0 / 3.0);
    e1 /= l;
    e2 /= l;
    q /= l;
    d00 = dot(e1, e1);
    d01 = dot(e1, e2);
    d11 = dot(e2, e2);
    d20 = dot(q, e1);
    d21 = dot(q, e2);
    den = d00 * d11 - d01 * d01;
    if (den == 0.0) return vec3(1.0 / 3.0);  // collinear in float
  }
  float v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
  return vec3(1.0 - v - w, v, w);
}
vec2 uv_triangle(ShapeRec s, UvRec t, vec3 p, vec3 n) {
  vec3 b = barycentric_triangle(s, p);
  return b.x * t.uv0 + b.y * t.uv1 + b.z * t.uv2;
}
// dp/du of the affine uv parameterisation: e1 = dp/du du1 + dp/dv dv1 (and e2), solved
// for dp/du, made orthogonal to n. w = -1 when the uv map is mirrored (then dp/dv points
// along -(n x t)); a degenerate uv map gives any tangent.
vec4 tangent_triangle(ShapeRec s, UvRec t, vec3 p, vec3 n) {
  TriangleRec k = triangle_rec(s);
  vec3 e1 = k.v1 - k.v0, e2 = k.v2 - k.v0;
  vec2 d1 = t.uv1 - t.uv0, d2 = t.uv2 - t.uv0;
  float det = d1.x * d2.y - d1.y * d2.x;
  vec3 dpdu = (e1 * d2.y - e2 * d1.y) * (det < 0.0 ? -1.0 : 1.0);
  dpdu -= n * dot(n, dpdu);
  float l = length(dpdu);
  return det != 0.0 && l > 0.0 ? vec4(dpdu / l, det < 0.0 ? -1.0 : 1.0) : vec4(frame_from(n).t, 1.0);
}
#endif
