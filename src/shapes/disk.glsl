// Disk: <Disk center="x y z" normal="x y z" radius="r" velocity=".."> (shapes/disk.h):
// the plane's distance, then the radius test on the point snapped onto the plane. A
// moving disk (HAS_MOTION): the ray is translated by -velocity * g_time and the hit point
// back; light sampling and image maps read the disk at the path's time (disk_at).
DiskRec disk_at(ShapeRec s) {
  DiskRec k = disk_rec(s);
#ifdef HAS_MOTION
  k.center += k.velocity * g_time;
#endif
  return k;
}

void intersect_disk(ShapeRec s, int id, Ray r, inout Hit h) {
  DiskRec k = disk_rec(s);
#ifdef HAS_MOTION
  vec3 off = k.velocity * g_time;
  r.o -= off;
#endif
  float denom = dot(k.normal, r.d);
  if (denom == 0.0) return;  // parallel: no hit, or the ray lies in the disk's plane
  float t = dot(k.normal, k.center - r.o) / denom;
  if (!(t > 0.0) || t >= h.t) return;
  vec3 q = r.o + t * r.d - k.center;
  q -= k.normal * dot(k.normal, q);
  if (dot(q, q) > k.radius * k.radius) return;
  h.t = t;
  h.id = id;
  h.n = k.normal;
  h.p = k.center + q;
#ifdef HAS_MOTION
  h.p += off;
#endif
}

#ifdef HAS_LIGHT_DISK
// Emissive disk: a point uniform by area (polar: r = R sqrt(u.x), phi = 2 pi u.y), emitting
// on its normal's side only, solid-angle density t^2 / (cos A) with A = pi R^2.
bool sample_light_disk(ShapeRec s, vec3 p, vec2 u, out vec3 wi, out float pdf, out float dist) {
  DiskRec k = disk_at(s);
  pdf = 0.0;
  dist = 0.0;
  if (dot(k.normal, p - k.center) <= 0.0) return false;  // p sees the back side
  Frame f = frame_from(k.normal);
  float rad = k.radius * sqrt(u.x), phi = TWO_PI * u.y;
  vec3 q = k.center + rad * (cos(phi) * f.t + sin(phi) * f.b);
  vec3 d = q - p;
  float t2 = dot(d, d);
  wi = d * inversesqrt(t2);
  dist = sqrt(t2);
  float cos_l = -dot(k.normal, wi);
  if (cos_l <= 0.0) return false;
  pdf = t2 / (cos_l * PI * k.radius * k.radius);
  return true;
}

float pdf_light_disk(ShapeRec s, vec3 p, vec3 wi, float t, vec3 n) {
  DiskRec k = disk_at(s);
  float cos_l = abs(dot(n, wi));
  return cos_l > 0.0 ? t * t / (cos_l * PI * k.radius * k.radius) : 0.0;
}
#endif

#ifdef HAS_IMAGE_MAPS
// Image maps: the disk inscribed in [0, 1]^2 in its tangent frame frame_from(normal)
// (as a plane's: u along t, v along b), centred at (0.5, 0.5).
vec2 uv_disk(ShapeRec s, vec3 p, vec3 n) {
  DiskRec k = disk_at(s);
  Frame f = frame_from(k.normal);
  vec3 q = p - k.center;
  return vec2(0.5) + vec2(dot(q, f.t), dot(q, f.b)) / (2.0 * k.radius);
}
vec4 tangent_disk(ShapeRec s, vec3 p, vec3 n) {
  DiskRec k = disk_at(s);
  return vec4(frame_from(k.normal).t, 1.0);
}
#endif
