// Triangle: <Triangle v0=".." v1=".." v2="..">, two-sided; the outward normal is
// normalize((v1 - v0) x (v2 - v0)). Moeller-Trumbore.
void intersect_triangle(ShapeRec s, int id, Ray r, inout Hit h) {
  vec3 e1 = s.b - s.a;
  vec3 e2 = s.c - s.a;
  vec3 p = cross(r.d, e2);
  float det = dot(e1, p);
  if (det == 0.0) return;
  float inv_det = 1.0 / det;
  vec3 tv = r.o - s.a;
  float u = dot(tv, p) * inv_det;
  if (u < 0.0 || u > 1.0) return;
  vec3 q = cross(tv, e1);
  float v = dot(r.d, q) * inv_det;
  if (v < 0.0 || u + v > 1.0) return;
  float t = dot(e2, q) * inv_det;
  if (t <= 0.0 || t >= h.t) return;
  h.t = t;
  h.id = id;
  h.n = normalize(cross(e1, e2));
}
