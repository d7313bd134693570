// Axis-aligned box: <Box min="x y z" max="x y z" velocity=".."> (the loader normalises
// min > max). A moving box (HAS_MOTION) is at lo, hi + velocity * g_time: intersection
// translates the ray by -velocity * g_time and the hit point back; light sampling and
// image maps read the box where it is at the path's time (box_at). Slab method. An axis
// the ray runs parallel to (a zero direction component) constrains nothing when the
// origin lies within the closed slab and rejects the ray otherwise; it is handled
// explicitly, so 0 * inf never makes a NaN and a ray lying in a face plane
// hits the box the same way whichever face (min or max) it lies in.
// Per ray, once: the reciprocal direction and which axes the ray runs parallel to.
struct BoxRay { vec3 inv; bvec3 parallel; };
BoxRay prepare_box(Ray r) {
  bvec3 par = lessThan(abs(r.d), vec3(1e-30));
  return BoxRay(1.0 / mix(r.d, vec3(1.0), par), par);
}

// The box at the path's time.
BoxRec box_at(ShapeRec s) {
  BoxRec k = box_rec(s);
#ifdef HAS_MOTION
  vec3 off = k.velocity * g_time;
  k.lo += off;
  k.hi += off;
#endif
  return k;
}

void intersect_box(ShapeRec s, int id, Ray r, BoxRay br, inout Hit h) {
  BoxRec k = box_rec(s);
#ifdef HAS_MOTION
  vec3 off = k.velocity * g_time;  // in the box's frame at time 0 (br: the direction only)
  r.o -= off;
#endif
  if (any(br.parallel) && any(bvec3(uvec3(br.parallel) & (uvec3(lessThan(r.o, k.lo)) | uvec3(greaterThan(r.o, k.hi)))))) return;
  vec3 ta = (k.lo - r.o) * br.inv;
  vec3 tb = (k.hi - r.o) * br.inv;
  vec3 tmin = mix(min(ta, tb), vec3(-T_INF), br.parallel);
  vec3 tmax = mix(max(ta, tb), vec3(T_INF), br.parallel);
  float t_near = max3(tmin);
  float t_far = min(min(tmax.x, tmax.y), tmax.z);
  if (t_near > t_far || t_far <= 0.0) return;
  bool inside = t_near <= 0.0;
  float t = inside ? t_far : t_near;
  if (t >= h.t) return;
  vec3 sel = inside ? tmax : tmin;
  vec3 axis = sel.x == t ? vec3(1, 0, 0) : (sel.y == t ? vec3(0, 1, 0) : vec3(0, 0, 1));
  // Entering: the normal opposes the ray; leaving from inside: it points along it.
  float along = dot(axis, r.d) >= 0.0 ? 1.0 : -1.0;
  h.t = t;
  h.id = id;
  h.n = axis * (inside ? along : -along);
  // Snap the coordinate across the face onto the face's plane.
  h.p = r.o + t * r.d;
  h.p = mix(h.p, dot(h.n, axis) > 0.0 ? k.hi : k.lo, axis);
#ifdef HAS_MOTION
  h.p += off;
#endif
}

#ifdef HAS_LIGHT_BOX
// Emissive box: a point chosen uniformly by area on the faces that face p (at most
// three; only front faces emit), converted to a solid-angle density t^2 / (|cos| A).
vec3 box_face_areas(ShapeRec s, vec3 p) {
  BoxRec k = box_at(s);
  vec3 e = k.hi - k.lo;
  vec3 visible = vec3(lessThan(p, k.lo)) + vec3(greaterThan(p, k.hi));
  return vec3(e.y * e.z, e.x * e.z, e.x * e.y) * visible;
}

bool sample_light_box(ShapeRec s, vec3 p, vec2 u, out vec3 wi, out float pdf, out float dist) {
  BoxRec k = box_at(s);
  vec3 area = box_face_areas(s, p);
  float total = area.x + area.y + area.z;
  pdf = 0.0;
  dist = 0.0;
  if (total <= 0.0) return false;
  float pick = u.x * total;
  // The chosen face as an axis mask; (v, u.y) span its two other axes, in order.
  vec3 axis = pick < area.x ? vec3(1, 0, 0) : (pick < area.x + area.y ? vec3(0, 1, 0) : vec3(0, 0, 1));
  float before = dot(axis, vec3(0.0, area.x, area.x + area.y));
  float v = clamp((pick - before) / dot(axis, area), 0.0, 1.0);
  vec3 f = axis.x > 0.0 ? vec3(0.0, v, u.y) : (axis.y > 0.0 ? vec3(v, 0.0, u.y) : vec3(v, u.y, 0.0));
  vec3 q = mix(k.lo, k.hi, f);
  q = mix(q, mix(k.lo, k.hi, vec3(greaterThan(p, k.hi))), axis);  // onto the face that p sees
  vec3 d = q - p;
  float t2 = dot(d, d);
  wi = d * inversesqrt(t2);
  dist = sqrt(t2);
  float cos_l = abs(dot(wi, axis));
  if (cos_l <= 0.0) return false;
  pdf = t2 / (cos_l * total);
  return true;
}

float pdf_light_box(ShapeRec s, vec3 p, vec3 wi, float t, vec3 n) {
  vec3 area = box_face_areas(s, p);
  float total = area.x + area.y + area.z;
  float cos_l = abs(dot(n, wi));
  return total > 0.0 && cos_l > 0.0 ? t * t / (cos_l * total) : 0.0;
}
#endif

#ifdef HAS_IMAGE_MAPS
// Image maps: every face spans [0, 1]^2 (three.js's BoxGeometry orientation). On the
// four side faces v runs up +y; on the top and bottom faces u runs along +x. u runs along
// t = unit dp/du: -z on +x, +z on -x, +x on +y, -y and +z, -x on -z, so that
// (t, n x t, n) is right-handed with n outward and n x t = dp/dv.
vec4 tangent_box(ShapeRec s, vec3 p, vec3 n) {
  vec3 a = abs(n);
  if (a.x > 0.5) return vec4(0.0, 0.0, -n.x, 1.0);
  if (a.y > 0.5) return vec4(1.0, 0.0, 0.0, 1.0);
  return vec4(n.z, 0.0, 0.0, 1.0);
}
vec2 uv_box(ShapeRec s, vec3 p, vec3 n) {
  BoxRec k = box_at(s);
  vec3 f = (p - k.lo) / max(k.hi - k.lo, vec3(1e-30));  // p in [0, 1]^3
  vec3 a = abs(n);
  if (a.x > 0.5) return vec2(n.x > 0.0 ? 1.0 - f.z : f.z, f.y);
  if (a.y > 0.5) return vec2(f.x, n.y > 0.0 ? 1.0 - f.z : f.z);
  return vec2(n.z > 0.0 ? f.x : 1.0 - f.x, f.y);
}
#endif
