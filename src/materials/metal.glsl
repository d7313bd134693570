// Metal: <Metal iorComplex="n k" | ior="n" glossiness="g" montecarlo="m" color="r g b"/>.
// A GGX microfacet conductor (Walter et al. 2007) with alpha = glossiness^2 and exact
// conductor Fresnel of n + ik; Smith height-correlated masking-shadowing (Heitz 2014).
// glossiness 0 is a perfect mirror (a delta lobe). montecarlo picks the sampling strategy,
// both exact: 1 = visible normals of GGX (Heitz 2018), 0 = cosine-weighted hemisphere.
#include "fresnel.glsl"

bool delta_metal(MaterialRec m) { return metal_rec(m).roughness < 0.03; }  // alpha < 1e-3
vec3 albedo_metal(MaterialRec m) { return m.tint; }

float ggx_d(float nh, float a2) {
  float d = nh * nh * (a2 - 1.0) + 1.0;
  return a2 / (PI * d * d);
}
float ggx_lambda_term(float c, float a2) { return sqrt(a2 + (1.0 - a2) * c * c); }
float ggx_g1(float c, float a2) { return 2.0 * c / (c + ggx_lambda_term(c, a2)); }
float ggx_g2(float co, float ci, float a2) {
  return 2.0 * co * ci / (co * ggx_lambda_term(ci, a2) + ci * ggx_lambda_term(co, a2));
}

// Density of GGX visible-normal sampling, as a density of wi.
float pdf_ggx_vndf(vec3 wo, vec3 hm, float a2) {
  return ggx_g1(wo.z, a2) * ggx_d(hm.z, a2) / (4.0 * wo.z);
}

vec3 sample_ggx_vndf(vec3 wo, float alpha, vec2 u) {
  vec3 vh = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));
  float lensq = vh.x * vh.x + vh.y * vh.y;
  vec3 t1 = lensq > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(lensq) : vec3(1.0, 0.0, 0.0);
  vec3 t2 = cross(vh, t1);
  float r = sqrt(u.x);
  float phi = TWO_PI * u.y;
  float p1 = r * cos(phi);
  float p2 = r * sin(phi);
  float s = 0.5 * (1.0 + vh.z);
  p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * p2;
  vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  return normalize(vec3(alpha * nh.x, alpha * nh.y, max(1e-6, nh.z)));
}

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
