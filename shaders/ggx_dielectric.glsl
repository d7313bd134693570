// ggx_dielectric.glsl: the GGX microfacet dielectric of Walter et al. 2007, written as
// pbrt-v4's DielectricBxDF (9.7), shared by RoughDielectric (materials/rough_dielectric.glsl)
// and the glTF BSDF's volume (materials/metallic_roughness.glsl, KHR_materials_volume).
// Frames: wo.z > 0 (the side the ray came from), wi.z < 0 is refraction; eta = n on wi's
// far side / n on wo's; a2 = alpha^2. Refraction is tinted by `tint` and carries the
// radiance scaling 1 / eta^2 (pbrt-v4, 9.5.2); a smooth one is smooth_interface.glsl.
#include "fresnel.glsl"
#include "ggx.glsl"
#include "smooth_interface.glsl"  // (refract.glsl with it)

// f |n.i| and the density of wi (the sampler's below: VNDF, then F or 1 - F).
vec3 ggx_dielectric_eval(float alpha, float eta, vec3 tint, vec3 wo, vec3 wi, out float pdf) {
  pdf = 0.0;
  if (wo.z <= 0.0 || wi.z == 0.0) return vec3(0.0);
  float a2 = alpha * alpha;
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
  return tint * (d * g * (1.0 - f) * (-ih) * oh / (wo.z * denom) / (eta * eta));
}

// A direction from the lobe: a visible normal h (u.xy), then reflection with probability
// F(wo.h) (total internal reflection: 1), else refraction (uz). False where none.
bool ggx_dielectric_sample(float alpha, float eta, vec3 wo, vec2 u, float uz, out vec3 wi) {
  vec3 h = sample_ggx_vndf(wo, alpha, u);
  float oh = dot(wo, h);
  if (oh <= 0.0) return false;
  if (uz < fresnel_dielectric(oh, eta)) {
    wi = reflect(-wo, h);
    return wi.z > 0.0;
  }
  wi = refract(-wo, h, 1.0 / eta);
  return wi.z < 0.0 && dot(wi, wi) > 0.0;
}
