// lights.glsl: next-event estimation. One light is chosen uniformly among the emissive
// shapes of samplable kinds; the shape's own snippet samples a direction towards it
// (sample_light_<kind>, through the generated light_sample_shape) with a solid-angle
// density, and light_pdf gives the same density for a direction found by BSDF sampling,
// for multiple importance sampling.
uniform int u_num_lights;

struct LightSample { vec3 wi; float pdf; vec3 radiance; int shape; };

bool light_sample(vec3 p, vec3 u, out LightSample ls) {
  if (u_num_lights == 0) return false;
  int li = min(int(u.z * float(u_num_lights)), u_num_lights - 1);
  LightRec l = load_light(li);
  if (!light_sample_shape(load_shape(l.shape), p, u.xy, ls.wi, ls.pdf) || !(ls.pdf > 0.0)) return false;
  ls.pdf /= float(u_num_lights);
  ls.radiance = l.radiance;
  ls.shape = l.shape;
  return true;
}

// Density with which light_sample would pick direction wi from p, reaching light `li`'s
// shape s at distance t where its normal is n.
float light_pdf(ShapeRec s, vec3 p, vec3 wi, float t, vec3 n) {
  return light_pdf_shape(s, p, wi, t, n) / float(u_num_lights);
}
