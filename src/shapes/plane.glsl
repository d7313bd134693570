// Infinite plane: <Plane normal="x y z" d="d">, the points p with dot(normal, p) = d
// (the loader normalises the normal and scales d with it).
void intersect_plane(ShapeRec s, int id, Ray r, inout Hit h) {
  float denom = dot(s.a, r.d);
  if (denom == 0.0) return;  // parallel: no hit, or the ray lies in the plane
  float t = (s.radius - dot(s.a, r.o)) / denom;
  if (t <= 0.0 || t >= h.t) return;
  h.t = t;
  h.id = id;
  h.n = s.a;
  h.p = r.o + t * r.d;
  h.p -= s.a * (dot(s.a, h.p) - s.radius);
}
