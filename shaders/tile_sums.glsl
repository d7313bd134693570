// tile_sums.glsl: the error estimate's sums, reduced on the GPU (render/tile_sums.h;
// core/metrics.h says what they estimate). One fragment per block of u_block x u_block
// pixels; per pixel and channel, with den = m^2 + 0.01:
//   var     += max(s, 0) / den         (s the samples' variance about their mean m)
//   diff[j] += (m - m_j)^2 / den       (m_j snapshot j's mean)
// summed in a row's own partial sums first (a float sum of at most u_block terms), then
// over the rows. Unbound snapshots (u_snapshots below 4) read the mean itself: 0.
uniform highp sampler2D u_radiance;  // accumulator: mean RGB, A the blue channel's variance
uniform highp sampler2D u_stats;     // accumulator: z, w the red and green channels' variance
uniform highp sampler2D u_snap0;
uniform highp sampler2D u_snap1;
uniform highp sampler2D u_snap2;
uniform highp sampler2D u_snap3;
uniform int u_block;
uniform ivec2 u_size;  // the image's pixels
layout(location = 0) out vec4 o_sums0;  // var, diff[0], diff[1], diff[2]
layout(location = 1) out vec4 o_sums1;  // diff[3], pixels, 0, 0

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
      vec3 inv = 1.0 / (m * m + 0.01);
      r0.x += dot(max(vec3(st.z, st.w, a.w), 0.0), inv);
      vec3 d = m - texelFetch(u_snap0, p, 0).rgb;
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
