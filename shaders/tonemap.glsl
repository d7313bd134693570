// tonemap.glsl: display transforms from linear radiance to display values in [0, 1].
// Applied on display only; the accumulation always holds linear radiance.
// Ids match ToneMap in src/core/tonemap.h.
#define TM_NONE 0
#define TM_LINEAR 1
#define TM_REINHARD 2
#define TM_FILMIC 3
#define TM_SRGB 4
#define TM_UNCHARTED2 5
#define TM_ACES 6

vec3 gamma22(vec3 c) { return pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)); }

vec3 srgb_oetf(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// John Hable's Uncharted 2 curve (filmicgames.com/archives/75), white point 11.2:
// (x (A x + C B) + D E) / (x (A x + B) + D F) - E / F, over one denominator so that
// black stays exactly 0 in float (the two terms cancel at x = 0; their rounding error,
// through the 1/2.2 power, lifted black to 2e-4).
vec3 hable(vec3 x) {
  const float A = 0.15, B = 0.50, C = 0.10, D = 0.20, E = 0.02, F = 0.30;
  return x * (A * (F - E) * x + B * (C * F - E)) / (F * (x * (A * x + B) + D * F));
}

// ACES filmic fit by Krzysztof Narkowicz (2016).
vec3 aces_fit(vec3 x) {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 tone_map(vec3 c, int op, float exposure) {
  c = max(c, vec3(0.0)) * exposure;
  if (op == TM_NONE) return clamp(c, 0.0, 1.0);
  if (op == TM_LINEAR) return gamma22(c);
  if (op == TM_REINHARD) return gamma22(c / (1.0 + c));
  if (op == TM_FILMIC) {  // Hejl and Burgess-Dawson; the curve includes the gamma
    vec3 x = max(vec3(0.0), c - 0.004);
    return (x * (6.2 * x + 0.5)) / (x * (6.2 * x + 1.7) + 0.06);
  }
  if (op == TM_SRGB) return srgb_oetf(c);
  if (op == TM_UNCHARTED2) return gamma22(hable(2.0 * c) / hable(vec3(11.2)));
  return srgb_oetf(aces_fit(c));
}
