// fresnel.glsl: exact unpolarised Fresnel reflectance.

// Dielectric; eta = n_transmitted / n_incident, cos_i >= 0. Total internal reflection gives 1.
float fresnel_dielectric(float cos_i, float eta) {
  float sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0) return 1.0;
  float cos_t = sqrt(1.0 - sin2_t);
  float r_par = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  float r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5 * (r_par * r_par + r_perp * r_perp);
}

// Conductor with complex IOR n + ik relative to the outside medium (pbrt-v3's
// FrConductor, the closed form of the complex Fresnel equations).
float fresnel_conductor(float cos_i, float n, float k) {
  float c2 = cos_i * cos_i;
  float s2 = 1.0 - c2;
  float t0 = n * n - k * k - s2;
  float a2b2 = sqrt(max(t0 * t0 + 4.0 * n * n * k * k, 0.0));
  float a = sqrt(max(0.5 * (a2b2 + t0), 0.0));
  float t1 = a2b2 + c2;
  float t2 = 2.0 * cos_i * a;
  float rs = (t1 - t2) / max(t1 + t2, 1e-30);
  float t3 = c2 * a2b2 + s2 * s2;
  float t4 = t2 * s2;
  float rp = rs * (t3 - t4) / max(t3 + t4, 1e-30);
  return clamp(0.5 * (rp + rs), 0.0, 1.0);
}
