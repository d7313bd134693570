// SmoothDielectric: <SmoothDielectric ior="n" color="r g b"/>: glass in air, the smooth
// interface of smooth_interface.glsl (reflection with probability F, else refraction of
// weight tint / eta^2).
#include "smooth_interface.glsl"

bool delta_smooth_dielectric(MaterialRec m) { return true; }
vec3 albedo_smooth_dielectric(MaterialRec m) { return m.tint; }

vec3 eval_smooth_dielectric(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  return vec3(0.0);
}

bool sample_smooth_dielectric(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) {
  SmoothDielectricRec q = smooth_dielectric_rec(m);
  float eta = entering ? q.eta_inner / q.eta_outer : q.eta_outer / q.eta_inner;
  float f = fresnel_dielectric(wo.z, eta);
  s.pdf = 0.0;
  s.delta = true;
  s.weight = sample_smooth_interface(wo, eta, u.z, s.wi) ? m.tint / (eta * eta) : vec3(1.0);
  return true;
}

// The medium inside (kMedium): its absorption per unit length.
bool medium_smooth_dielectric(MaterialRec m, out vec3 sigma) {
  sigma = smooth_dielectric_rec(m).sigma;
  return true;
}
