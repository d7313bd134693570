// tile_sums.glsl: the error estimate's sums, reduced on the GPU (render/tile_sums.h;
// core/metrics.h says what they estimate). One fragment per block of u_block x u_block
// pixels; per pixel and channel, with den = d^2 + 0.01 (d: the mean m, or for a firefly the
// mean of its surface around it: error_scale below, core/metrics.h):
//   var     += max(s, 0) / den         (s the samples' variance about their mean m)
//   diff[j] += (m - m_j)^2 / den       (m_j snapshot j's mean)
// summed in a row's own partial sums first (a float sum of at most u_block terms), then
// over the rows. A snapshot slot with none bound is given the mean itself (its sum: 0).
uniform highp sampler2D u_radiance;  // accumulator: mean RGB, A the blue channel's variance
uniform highp sampler2D u_stats;     // accumulator: z, w the red and green channels' variance
uniform highp sampler2D u_snap0;
uniform highp sampler2D u_snap1;
uniform highp sampler2D u_snap2;
uniform highp sampler2D u_snap3;
uniform highp sampler2D u_guide;     // error_guide.glsl's: x the 3x3 median, y the neighbours' largest luminance
uniform int u_block;
uniform ivec2 u_size;  // the image's pixels
layout(location = 0) out vec4 o_sums0;  // var, diff[0], diff[1], diff[2]
layout(location = 1) out vec4 o_sums1;  // diff[3], pixels, 0, 0

// core/metrics.h's error_scale (its constants defined by render/tile_sums.cpp): m, or for a firefly per channel the smaller of m and the
// mean of the other pixels within kFireflyRadius whose guides are within the tolerance of
// its own (none: m).
vec3 error_scale(ivec2 p, vec3 m) {
  vec2 g = texelFetch(u_guide, p, 0).xy;
  float l = dot(m, vec3(0.2126, 0.7152, 0.0722));
  if (!(l > FIREFLY_RATIO * g.x && l >= FIREFLY_NEIGHBOUR * g.y)) return m;
  const int R = FIREFLY_RADIUS;
  float tol = GUIDE_TOLERANCE * (g.x + GUIDE_FLOOR);
  vec3 sum = vec3(0.0);
  float n = 0.0;
  for (int j = max(p.y - R, 0); j <= min(p.y + R, u_size.y - 1); ++j)
    for (int i = max(p.x - R, 0); i <= min(p.x + R, u_size.x - 1); ++i) {
      ivec2 q = ivec2(i, j);
      if (q == p || !(abs(texelFetch(u_guide, q, 0).x - g.x) <= tol)) continue;
      sum += texelFetch(u_radiance, q, 0).rgb;
      n += 1.0;
    }
  return n > 0.0 ? min(m, sum / n) : m;
}

void main() {
  ivec2 lo = ivec2(gl_FragCoord.xy) * u_block;
  ivec2 hi = min(lo + u_block, u_size);
  vec4 s0 = vec4(0.0);
  float s1 = 0.0;
  for (int y = lo.y; y < hi.y; ++y) {
    vec4 r0 = vec4(0.0);
    float r1 = 0.0;
    for (int x = lo.x; x < hi.x; ++x) {
      ivec2 p = ivec2(x, y);
      vec4 a = texelFetch(u_radiance, p, 0);
      vec4 st = texelFetch(u_stats, p, 0);
      vec3 m = a.rgb;
      vec3 d = error_scale(p, m);
      vec3 inv = 1.0 / (d * d + 0.01);
      r0.x += dot(max(vec3(st.z, st.w, a.w), 0.0), inv);
      d = m - texelFetch(u_snap0, p, 0).rgb;
      r0.y += dot(d * d, inv);
      d = m - texelFetch(u_snap1, p, 0).rgb;
      r0.z += dot(d * d, inv);
      d = m - texelFetch(u_snap2, p, 0).rgb;
      r0.w += dot(d * d, inv);
      d = m - texelFetch(u_snap3, p, 0).rgb;
      r1 += dot(d * d, inv);
    }
    s0 += r0;
    s1 += r1;
  }
  vec2 span = vec2(max(hi - lo, ivec2(0)));
  o_sums0 = s0;
  o_sums1 = vec4(s1, span.x * span.y, 0.0, 0.0);
}
