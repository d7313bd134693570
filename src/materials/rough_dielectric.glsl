// RoughDielectric: the GGX microfacet dielectric of Walter et al. 2007 (the model:
// rough_dielectric.h), written as pbrt-v4's DielectricBxDF (9.7). Frames: wo.z > 0 (the
// side the ray came from), wi.z < 0 is refraction; eta = n on wi's far side / n on wo's.
#include "fresnel.glsl"
#include "ggx.glsl"

bool delta_rough_dielectric(MaterialRec m) { return false; }
vec3 albedo_rough_dielectric(MaterialRec m) { return m.tint; }

float rough_dielectric_eta(MaterialRec m, bool entering) {
  float n = rough_dielectric_rec(m).eta_inner;
  return entering ? n : 1.0 / n;
}

// f |n.i| and the density of wi (the sampler's: VNDF, then F or 1 - F).
vec3 eval_rough_dielectric(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  if (wo.z <= 0.0 || wi.z == 0.0) return vec3(0.0);
  RoughDielectricRec q = rough_dielectric_rec(m);
  float eta = rough_dielectric_eta(m, entering), a2 = q.alpha * q.alpha;
  bool reflect = wi.z > 0.0;
  vec3 h = reflect ? wo + wi : wo + eta * wi;
  if (dot(h, h) == 0.0) return vec3(0.0);
  h = normalize(h);
  if (h.z < 0.0) h = -h;
  float oh = dot(wo, h), ih = dot(wi, h);
  if (oh <= 0.0 || (reflect ? ih <= 0.0 : ih >= 0.0)) return vec3(0.0);  // microfacets seen from behind
  float f = fresnel_dielectric(oh, eta), d = ggx_d(h.z, a2), g = ggx_g2(wo.z, abs(wi.z), a2);
  float vndf = ggx_g1(wo.z, a2) * d * oh / wo.z;  // the visible normals' density of h
  if (reflect) {
    pdf = vndf / (4.0 * oh) * f;
    return vec3(d * g * f / (4.0 * wo.z));
  }
  float denom = ih + oh / eta;
  denom *= denom;
  pdf = vndf * (-ih / denom) * (1.0 - f);
  return m.tint * (d * g * (1.0 - f) * (-ih) * oh / (wo.z * denom) / (eta * eta));
}

bool sample_rough_dielectric(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) {
  s.delta = false;
  if (wo.z <= 0.0) return false;
  RoughDielectricRec q = rough_dielectric_rec(m);
  float eta = rough_dielectric_eta(m, entering);
  vec3 h = sample_ggx_vndf(wo, q.alpha, u.xy);
  float oh = dot(wo, h);
  if (oh <= 0.0) return false;
  if (u.z < fresnel_dielectric(oh, eta)) {  // total internal reflection: F = 1
    s.wi = reflect(-wo, h);
    if (s.wi.z <= 0.0) return false;
  } else {
    s.wi = refract(-wo, h, 1.0 / eta);
    if (s.wi.z >= 0.0 || dot(s.wi, s.wi) == 0.0) return false;
  }
  vec3 f = eval_rough_dielectric(m, wo, s.wi, entering, s.pdf);
  s.weight = s.pdf > 0.0 ? f / s.pdf : vec3(0.0);
  return s.pdf > 0.0;
}

// The medium inside (kMedium): its absorption per unit length.
vec3 medium_sigma_rough_dielectric(MaterialRec m) { return rough_dielectric_rec(m).sigma; }
