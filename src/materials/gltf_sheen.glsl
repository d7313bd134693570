// gltf_sheen.glsl: KHR_materials_sheen's lobe (materials/gltf_lobes.h), compiled in only
// when a material uses it (HAS_GLTF_SHEEN). The Charlie distribution of Estevez and Kulla
// 2017 ("Production Friendly Microfacet Sheen BRDF"), alpha = sheenRoughness^2:
//     D(h) = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi),
//     f_sheen = sheenColor D V,  V = 1 / ((1 + Lambda(n.v) + Lambda(n.l)) 4 |n.l| |n.v|)
// with their fitted Lambda (the extension's "Sheen visibility"; the Khronos sample
// renderer's V_Sheen), over the base scaled by the extension's albedo scaling
//     min(1 - max(sheenColor) E(n.v), 1 - max(sheenColor) E(n.l))   (at least 0)
// where E(mu, r) is the lobe's directional albedo, tabulated at build time
// (tools/gen_sheen_lut.py -> materials/gltf_sheen_lut.glsl). Sheen roughness is clamped
// to the table's lowest, 0.05. The lobe is sampled by the cosine-weighted hemisphere
// together with the diffuse one (metallic_roughness.glsl).
#include "materials/gltf_sheen_lut.glsl"

float gltf_sheen_l(float x, float alpha) {
  float t = (1.0 - alpha) * (1.0 - alpha);
  float a = mix(21.5473, 25.3245, t), b = mix(3.82987, 3.32435, t), c = mix(0.19823, 0.16801, t);
  float d = mix(-1.97760, -1.27393, t), e = mix(-4.32054, -4.85967, t);
  return a / (1.0 + b * pow(x, c)) + d * x + e;
}
float gltf_sheen_lambda(float c, float alpha) {
  c = min(c, 1.0);  // a cosine that rounded above 1 would make pow's base 1 - c negative: NaN
  return c < 0.5 ? exp(gltf_sheen_l(c, alpha)) : exp(2.0 * gltf_sheen_l(0.5, alpha) - gltf_sheen_l(1.0 - c, alpha));
}
float gltf_sheen_roughness(float r) { return clamp(r, SHEEN_E_R_MIN, 1.0); }

// The lobe (colour 1) times n.l for wo, wi in the shading frame (both above it).
float gltf_sheen_eval(float r, vec3 wo, vec3 wi) {
  float alpha = r * r;
  vec3 h = normalize(wo + wi);
  float s2 = max(0.0, 1.0 - h.z * h.z);
  float d = (2.0 + 1.0 / alpha) * pow(s2, 0.5 / alpha) * (0.5 * INV_PI);
  return d / ((1.0 + gltf_sheen_lambda(wo.z, alpha) + gltf_sheen_lambda(wi.z, alpha)) * 4.0 * wo.z);
}

// E(mu, r) from the table, bilinear.
float gltf_sheen_albedo(float mu, float r) {
  float x = clamp(mu, 0.0, 1.0) * float(SHEEN_E_MU - 1);
  float y = clamp((r - SHEEN_E_R_MIN) / (1.0 - SHEEN_E_R_MIN), 0.0, 1.0) * float(SHEEN_E_R - 1);
  int i = min(int(x), SHEEN_E_MU - 2), j = min(int(y), SHEEN_E_R - 2);
  float fx = x - float(i), fy = y - float(j);
  int k = j * SHEEN_E_MU + i;
  return mix(mix(sheen_e_entry(k), sheen_e_entry(k + 1), fx), mix(sheen_e_entry(k + SHEEN_E_MU), sheen_e_entry(k + SHEEN_E_MU + 1), fx), fy);
}
