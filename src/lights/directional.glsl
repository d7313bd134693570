// DirectionalLight (lights/directional.h): irradiance E everywhere, from -direction;
// its shadow ray goes to infinity.
bool punctual_directional(LightRec l, vec3 p, out vec3 wi, out float dist, out vec3 e) {
  wi = -l.direction;
  dist = T_INF;
  e = l.radiance;
  return max3(e) > 0.0;
}
