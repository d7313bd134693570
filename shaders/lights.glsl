// lights.glsl: next-event estimation towards sphere lights, sampled uniformly by
// solid angle inside the cone they subtend (pbrt-v4, 6.2.3); one light chosen uniformly.
uniform int u_num_lights;

struct LightSample { vec3 wi; float pdf; vec3 radiance; int shape; };

// 1 - cos(theta_max) of the cone that the sphere subtends from p, computed from
// sin^2 so it stays accurate for small, far lights; 0 when p is inside the sphere.
float light_cone(LightRec l, vec3 p) {
  vec3 toc = l.center - p;
  float d2 = dot(toc, toc);
  float sin2 = l.radius * l.radius / d2;
  if (sin2 >= 1.0) return 0.0;
  return sin2 / (1.0 + sqrt(1.0 - sin2));
}

// Solid-angle density with which light_sample picks direction towards light `li` from p
// (selection probability included).
float light_pdf(int li, vec3 p) {
  float omc = light_cone(load_light(li), p);
  return omc > 0.0 ? 1.0 / (TWO_PI * omc * float(u_num_lights)) : 0.0;
}

bool light_sample(vec3 p, vec3 u, out LightSample ls) {
  int li = min(int(u.z * float(u_num_lights)), u_num_lights - 1);
  LightRec l = load_light(li);
  float omc = light_cone(l, p);
  if (omc <= 0.0) return false;
  Frame f = frame_from(normalize(l.center - p));
  ls.wi = from_local(f, sample_uniform_cone(u.xy, omc));
  ls.pdf = 1.0 / (TWO_PI * omc * float(u_num_lights));
  ls.radiance = l.radiance;
  ls.shape = l.shape;
  return true;
}
