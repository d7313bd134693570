// lights.glsl: next-event estimation. One light record is chosen with probability
// proportional to its power (render/light_select.h: an alias table in the records:
// slot i uniformly, kept with probability alias_p, else its alias; pmf its probability).
// An emitting shape's own snippet samples a direction towards it (sample_light_<kind>,
// through the generated light_sample_shape) with a solid-angle density, and light_pdf
// gives the same density for a direction found by BSDF sampling, for multiple importance
// sampling. A punctual light (shape < 0; lights/<kind>.glsl through the generated
// punctual_sample) is a delta: its sample carries the irradiance it gives, is weighted 1
// (no BSDF sample can reach it) and light_pdf never sees it.
uniform int u_num_lights;
// 1 while the camera is inside a box that seals lights off (render/light_select.h): then
// the sealed lights may contribute, and every light is selected with probability 1/n.
uniform int u_lights_uniform;

// dist: how far along wi the light's surface is (T_INF for the environment).
// delta: a punctual light: radiance is the irradiance at p from wi and pdf the
// probability of its selection (the estimate is f * radiance / pdf, weight 1).
struct LightSample { vec3 wi; float pdf; vec3 radiance; int shape; float dist; bool delta; };

// With an environment map, half the light samples go to it (all of them when the scene
// has no other lights); the densities below include that choice.
float env_select_prob() {
#ifdef HAS_ENV_MAP
  return u_num_lights > 0 ? 0.5 : 1.0;
#else
  return 0.0;
#endif
}

bool have_lights() { return u_num_lights > 0 || env_select_prob() > 0.0; }

// The light record chosen by u in [0, 1) from the alias table (its fraction reused for
// the alias choice). A single light: always record 0.
LightRec select_light(float u, out float pmf) {
  float x = u * float(u_num_lights);
  int i = min(int(x), u_num_lights - 1);
  LightRec l = load_light(i);
  if (u_lights_uniform != 0) {
    pmf = 1.0 / float(u_num_lights);
    return l;
  }
  if (x - float(i) >= l.alias_p) l = load_light(l.alias);
  pmf = l.pmf;
  return l;
}

float light_pmf(int light) { return u_lights_uniform != 0 ? 1.0 / float(u_num_lights) : load_light(light).pmf; }

bool light_sample(vec3 p, vec3 u, out LightSample ls) {
  float pe = env_select_prob();
  ls.delta = false;
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
  float pmf;
  LightRec l = select_light(u.z, pmf);
  if (!(pmf > 0.0)) return false;  // every light sealed off (render/light_select.h)
#ifdef HAS_PUNCTUAL
  if (l.shape < 0) {
    ls.delta = true;
    ls.shape = -1;  // nothing to skip: the shadow ray ends at the light (or at infinity)
    if (!punctual_sample(l, p, ls.wi, ls.dist, ls.radiance)) return false;
    ls.pdf = (1.0 - pe) * pmf;
    return true;
  }
#endif
  // A direction of infinite density (a light too small for float seen from far) carries
  // radiance / pdf = 0: no sample, rather than inf / inf in the weights.
  if (!light_sample_shape(load_shape(l.shape), p, u.xy, ls.wi, ls.pdf, ls.dist) || !(ls.pdf > 0.0 && ls.pdf < T_INF)) return false;
  ls.pdf *= (1.0 - pe) * pmf;
  ls.radiance = l.radiance;
  ls.shape = l.shape;
  return true;
}

// Density with which light_sample would pick direction wi from p, reaching the emitting
// shape s (a light: s.light >= 0) at distance t where its normal is n.
float light_pdf(ShapeRec s, vec3 p, vec3 wi, float t, vec3 n) {
  return light_pdf_shape(s, p, wi, t, n) * (1.0 - env_select_prob()) * light_pmf(s.light);
}

#ifdef HAS_ENV_MAP
float env_light_pdf(vec3 wi) { return env_pdf(wi) * env_select_prob(); }
#endif
