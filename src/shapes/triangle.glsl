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

float edge_function(vec3 p, vec3 q, vec2 ps, vec2 qs) {
  return vertex_before(p, q) ? ps.x * qs.y - ps.y * qs.x : -(qs.x * ps.y - qs.y * ps.x);
}

void intersect_triangle(ShapeRec s, int id, Ray r, inout Hit h) {
  vec3 ad = abs(r.d);
  int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
  int kx = kz == 2 ? 0 : kz + 1;
  int ky = kx == 2 ? 0 : kx + 1;
  if (r.d[kz] < 0.0) {
    int tmp = kx;
    kx = ky;
    ky = tmp;
  }
  float sz = 1.0 / r.d[kz];
  float sx = r.d[kx] * sz;
  float sy = r.d[ky] * sz;
  vec3 a = s.a - r.o, b = s.b - r.o, c = s.c - r.o;
  vec2 a2 = vec2(a[kx] - sx * a[kz], a[ky] - sy * a[kz]);
  vec2 b2 = vec2(b[kx] - sx * b[kz], b[ky] - sy * b[kz]);
  vec2 c2 = vec2(c[kx] - sx * c[kz], c[ky] - sy * c[kz]);
  float u = edge_function(s.c, s.b, c2, b2);  // cx * by - cy * bx
  float v = edge_function(s.a, s.c, a2, c2);  // ax * cy - ay * cx
  float w = edge_function(s.b, s.a, b2, a2);  // bx * ay - by * ax
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return;
  float det = u + v + w;
  if (det == 0.0) return;
  float tt = (u * a[kz] + v * b[kz] + w * c[kz]) * sz;
  float t = tt / det;
  if (!(t > 0.0) || t >= h.t) return;
  vec3 e1 = s.b - s.a;
  vec3 e2 = s.c - s.a;
  h.t = t;
  h.id = id;
  h.n = normalize(cross(e1, e2));
  h.p = (u * s.a + v * s.b + w * s.c) / det;  // barycentric: on the triangle's plane by construction
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
