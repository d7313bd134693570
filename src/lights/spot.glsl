// SpotLight (lights/spot.h): a point light times KHR_lights_punctual's angular falloff,
// the square of clamp(cos theta * scale + offset, 0, 1) with
// scale = 1 / max(0.001, cos inner - cos outer), offset = -cos outer * scale (the
// extension README's reference code), theta the angle between the spot's direction and
// the direction from the light to p.
#include "lights/punctual.glsl"
float spot_falloff(LightRec l, vec3 from_light) {
  float scale = 1.0 / max(0.001, l.cos_inner - l.cos_outer);
  float a = clamp(dot(l.direction, from_light) * scale - l.cos_outer * scale, 0.0, 1.0);
  return a * a;
}

bool punctual_spot(LightRec l, vec3 p, out vec3 wi, out float dist, out vec3 e) {
  vec3 to = l.position - p;
  float d2 = dot(to, to);
  dist = sqrt(d2);
  wi = to / dist;
  e = l.radiance * (spot_falloff(l, -wi) * punctual_window(dist, l.range) / d2);
  return d2 > 0.0 && max3(e) > 0.0;
}
