// smooth_interface.glsl: the sample of a smooth dielectric interface, shared by
// SmoothDielectric and the glTF volume's smooth transmission (KHR_materials_volume):
// exact Fresnel picks reflection with probability F (total internal reflection gives
// F = 1), else refraction, so the one-sample weight is 1 for the reflection and
// 1 / eta^2 for the refraction (radiance is compressed into the denser medium:
// pbrt-v4, 9.5.2), each times the caller's own factor (tint, lobe weight).
// eta = n_transmitted / n_incident; u in [0, 1). Returns true when wi is the refraction,
// false when it is the mirror direction.
#include "fresnel.glsl"
#include "refract.glsl"

bool sample_smooth_interface(vec3 wo, float eta, float u, out vec3 wi) {
  if (u < fresnel_dielectric(wo.z, eta) || !refract_local(wo, eta, wi)) {
    wi = vec3(-wo.x, -wo.y, wo.z);
    return false;
  }
  return true;
}
