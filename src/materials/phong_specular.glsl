// PhongSpecular: <PhongSpecular n="100" color="r g b"/>: the normalised modified Phong
// lobe of Lafortune and Willems (1994), f = tint (n + 2) / (2 pi) cos^n(alpha), alpha the
// angle between wi and the mirror direction of wo; energy-conserving for tint <= 1.
// Sampling draws cos^n(alpha) about the mirror direction, pdf = (n + 1) / (2 pi) cos^n;
// directions below the surface are rejected (the pdf there is lost, not moved).
bool delta_phong_specular(MaterialRec m) { return false; }
vec3 albedo_phong_specular(MaterialRec m) { return m.tint; }

vec3 eval_phong_specular(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  if (wi.z <= 0.0 || wo.z <= 0.0) return vec3(0.0);
  float n = phong_specular_rec(m).exponent;
  float c = max(dot(wi, vec3(-wo.x, -wo.y, wo.z)), 0.0);
  // The lobe lives where c > 0; pow(0, 0) (n = 0) is undefined in GLSL (exp2(0 * -inf):
  // NaN on some drivers), so c = 0 is not passed to it.
  float lobe = c > 0.0 ? pow(c, n) * INV_PI * 0.5 : 0.0;
  pdf = (n + 1.0) * lobe;
  return m.tint * ((n + 2.0) * lobe * wi.z);
}

bool sample_phong_specular(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) {
  if (wo.z <= 0.0) return false;
  float cos_a = pow(u.x, 1.0 / (phong_specular_rec(m).exponent + 1.0));
  float sin_a = sqrt(max(0.0, 1.0 - cos_a * cos_a));
  float phi = TWO_PI * u.y;
  Frame lobe = frame_from(vec3(-wo.x, -wo.y, wo.z));
  s.wi = from_local(lobe, vec3(sin_a * cos(phi), sin_a * sin(phi), cos_a));
  s.delta = false;
  vec3 f = eval_phong_specular(m, wo, s.wi, entering, s.pdf);
  s.weight = s.pdf > 0.0 ? f / s.pdf : vec3(0.0);
  return s.pdf > 0.0;
}
