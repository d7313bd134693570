// ggx.glsl: the GGX (Trowbridge-Reitz) microfacet distribution, shared by every kind with
// a GGX lobe (materials/metal.glsl, materials/metallic_roughness.glsl). a2 = alpha^2.
//  - ggx_d: the normal distribution D(h) (Walter et al. 2007, eq. 33);
//  - ggx_lambda_term, ggx_g1, ggx_g2: Smith masking G1 and the height-correlated
//    masking-shadowing G2 = 1 / (1 + Lambda(o) + Lambda(i)) (Heitz 2014, eq. 99), written
//    with Lambda(c) = (sqrt(a2 + (1 - a2) c^2) / c - 1) / 2;
//  - sample_ggx_vndf, pdf_ggx_vndf: sampling of the visible normals (Heitz 2018, "Sampling
//    the GGX Distribution of Visible Normals", JCGT 7(4)) and its density as a density of
//    the reflected wi, G1(o) D(h) / (4 o.z).
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
