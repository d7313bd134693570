// denoise.glsl: the denoiser (render/denoise.h), four kinds of fragment pass chosen by
// PT_DENOISE_PASS (one small program each):
//   0 prepare: radiance / albedo (demodulation) and the variance of that pixel mean's
//     luminance, from the accumulator's per-channel variance of the samples (v / (n - 1):
//     core/metrics.h); below 4 samples from the 5x5 neighbourhood instead (SVGF's
//     spatial estimate for short histories), the per-pixel one being too noisy or 0;
//   1 one a-trous iteration (Dammertz et al. 2010) with step u_step: a 5x5 B3-spline
//     kernel whose taps are weighted by SVGF's edge-stopping functions (Schied et al.
//     2017, eq. 3-5): depth (against the depth's screen gradient), shading normal
//     (cosine^128), first-hit albedo (not SVGF's: a light's rim shares the ceiling's plane
//     and normal) and luminance (against the standard deviation of the pixel's
//     luminance, its variance blurred 3x3), the variance filtered along with squared
//     weights (SVGF eq. 2);
//   3 regression: weighted local first-order regression (Moon et al. 2014, "Adaptive
//     Rendering based on Weighted Local Regression"; Bitterli et al. 2016, "Nonlinearly
//     Weighted First-order Regression for Denoising Monte Carlo Renderings"): the image of
//     a-trous iteration 1 (u_noisy) fitted in a window as linear in the screen offset,
//     with the geometric weights and range weights from the last iteration's output (the
//     guide, u_input); the pixel gets the fit's value at its centre;
//   2 finish: re-modulated by the albedo and blended with the raw mean by u_weight;
//   4 change: per block of u_block x u_block pixels, the sum of the weight-1 image's
//     relative squared change, (albedo (filtered - demodulated))^2 / (raw^2 + 0.01) over
//     the channels: D's terms, from which the blend's weight is measured (render/denoise.h,
//     Denoiser::run).
// The output of every pass moves the pixel's own value by a weighted mean of differences
// (x_p + sum w (x_q - x_p) / sum w; the regression: x_p + the intercept of the fit of
// x_q - x_p), and the finish adds weight * albedo * (filtered - own demodulated value) to
// the raw radiance: a constant image, or weight 0, comes back bit for bit.
uniform highp sampler2D u_radiance;  // accumulator: mean RGB, A the blue channel's variance
uniform highp sampler2D u_stats;     // accumulator: z, w the red and green channels' variance
uniform highp sampler2D u_aux0;      // albedo RGB, view depth
uniform highp sampler2D u_aux1;      // shading normal (mean over the samples)
uniform highp sampler2D u_input;     // passes 1, 2, 3: demodulated RGB and its luminance variance
uniform highp sampler2D u_noisy;     // pass 3: the image fitted (DenoiseParams::reg_input)
uniform int u_samples;
uniform int u_step;                  // pass 1: the a-trous step, 1, 2, 4, ...
uniform float u_weight;              // pass 2: blend weight of the filtered image
uniform float u_sigma_z, u_sigma_n, u_sigma_l, u_sigma_a;
uniform float u_reg_rel, u_reg_sd, u_reg_ridge;  // pass 3: the guide's tolerance, the ridge
uniform int u_block;                 // pass 4: pixels per block side
out vec4 o_color;

const vec3 kLum = vec3(0.2126, 0.7152, 0.0722);
const float kMinAlbedo = 0.01;  // demodulation by max(albedo, this): black surfaces, lights

ivec2 g_size;
bool inside(ivec2 q) { return all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, g_size)); }
vec3 safe_albedo(ivec2 q) { return max(texelFetch(u_aux0, q, 0).rgb, vec3(kMinAlbedo)); }
vec3 demodulated(ivec2 q) { return texelFetch(u_radiance, q, 0).rgb / safe_albedo(q); }
float depth(ivec2 q) { return texelFetch(u_aux0, q, 0).a; }

// The luminance variance of pixel q's mean, demodulated, from the per-channel variance of
// its samples: (sum w_c sd_c)^2, exact for proportional channels, else an upper bound.
float pixel_variance(ivec2 q) {
  vec3 v = vec3(texelFetch(u_stats, q, 0).zw, texelFetch(u_radiance, q, 0).a) / float(max(u_samples - 1, 1));
  float sd = dot(kLum, sqrt(max(v, vec3(0.0))) / safe_albedo(q));
  return sd * sd;
}

// The depth's screen gradient at p, per axis the smaller one-sided difference (an edge
// does not make a surface look steep).
vec2 depth_gradient(ivec2 p) {
  float z = depth(p);
  vec2 g = vec2(1.0e30);
  for (int k = 0; k < 2; ++k) {
    ivec2 e = k == 0 ? ivec2(1, 0) : ivec2(0, 1);
    if (inside(p + e)) g[k] = min(g[k], abs(depth(p + e) - z));
    if (inside(p - e)) g[k] = min(g[k], abs(depth(p - e) - z));
    if (g[k] > 1.0e29) g[k] = 0.0;
  }
  return g;
}

// What the geometric weights need of pixel p, fetched once.
struct Guide {
  float z;     // depth
  vec2 grad;   // depth_gradient
  vec3 n;      // unit normal (when valid)
  vec3 a;      // first-hit albedo (an emitter's: 1)
  bool valid;  // a surface: the ray did not leave the scene
  bool light;  // some of its samples see a light itself (camera_aux.glsl): left raw
};
// A pixel some of whose samples see a light itself (an Emit+Absorb hit): the light is not
// albedo x irradiance, and at its rim it is mixed with what lies around it, so such pixels
// are neither filtered (the finish gives them the raw mean) nor taps of the others.
bool sees_light(vec4 aux1) { return aux1.w > 0.0; }
Guide guide(ivec2 p) {
  vec4 a1 = texelFetch(u_aux1, p, 0);
  vec3 n = a1.xyz;
  bool valid = dot(n, n) > 0.25;  // else the ray left the scene (or an edge of one)
  return Guide(depth(p), depth_gradient(p), valid ? normalize(n) : n, texelFetch(u_aux0, p, 0).rgb, valid, sees_light(a1));
}

// SVGF's geometric edge-stopping weight of tap q for pixel p (0 across a sky edge, and
// between a pixel that sees a light and one that does not), times
// an albedo term: exp(-(d / sigma_a)^2) with d the largest channel's difference relative to
// the pair's mean, so that a light's rim does not mix the emitter with the ceiling around
// it (they share a plane and a normal; the albedo of an emitter seen directly is 1).
float geometry_weight(Guide g, ivec2 p, ivec2 q) {
  vec4 a1q = texelFetch(u_aux1, q, 0);
  vec3 nq = a1q.xyz;
  bool valid_q = dot(nq, nq) > 0.25;
  if (valid_q != g.valid || sees_light(a1q) != g.light) return 0.0;
  float wn = g.valid ? pow(max(dot(g.n, normalize(nq)), 0.0), u_sigma_n) : 1.0;
  vec4 aq = texelFetch(u_aux0, q, 0);
  vec3 da = abs(g.a - aq.rgb) / (0.5 * (g.a + aq.rgb) + 0.02);
  float d = u_sigma_a > 0.0 ? max(da.r, max(da.g, da.b)) / u_sigma_a : 0.0;  // 0: off
  return wn * exp(-abs(g.z - aq.a) / (u_sigma_z * dot(g.grad, abs(vec2(q - p))) + 1.0e-3 * abs(g.z) + 1.0e-6) - d * d);
}

const float kB3[3] = float[3](0.375, 0.25, 0.0625);  // the B3 spline: 1/16 1/4 3/8 1/4 1/16

void main() {
  g_size = textureSize(u_radiance, 0);
  ivec2 p = ivec2(gl_FragCoord.xy);
#if PT_DENOISE_PASS == 0
  vec3 c = demodulated(p);
  float var = pixel_variance(p);
  if (u_samples < 4) {
    // The luminance's variance over the geometrically similar 5x5 neighbours, a sample
    // each: the pixels' own estimate has (n - 1) < 3 degrees of freedom.
    Guide g = guide(p);
    float sw = 0.0, m1 = 0.0, m2 = 0.0;
    for (int y = -2; y <= 2; ++y)
      for (int x = -2; x <= 2; ++x) {
        ivec2 q = p + ivec2(x, y);
        if (!inside(q)) continue;
        float w = geometry_weight(g, p, q);
        if (w == 0.0) continue;
        float l = dot(kLum, demodulated(q));
        sw += w, m1 += w * l, m2 += w * l * l;
      }
    m1 /= sw;
    var = max(m2 / sw - m1 * m1, 0.0) / float(max(u_samples, 1));  // of the mean of n
  }
  o_color = vec4(c, var);
#elif PT_DENOISE_PASS == 1
  vec4 cp = texelFetch(u_input, p, 0);
  float lp = dot(kLum, cp.rgb);
  // The variance for the luminance weight, blurred 3x3 (SVGF: a Gaussian prefilter).
  float gv = 0.0, gw = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) {
      ivec2 q = p + ivec2(x, y);
      if (!inside(q)) continue;
      float w = (x == 0 ? 0.5 : 0.25) * (y == 0 ? 0.5 : 0.25);
      gv += w * texelFetch(u_input, q, 0).a;
      gw += w;
    }
  float sd = sqrt(max(gv / gw, 0.0));
  Guide g = guide(p);
  float sw = kB3[0] * kB3[0];  // the centre tap, weight 1 in every edge-stopping function
  vec3 sdiff = vec3(0.0);
  float svar = sw * sw * cp.a;
  for (int y = -2; y <= 2; ++y)
    for (int x = -2; x <= 2; ++x) {
      if (x == 0 && y == 0) continue;
      ivec2 q = p + ivec2(x, y) * u_step;
      if (!inside(q)) continue;
      float wg = geometry_weight(g, p, q);
      if (wg == 0.0) continue;  // across an edge: the tap adds nothing
      vec4 cq = texelFetch(u_input, q, 0);
      float wl = exp(-abs(lp - dot(kLum, cq.rgb)) / (u_sigma_l * sd + 1.0e-10));
      float w = kB3[abs(x)] * kB3[abs(y)] * wg * wl;
      sw += w;
      sdiff += w * (cq.rgb - cp.rgb);
      svar += w * w * cq.a;
    }
  o_color = vec4(cp.rgb + sdiff / sw, svar / (sw * sw));
#elif PT_DENOISE_PASS == 3
  // Weighted local first-order regression (Moon et al. 2014; Bitterli et al. 2016): the
  // demodulated image u_noisy (a-trous iteration reg_input's output: 1, a 5x5 edge-aware
  // mean that takes the edge off single-pixel outliers; 0 the unfiltered one) in a
  // (2R+1)^2 window, taps STRIDE apart, fitted as linear in the screen offset,
  // y_q ~ b + c . (q - p) / ((R + 1) STRIDE), by weighted least squares; the pixel gets the
  // intercept b. Weights: an Epanechnikov taper, the geometric edge-stopping weight
  // (depth, normal, albedo) and a range weight on the last a-trous output (u_input, the
  // guide: smooth, so it tells which taps lie on the same lighting):
  // exp(-dl^2 / (rel^2 (l_p^2 + l_q^2) + sd^2 (v_p + v_q))), dl the guides' luminance
  // difference, v their variances. A linear gradient is fitted without bias, also where
  // the window is one-sided (at edges, borders), which a weighted mean is not. The slopes
  // get a ridge (u_reg_ridge x the sum of weights), so a window whose taps lie on a line,
  // or one tap, falls back to the weighted mean. The fit is of the differences y_q - y_p:
  // a constant image comes back bit for bit.
  vec3 yp = texelFetch(u_noisy, p, 0).rgb;
  vec4 gp = texelFetch(u_input, p, 0);
  float lp = dot(kLum, gp.rgb);
  Guide g = guide(p);
  float m00 = 0.0, m01 = 0.0, m02 = 0.0, m11 = 0.0, m12 = 0.0, m22 = 0.0;
  vec3 b0 = vec3(0.0), b1 = vec3(0.0), b2 = vec3(0.0);
  const float kInvR = 1.0 / float(PT_REG_RADIUS + 1);
  for (int y = -PT_REG_RADIUS; y <= PT_REG_RADIUS; ++y)
    for (int x = -PT_REG_RADIUS; x <= PT_REG_RADIUS; ++x) {
      ivec2 q = p + ivec2(x, y) * PT_REG_STRIDE;
      if (!inside(q)) continue;
      vec2 o = vec2(x, y) * kInvR;
      float w = max(1.0 - dot(o, o), 0.0);  // Epanechnikov
      if (x != 0 || y != 0) {
        w *= geometry_weight(g, p, q);
        if (w == 0.0) continue;
        vec4 gq = texelFetch(u_input, q, 0);
        float lq = dot(kLum, gq.rgb), dl = lq - lp;
        w *= exp(-dl * dl / (u_reg_rel * u_reg_rel * (lp * lp + lq * lq) + u_reg_sd * u_reg_sd * (gp.a + gq.a) + 1.0e-20));
      }
      vec3 d = texelFetch(u_noisy, q, 0).rgb - yp;
      m00 += w, m01 += w * o.x, m02 += w * o.y, m11 += w * o.x * o.x, m12 += w * o.x * o.y, m22 += w * o.y * o.y;
      b0 += w * d, b1 += w * o.x * d, b2 += w * o.y * d;
    }
  m11 += u_reg_ridge * m00;
  m22 += u_reg_ridge * m00;
  // The intercept: the first row of the inverse (cofactors over the determinant) times b.
  float c00 = m11 * m22 - m12 * m12, c01 = m02 * m12 - m01 * m22, c02 = m01 * m12 - m02 * m11;
  float det = m00 * c00 + m01 * c01 + m02 * c02;
  o_color = vec4(yp + (c00 * b0 + c01 * b1 + c02 * b2) / det, gp.a);
#elif PT_DENOISE_PASS == 4
  // p is a block here, not a pixel.
  float sum = 0.0;
  ivec2 lo = p * u_block, hi = min(lo + u_block, g_size);
  for (int y = lo.y; y < hi.y; ++y)
    for (int x = lo.x; x < hi.x; ++x) {
      ivec2 q = ivec2(x, y);
      vec3 raw = texelFetch(u_radiance, q, 0).rgb;
      vec3 change = sees_light(texelFetch(u_aux1, q, 0)) ? vec3(0.0) : safe_albedo(q) * (texelFetch(u_input, q, 0).rgb - demodulated(q));
      sum += dot(change * change / (raw * raw + 0.01), vec3(1.0));
    }
  o_color = vec4(sum, 0.0, 0.0, 0.0);
#else
  vec3 raw = texelFetch(u_radiance, p, 0).rgb;
  vec3 filtered = texelFetch(u_input, p, 0).rgb;
  if (sees_light(texelFetch(u_aux1, p, 0))) filtered = demodulated(p);  // a light's pixels stay raw
  o_color = vec4(raw + u_weight * safe_albedo(p) * (filtered - demodulated(p)), 1.0);
#endif
}
