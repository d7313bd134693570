// RoughDielectric: the GGX microfacet dielectric of Walter et al. 2007 (the model:
// rough_dielectric.h; the lobe: ggx_dielectric.glsl). eta = n on wi's far side / n on wo's.
#include "ggx_dielectric.glsl"

bool delta_rough_dielectric(MaterialRec m) { return false; }
vec3 albedo_rough_dielectric(MaterialRec m) { return m.tint; }

float rough_dielectric_eta(MaterialRec m, bool entering) {
  float n = rough_dielectric_rec(m).eta_inner;
  return entering ? n : 1.0 / n;
}

// f |n.i| and the density of wi (the sampler's: VNDF, then F or 1 - F).
vec3 eval_rough_dielectric(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  return ggx_dielectric_eval(rough_dielectric_rec(m).alpha, rough_dielectric_eta(m, entering), m.tint, wo, wi, pdf);
}

bool sample_rough_dielectric(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) {
  s.delta = false;
  if (wo.z <= 0.0) return false;
  if (!ggx_dielectric_sample(rough_dielectric_rec(m).alpha, rough_dielectric_eta(m, entering), wo, u.xy, u.z, s.wi)) return false;
  vec3 f = eval_rough_dielectric(m, wo, s.wi, entering, s.pdf);
  s.weight = s.pdf > 0.0 ? f / s.pdf : vec3(0.0);
  return s.pdf > 0.0;
}

// The medium inside (kMedium): its absorption per unit length.
bool medium_rough_dielectric(MaterialRec m, out vec3 sigma) {
  sigma = rough_dielectric_rec(m).sigma;
  return true;
}
