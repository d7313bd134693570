// Sphere: <Sphere center="x y z" radius="r"> (a light is a sphere too).
// Intersection in the form of Haines et al., "Precision Improvements for Ray/Sphere
// Intersection" (Ray Tracing Gems, ch. 7): the discriminant is computed from the
// perpendicular offset, so it stays accurate far from the origin and for small spheres.
void intersect_sphere(ShapeRec s, int id, Ray r, inout Hit h) {
  vec3 f = r.o - s.a;
  float b = -dot(f, r.d);
  vec3 l = f + b * r.d;
  float r2 = s.radius * s.radius;
  float disc = r2 - dot(l, l);
  if (disc < 0.0) return;
  float q = b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(disc);
  float c = dot(f, f) - r2;
  float t0 = c / q;
  float t1 = q;
  float t = min(t0, t1);
  if (t <= 0.0) t = max(t0, t1);
  if (t <= 0.0 || t >= h.t) return;
  h.t = t;
  h.id = id;
  h.n = (r.o + t * r.d - s.a) / s.radius;
}
