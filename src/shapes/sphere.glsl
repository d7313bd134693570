// Sphere: <Sphere center="x y z" radius="r" velocity="vx vy vz"> (a light is a sphere
// too). A moving sphere is at centre + velocity * g_time (motion blur).
// Intersection in the form of Haines et al., "Precision Improvements for Ray/Sphere
// Intersection" (Ray Tracing Gems, ch. 7): the discriminant is computed from the
// perpendicular offset, so it stays accurate far from the origin and for small spheres.
// Only scenes with a moving sphere pay for the time (Features::motion).
#ifdef HAS_MOTION
vec3 sphere_center(ShapeRec s) { SphereRec k = sphere_rec(s); return k.center + k.velocity * g_time; }
#else
vec3 sphere_center(ShapeRec s) { SphereRec k = sphere_rec(s); return k.center; }
#endif

void intersect_sphere(ShapeRec s, int id, Ray r, inout Hit h) {
  SphereRec k = sphere_rec(s);
  vec3 center = sphere_center(s);
  vec3 f = r.o - center;
  float b = -dot(f, r.d);
  vec3 l = f + b * r.d;
  float r2 = k.radius * k.radius;
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
  h.n = normalize(r.o + t * r.d - center);
  h.p = center + k.radius * h.n;
}

#ifdef HAS_LIGHT_SPHERE
// Emissive sphere: directions sampled uniformly inside the cone it subtends from p
// (pbrt-v4, 6.2.3), which covers exactly its visible part. 1 - cos(theta_max) comes from
// sin^2 so it stays accurate for small, far lights. No sample from inside the sphere.
float sphere_cone(ShapeRec s, vec3 p) {
  SphereRec k = sphere_rec(s);
  vec3 toc = sphere_center(s) - p;
  float sin2 = k.radius * k.radius / dot(toc, toc);
  return sin2 >= 1.0 ? 0.0 : sin2 / (1.0 + sqrt(1.0 - sin2));
}

bool sample_light_sphere(ShapeRec s, vec3 p, vec2 u, out vec3 wi, out float pdf, out float dist) {
  SphereRec k = sphere_rec(s);
  float omc = sphere_cone(s, p);
  pdf = omc > 0.0 ? 1.0 / (TWO_PI * omc) : 0.0;
  dist = 0.0;
  if (omc <= 0.0) return false;
  wi = from_local(frame_from(normalize(sphere_center(s) - p)), sample_uniform_cone(u, omc));
  // Distance to the near surface along wi (a direction inside the cone meets it; rounding
  // at the cone's rim is clamped to the tangent point).
  vec3 f = p - sphere_center(s);
  float b = -dot(f, wi);
  vec3 l = f + b * wi;
  dist = b - sqrt(max(k.radius * k.radius - dot(l, l), 0.0));
  return true;
}

float pdf_light_sphere(ShapeRec s, vec3 p, vec3 wi, float t, vec3 n) {
  float omc = sphere_cone(s, p);
  return omc > 0.0 ? 1.0 / (TWO_PI * omc) : 0.0;
}
#endif

#ifdef HAS_IMAGE_MAPS
// Image maps: longitude and latitude of the outward normal n (the direction from the
// centre, so a moving sphere carries its texture): u = phi / (2 pi) with
// phi = atan(-n.z, n.x), v = 1 - theta / pi with theta = acos(n.y) (computed as
// atan(|n.xz|, n.y)), so v = 1 at the +y pole and an image stands upright. The tangent
// t = unit dp/du = (-sin phi, 0, -cos phi) makes (t, n x t, n) right-handed with n x t
// pointing north (dp/dv); at the poles phi = 0 (atan(0, 0) is undefined in GLSL).
vec2 uv_sphere(ShapeRec s, vec3 p, vec3 n) {
  float phi = n.x == 0.0 && n.z == 0.0 ? 0.0 : atan(-n.z, n.x);
  return vec2(fract(phi / TWO_PI), 1.0 - atan(length(n.xz), n.y) / PI);  // atan: accurate near the poles too
}
vec4 tangent_sphere(ShapeRec s, vec3 p, vec3 n) {
  vec3 t = vec3(n.z, 0.0, -n.x);
  float l = length(t);
  return vec4(l > 0.0 ? t / l : vec3(0.0, 0.0, -1.0), 1.0);
}
#endif
