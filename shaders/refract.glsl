// refract.glsl: refraction through the local +z interface, shared by the dielectric kinds.
// eta = n_transmitted / n_incident. Returns false on total internal reflection.
bool refract_local(vec3 wo, float eta, out vec3 wt) {
  float sin2_t = (1.0 - wo.z * wo.z) / (eta * eta);
  if (sin2_t >= 1.0) return false;
  float cos_t = sqrt(1.0 - sin2_t);
  wt = vec3(-wo.x / eta, -wo.y / eta, -cos_t);
  return true;
}
