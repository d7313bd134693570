// MetallicRoughness: the glTF 2.0 metallic-roughness BSDF (Appendix B; the model and the
// XML: metallic_roughness.h). With s5 = (1 - v.h)^5, F_d = f0 + (1 - f0) s5 (dielectric)
// and F_m = tint + (1 - tint) s5 (metal, f0 = the base colour):
//     f = (1 - metallic) [(1 - F_d) tint / pi + F_d f_s] + metallic F_m f_s,
//     f_s = D G2 / (4 |n.l| |n.v|)   (GGX, height-correlated Smith: ggx.glsl)
// Sampling picks the specular lobe (GGX visible normals, Heitz 2018) with probability p_s
// from the lobes' Fresnel-weighted albedos at wo (clamped to [0.1, 0.9] when both lobes
// carry light, so neither is starved), else the cosine-weighted diffuse lobe; the pdf is
// the mixture's (one-sample MIS, as pbrt's BSDFs do). Below roughness 0.03 the specular
// lobe is a mirror chosen with p_s, weight F / p_s; the material is a delta one only when
// it is also fully metallic.
#include "ggx.glsl"
bool delta_metallic_roughness(MaterialRec m) {
  MetallicRoughnessRec q = metallic_roughness_rec(m);
  return q.roughness < 0.03 && q.metallic >= 1.0;
}
vec3 albedo_metallic_roughness(MaterialRec m) { return m.tint; }

float mr_schlick5(float c) {
  float s = clamp(1.0 - c, 0.0, 1.0), s2 = s * s;
  return s2 * s2 * s;
}

float mr_specular_probability(MaterialRec m, MetallicRoughnessRec q, float cos_o) {
  float s5 = mr_schlick5(cos_o);
  float fd = q.f0 + (1.0 - q.f0) * s5;
  float ws = q.metallic * luminance(m.tint + (1.0 - m.tint) * s5) + (1.0 - q.metallic) * fd;
  float wd = (1.0 - q.metallic) * (1.0 - fd) * luminance(m.tint);
  if (wd <= 0.0) return 1.0;  // no diffuse light: all specular
  return clamp(ws / (ws + wd), 0.1, 0.9);
}

// The smooth lobe's reflectance at incidence cos_o (a mirror: h = n).
vec3 mr_mirror_fresnel(MaterialRec m, MetallicRoughnessRec q, float cos_o) {
  float s5 = mr_schlick5(cos_o);
  return (1.0 - q.metallic) * vec3(q.f0 + (1.0 - q.f0) * s5) + q.metallic * (m.tint + (1.0 - m.tint) * s5);
}

vec3 eval_metallic_roughness(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  if (wi.z <= 0.0 || wo.z <= 0.0) return vec3(0.0);
  MetallicRoughnessRec q = metallic_roughness_rec(m);
  vec3 h = normalize(wo + wi);
  float s5 = mr_schlick5(dot(wo, h));
  float fd = q.f0 + (1.0 - q.f0) * s5;
  float ps = mr_specular_probability(m, q, wo.z);
  vec3 f = (1.0 - q.metallic) * (1.0 - fd) * m.tint * (INV_PI * wi.z);
  pdf = (1.0 - ps) * pdf_cosine_hemisphere(wi);
  if (q.roughness >= 0.03) {
    float alpha = q.roughness * q.roughness, a2 = alpha * alpha;
    vec3 fresnel = (1.0 - q.metallic) * vec3(fd) + q.metallic * (m.tint + (1.0 - m.tint) * s5);
    f += fresnel * (ggx_d(h.z, a2) * ggx_g2(wo.z, wi.z, a2) / (4.0 * wo.z));  // f_s |n.l|
    pdf += ps * pdf_ggx_vndf(wo, h, a2);
  }
  return f;
}

bool sample_metallic_roughness(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) {
  if (wo.z <= 0.0) return false;
  MetallicRoughnessRec q = metallic_roughness_rec(m);
  float ps = mr_specular_probability(m, q, wo.z);
  bool specular = u.z < ps;
  if (specular && q.roughness < 0.03) {
    s.wi = vec3(-wo.x, -wo.y, wo.z);
    s.weight = mr_mirror_fresnel(m, q, wo.z) / ps;
    s.pdf = 0.0;
    s.delta = true;
    return true;
  }
  s.wi = specular ? reflect(-wo, sample_ggx_vndf(wo, q.roughness * q.roughness, u.xy)) : sample_cosine_hemisphere(u.xy);
  s.delta = false;
  vec3 f = eval_metallic_roughness(m, wo, s.wi, entering, s.pdf);
  s.weight = s.pdf > 0.0 ? f / s.pdf : vec3(0.0);
  return s.pdf > 0.0;
}
