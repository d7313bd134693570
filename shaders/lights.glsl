// lights.glsl: next-event estimation. One light is chosen uniformly among the emissive
// shapes of samplable kinds; the shape's own snippet samples a direction towards it
// (sample_light_<kind>, through the generated light_sample_shape) with a solid-angle
// density, and light_pdf gives the same density for a direction found by BSDF sampling,
// for multiple importance sampling.
uniform int u_num_lights;

// dist: how far along wi the light's surface is (T_INF for the environment).
struct LightSample { vec3 wi; float pdf; vec3 radiance; int shape; float dist; };

// With an environment map, half the light samples go to it (all of them when the scene
// has no emitters); the densities below include that choice.
float env_select_prob() {
#ifdef HAS_ENV_MAP
  return u_num_lights > 0 ? 0.5 : 1.0;
#else
  return 0.0;
#endif
}

bool have_lights() { return u_num_lights > 0 || env_select_prob() > 0.0; }

bool light_sample(vec3 p, vec3 u, out LightSample ls) {
  float pe = env_select_prob();
#ifdef HAS_ENV_MAP
  if (u.z < pe) {
    float pdf;
    if (!env_sample(u.xy, ls.wi, pdf, ls.radiance)) return false;
    ls.pdf = pdf * pe;
    ls.shape = -1;  // visible when the shadow ray leaves the scene
    ls.dist = T_INF;
    return true;
  }
  u.z = (u.z - pe) / (1.0 - pe);
#endif
  if (u_num_lights == 0) return false;
  int li = min(int(u.z * float(u_num_lights)), u_num_lights - 1);
  LightRec l = load_light(li);
  // A direction of infinite density (a light too small for float seen from far) carries
  // radiance / pdf = 0: no sample, rather than inf / inf in the weights.
  if (!light_sample_shape(load_shape(l.shape), p, u.xy, ls.wi, ls.pdf, ls.dist) || !(ls.pdf > 0.0 && ls.pdf < T_INF)) return false;
  ls.pdf *= (1.0 - pe) / float(u_num_lights);
  ls.radiance = l.radiance;
  ls.shape = l.shape;
  return true;
}

// Density with which light_sample would pick direction wi from p, reaching the emitting
// shape s at distance t where its normal is n.
float light_pdf(ShapeRec s, vec3 p, vec3 wi, float t, vec3 n) {
  return light_pdf_shape(s, p, wi, t, n) * (1.0 - env_select_prob()) / float(u_num_lights);
}

#ifdef HAS_ENV_MAP
float env_light_pdf(vec3 wi) { return env_pdf(wi) * env_select_prob(); }
#endif
