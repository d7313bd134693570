// gltf_clearcoat.glsl: KHR_materials_clearcoat's layer (materials/gltf_lobes.h), compiled in
// only when a material uses it (HAS_GLTF_CLEARCOAT). The coat is a GGX lobe of ior 1.5
// (f0 = 0.04) and alpha = clearcoatRoughness^2 around its own normal n_c (in the shading
// frame), laid over the base as the extension's fresnel_coat does:
//     f = (1 - clearcoat F_c(n_c.v)) f_base + clearcoat F_c(n_c.v) f_coat,
//     F_c(c) = 0.04 + 0.96 (1 - c)^5,   f_coat = D G2 / (4 |n_c.l| |n_c.v|)
// (Fresnel of n_c.v, as the extension and the Khronos sample renderer write it: the base
// loses at most what the coat reflects, so the whole stays at most 1; the price is that
// f(v, l) != f(l, v) where the coat is, docs/gltf.md). The layer's cosine is n_c.l.
// Below clearcoatRoughness 0.03 the coat is a mirror about n_c.
#include "ggx.glsl"

float gltf_coat_fresnel(float c) {
  float s = clamp(1.0 - c, 0.0, 1.0), s2 = s * s;
  return 0.04 + 0.96 * s2 * s2 * s;
}

// The coat's lobe times its cosine (n_c.l) for wo, wi in the shading frame, and its
// sampling density (GGX visible normals around n_c); zero below the coat's horizon.
float gltf_coat_eval(vec3 nc, float alpha, vec3 wo, vec3 wi, out float pdf) {
  pdf = 0.0;
  float co = dot(nc, wo), ci = dot(nc, wi);
  if (co <= 0.0 || ci <= 0.0) return 0.0;
  float a2 = alpha * alpha, hc = dot(nc, normalize(wo + wi));
  float d = ggx_d(hc, a2);
  pdf = ggx_g1(co, a2) * d / (4.0 * co);
  return d * ggx_g2(co, ci, a2) / (4.0 * co);
}

// A direction from the coat's visible normals (the shading frame), or its mirror (smooth).
vec3 gltf_coat_sample(vec3 nc, float alpha, vec3 wo, vec2 u, bool smooth_coat) {
  if (smooth_coat) return reflect(-wo, nc);
  Frame fc = frame_from(nc);
  vec3 o = to_local(fc, wo);
  return from_local(fc, reflect(-o, sample_ggx_vndf(o, alpha, u)));
}
