// Diffuse: <Diffuse/>, Lambertian with albedo = tint (1 unless wrapped in <Attenuate>).
// Sampling follows SceneLevel's dotWeight: cosine-weighted (true) or uniform hemisphere
// (false); both are exact, so the image is the same and only the noise differs.
uniform int u_dot_weight;

bool delta_diffuse(MaterialRec m) { return false; }
vec3 albedo_diffuse(MaterialRec m) { return m.tint; }

vec3 eval_diffuse(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  if (wi.z <= 0.0 || wo.z <= 0.0) { pdf = 0.0; return vec3(0.0); }
  pdf = u_dot_weight != 0 ? pdf_cosine_hemisphere(wi) : pdf_uniform_hemisphere(wi);
  return m.tint * (INV_PI * wi.z);
}

bool sample_diffuse(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) {
  s.wi = u_dot_weight != 0 ? sample_cosine_hemisphere(u.xy) : sample_uniform_hemisphere(u.xy);
  s.delta = false;
  vec3 f = eval_diffuse(m, wo, s.wi, entering, s.pdf);
  s.weight = s.pdf > 0.0 ? f / s.pdf : vec3(0.0);
  return s.pdf > 0.0;
}
