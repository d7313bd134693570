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
  h.p = s.a + u * e1 + v * e2;  // barycentric: on the triangle's plane by construction
}

#ifdef HAS_LIGHT_TRIANGLE
// Emissive triangle: uniform by area (square-root barycentrics), emitting from its
// front side only, solid-angle density t^2 / (cos A).
bool sample_light_triangle(ShapeRec s, vec3 p, vec2 u, out vec3 wi, out float pdf) {
  vec3 c = cross(s.b - s.a, s.c - s.a);
  float area = 0.5 * length(c);
  vec3 n = c / (2.0 * area);
  pdf = 0.0;
  if (dot(n, p - s.a) <= 0.0) return false;  // p sees the back side
  float r = sqrt(u.x);
  vec3 q = s.a * (1.0 - r) + s.b * (r * (1.0 - u.y)) + s.c * (r * u.y);
  vec3 d = q - p;
  float t2 = dot(d, d);
  wi = d * inversesqrt(t2);
  float cos_l = -dot(n, wi);
  if (cos_l <= 0.0) return false;
  pdf = t2 / (cos_l * area);
  return true;
}

float pdf_light_triangle(ShapeRec s, vec3 p, vec3 wi, float t, vec3 n) {
  float area = 0.5 * length(cross(s.b - s.a, s.c - s.a));
  float cos_l = abs(dot(n, wi));
  return cos_l > 0.0 ? t * t / (cos_l * area) : 0.0;
}
#endif
