// SmoothDielectric: <SmoothDielectric ior="n" color="r g b"/>: glass in air. Exact
// Fresnel picks reflection or refraction with probability F (total internal reflection
// gives F = 1), so the weight is 1 for reflection and tint / eta^2 for refraction
// (radiance is compressed into the denser medium: pbrt-v4, 9.5.2).
#include "fresnel.glsl"
#include "refract.glsl"

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
  vec3 wt;
  if (u.z < f || !refract_local(wo, eta, wt)) {
    s.wi = vec3(-wo.x, -wo.y, wo.z);
    s.weight = vec3(1.0);
  } else {
    s.wi = wt;
    s.weight = m.tint / (eta * eta);
  }
  return true;
}

// The medium inside (kMedium): its absorption per unit length.
bool medium_smooth_dielectric(MaterialRec m, out vec3 sigma) {
  sigma = smooth_dielectric_rec(m).sigma;
  return true;
}
