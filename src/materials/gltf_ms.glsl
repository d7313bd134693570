// gltf_ms.glsl: the multiple-scattering energy compensation of the glTF BSDF's GGX lobes
// (materials/metallic_roughness.glsl), compiled in only when on (HAS_GLTF_MS: the default;
// RenderSettings::gltf_ms, --gltf-ms off renders the specification's single-scattering
// model). Kulla and Conty 2017 ("Revisiting Physically Based Shading at Imageworks",
// sections 4 and 5): with E(mu) the directional albedo of the GGX lobe (F = 1) and
// E_avg = 2 int E mu dmu,
//  - the metal gains f_ms = F_ms (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)),
//    F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), F_avg = F0 + (1 - F0) / 21 (Schlick's);
//  - the dielectric's base is weighted by (1 - E_s(mu_o)) (1 - E_s(mu_i)) / (1 - E_s,avg)
//    instead of 1 - F(v.h), E_s = specular (f0 E(mu) + (1 - f0) E2(mu)) the specular
//    layer's albedo with its Schlick Fresnel (linear in f0; f0 = max(F0)).
// E and E2 (the Schlick-weighted albedo) are tabulated at build time by
// tools/gen_ggx_ms_lut.py (24 x 24 over sqrt(mu) and roughness; E_avg of the table's own
// interpolant, so both compensation lobes integrate to exactly what is missing).
#include "materials/gltf_ms_lut.glsl"

// (E, E2) of the GGX lobe of roughness r (alpha = r^2) at mu = n.v: bilinear in (sqrt(mu), r).
vec2 gltf_ms_e(float mu, float r) {
  float x = sqrt(clamp(mu, 0.0, 1.0)) * float(GGX_E_MU - 1);
  float y = clamp(r, 0.0, 1.0) * float(GGX_E_R - 1);
  int i = min(int(x), GGX_E_MU - 2), j = min(int(y), GGX_E_R - 2);
  float fx = x - float(i), fy = y - float(j);
  int k = j * GGX_E_MU + i;
  return mix(mix(ggx_e_entry(k), ggx_e_entry(k + 1), fx), mix(ggx_e_entry(k + GGX_E_MU), ggx_e_entry(k + GGX_E_MU + 1), fx), fy);
}
// Their averages 2 int E mu dmu (the same interpolation in r).
vec2 gltf_ms_eavg(float r) {
  float y = clamp(r, 0.0, 1.0) * float(GGX_E_R - 1);
  int j = min(int(y), GGX_E_R - 2);
  return mix(ggx_eavg_entry(j), ggx_eavg_entry(j + 1), y - float(j));
}
