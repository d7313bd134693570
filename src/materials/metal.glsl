// Metal: <Metal iorComplex="n k" | ior="n" glossiness="g" montecarlo="m" color="r g b"/>.
// A GGX microfacet conductor (Walter et al. 2007) with alpha = glossiness^2 and exact
// conductor Fresnel of n + ik; Smith height-correlated masking-shadowing (Heitz 2014).
// glossiness 0 is a perfect mirror (a delta lobe). montecarlo picks the sampling strategy,
// both exact: 1 = visible normals of GGX (Heitz 2018), 0 = cosine-weighted hemisphere.
#include "fresnel.glsl"
#include "ggx.glsl"

bool delta_metal(MaterialRec m) { return metal_rec(m).roughness < 0.03; }  // alpha < 1e-3
vec3 albedo_metal(MaterialRec m) { return m.tint; }

vec3 eval_metal(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  if (wi.z <= 0.0 || wo.z <= 0.0 || delta_metal(m)) return vec3(0.0);
  MetalRec q = metal_rec(m);
  float alpha = q.roughness * q.roughness;
  float a2 = alpha * alpha;
  vec3 hm = normalize(wo + wi);
  float d = ggx_d(hm.z, a2);
  float f = fresnel_conductor(dot(wi, hm), q.ior_n, q.ior_k);
  pdf = q.sampling >= 0.5 ? pdf_ggx_vndf(wo, hm, a2) : pdf_cosine_hemisphere(wi);
  return m.tint * (d * ggx_g2(wo.z, wi.z, a2) * f / (4.0 * wo.z));
}

bool sample_metal(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) {
  if (wo.z <= 0.0) return false;
  MetalRec q = metal_rec(m);
  if (delta_metal(m)) {
    s.wi = vec3(-wo.x, -wo.y, wo.z);
    s.weight = m.tint * fresnel_conductor(wo.z, q.ior_n, q.ior_k);
    s.pdf = 0.0;
    s.delta = true;
    return true;
  }
  float alpha = q.roughness * q.roughness;
  if (q.sampling >= 0.5) {
    vec3 hm = sample_ggx_vndf(wo, alpha, u.xy);
    s.wi = reflect(-wo, hm);
  } else {
    s.wi = sample_cosine_hemisphere(u.xy);
  }
  s.delta = false;
  vec3 f = eval_metal(m, wo, s.wi, entering, s.pdf);
  s.weight = s.pdf > 0.0 ? f / s.pdf : vec3(0.0);
  return s.pdf > 0.0;
}
