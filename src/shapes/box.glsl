// Axis-aligned box: <Box min="x y z" max="x y z"> (the loader normalises min > max).
// Slab method; zero direction components are nudged to a tiny positive value so that
// 0 * inf never makes a NaN and a slab the ray runs parallel to constrains nothing
// unless the origin lies outside it.
void intersect_box(ShapeRec s, int id, Ray r, inout Hit h) {
  vec3 d = mix(r.d, vec3(1e-30), lessThan(abs(r.d), vec3(1e-30)));
  vec3 inv = 1.0 / d;
  vec3 ta = (s.a - r.o) * inv;
  vec3 tb = (s.b - r.o) * inv;
  vec3 tmin = min(ta, tb);
  vec3 tmax = max(ta, tb);
  float t_near = max3(tmin);
  float t_far = min(min(tmax.x, tmax.y), tmax.z);
  if (t_near > t_far || t_far <= 0.0) return;
  bool inside = t_near <= 0.0;
  float t = inside ? t_far : t_near;
  if (t >= h.t) return;
  vec3 sel = inside ? tmax : tmin;
  vec3 axis = sel.x == t ? vec3(1, 0, 0) : (sel.y == t ? vec3(0, 1, 0) : vec3(0, 0, 1));
  // Entering: the normal opposes the ray; leaving from inside: it points along it.
  h.t = t;
  h.id = id;
  h.n = axis * (inside ? sign(dot(axis, d)) : -sign(dot(axis, d)));
}
