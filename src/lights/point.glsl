// PointLight (lights/point.h): irradiance I / d^2 on a surface facing it, windowed by the
// range (lights/punctual.glsl).
#include "lights/punctual.glsl"

bool punctual_point(LightRec l, vec3 p, out vec3 wi, out float dist, out vec3 e) {
  vec3 to = l.position - p;
  float d2 = dot(to, to);
  dist = sqrt(d2);
  wi = to / dist;
  e = l.radiance * (punctual_window(dist, l.range) / d2);
  return d2 > 0.0 && max3(e) > 0.0;
}
