// environment.glsl: an equirectangular HDR environment map (included when the scene has
// one). Directions: theta from +y, phi from +x towards +z, plus the rotation. Radiance is
// the texel's (piecewise constant, matching the sampling density exactly). Sampling
// inverts the CDFs of render/environment.h with binary searches; the solid-angle density
// is f(i, j) / integral / (2 pi^2 sin theta) with f = luminance * sin(theta at the row).
uniform highp sampler2D u_env_map;  // w x h, row 0 at theta = 0
uniform highp sampler2D u_env_cdf;  // (w + 1) x (h + 1), see EnvDistribution
uniform ivec2 u_env_size;
uniform float u_env_rotation;       // radians
uniform float u_env_intensity;
uniform float u_env_integral;

vec2 env_uv(vec3 d) {
  float theta = acos(clamp(d.y, -1.0, 1.0));
  float phi = atan(d.z, d.x) - u_env_rotation;
  return vec2(fract(phi / TWO_PI), theta / PI);
}

vec3 env_dir(vec2 uv) {
  float phi = uv.x * TWO_PI + u_env_rotation;
  float theta = uv.y * PI;
  return vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
}

ivec2 env_texel(vec2 uv) { return clamp(ivec2(uv * vec2(u_env_size)), ivec2(0), u_env_size - 1); }

vec3 env_radiance(vec3 d) { return texelFetch(u_env_map, env_texel(env_uv(d)), 0).rgb * u_env_intensity; }

// Density of direction d (solid angle) under env_sample, given its texel.
float env_density(ivec2 t, float sin_theta) {
  if (u_env_integral <= 0.0 || sin_theta <= 0.0) return 0.0;
  float sin_row = sin(PI * (float(t.y) + 0.5) / float(u_env_size.y));
  float f = luminance(texelFetch(u_env_map, t, 0).rgb) * sin_row;
  return f / (u_env_integral * 2.0 * PI * PI * sin_theta);
}

float env_pdf(vec3 d) {
  vec2 uv = env_uv(d);
  return env_density(env_texel(uv), sin(uv.y * PI));
}

float env_cdf(int x, int row) { return texelFetch(u_env_cdf, ivec2(x, row), 0).r; }

// The largest i in [0, n) with cdf(i) <= u, in a row of n + 1 increasing entries.
int env_search(int row, int n, float u) {
  int lo = 0, hi = n;
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (env_cdf(mid, row) <= u) lo = mid;
    else hi = mid;
  }
  return lo;
}

bool env_sample(vec2 u, out vec3 wi, out float pdf, out vec3 radiance) {
  int w = u_env_size.x, h = u_env_size.y;
  int j = env_search(h, h, u.y);
  float c0 = env_cdf(j, h), c1 = env_cdf(j + 1, h);
  int i = env_search(j, w, u.x);
  float d0 = env_cdf(i, j), d1 = env_cdf(i + 1, j);
  vec2 uv = vec2((float(i) + clamp((u.x - d0) / max(d1 - d0, 1e-30), 0.0, 1.0)) / float(w),
                 (float(j) + clamp((u.y - c0) / max(c1 - c0, 1e-30), 0.0, 1.0)) / float(h));
  wi = env_dir(uv);
  pdf = env_density(ivec2(i, j), sin(uv.y * PI));
  radiance = texelFetch(u_env_map, ivec2(i, j), 0).rgb * u_env_intensity;
  return pdf > 0.0;
}
