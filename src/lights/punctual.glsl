// What the punctual light kinds share (lights/light.h): KHR_lights_punctual's range
// window, clamp(1 - (d / range)^4, 0, 1) (the README's recommended falloff; range 0:
// none), applied on top of the inverse square law.
float punctual_window(float d, float range) {
  if (range <= 0.0) return 1.0;
  float x = d / range;
  x *= x;
  return clamp(1.0 - x * x, 0.0, 1.0);
}
