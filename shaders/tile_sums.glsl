// tile_sums.glsl: the error estimate's sums, reduced on the GPU (render/tile_sums.h;
// core/metrics.h says what they estimate). One fragment per block of u_block x u_block
// pixels; per pixel and channel, with den = d^2 + 0.01 (d: the mean m, or for a firefly the
// mean of its surface around it: error_scale.glsl's, core/metrics.h):
//   var     += max(s, 0) / den         (s the samples' variance about their mean m)
//   diff[j] += (m - m_j)^2 / den       (m_j snapshot j's mean)
// summed in two rows' own partial sums first (a float sum of at most 2 u_block terms),
// then over the rows. A snapshot slot with none bound is given the mean itself (its sum: 0).
uniform highp sampler2D u_radiance;  // accumulator: mean RGB, A the blue channel's variance
uniform highp sampler2D u_stats;     // accumulator: z, w the red and green channels' variance
uniform highp sampler2D u_snap0;
uniform highp sampler2D u_snap1;
uniform highp sampler2D u_snap2;
uniform highp sampler2D u_snap3;
uniform highp sampler2D u_guide;     // error_guide.glsl's, packed 2x2: the 3x3 medians, fireflies' sign bits set
uniform highp sampler2D u_scale_r;   // error_scale.glsl's, packed as the guide (only fireflies' are read)
uniform highp sampler2D u_scale_g;
uniform highp sampler2D u_scale_b;
uniform int u_block;
uniform ivec2 u_size;  // the image's pixels
layout(location = 0) out vec4 o_sums0;  // var, diff[0], diff[1], diff[2]
layout(location = 1) out vec4 o_sums1;  // diff[3], pixels, 0, 0

#include "firefly_mark.glsl"

// Pixel p's terms; its error scale (core/metrics.h's error_scale) the mean m, or for a
// firefly `scale`.
void add_pixel(ivec2 p, bool firefly, vec3 scale, inout vec4 r0, inout float r1) {
  vec4 a = texelFetch(u_radiance, p, 0);
  vec4 st = texelFetch(u_stats, p, 0);
  vec3 m = a.rgb;
  vec3 d = firefly ? scale : m;
  vec3 inv = 1.0 / (d * d + 0.01);
  r0.x += dot(max(vec3(st.z, st.w, a.w), 0.0), inv);
  vec3 e = m - texelFetch(u_snap0, p, 0).rgb;
  r0.y += dot(e * e, inv);
  e = m - texelFetch(u_snap1, p, 0).rgb;
  r0.z += dot(e * e, inv);
  e = m - texelFetch(u_snap2, p, 0).rgb;
  r0.w += dot(e * e, inv);
  e = m - texelFetch(u_snap3, p, 0).rgb;
  r1 += dot(e * e, inv);
}

void main() {
  ivec2 lo = ivec2(gl_FragCoord.xy) * u_block;
  ivec2 hi = min(lo + u_block, u_size);
  vec4 s0 = vec4(0.0);
  float s1 = 0.0;
  // Two rows of the block at a time (their own partial sums, then over the rows); along
  // them, the guide's and the scales' texels, 2x2 pixels each.
  for (int y = lo.y & ~1; y < hi.y; y += 2) {
    vec4 r0 = vec4(0.0);
    float r1 = 0.0;
    for (int x = lo.x & ~1; x < hi.x; x += 2) {
      ivec2 t = ivec2(x, y) >> 1;
      bvec4 fly = fireflies(texelFetch(u_guide, t, 0));
      vec4 r = vec4(0.0), gg = vec4(0.0), b = vec4(0.0);
      if (any(fly)) r = texelFetch(u_scale_r, t, 0), gg = texelFetch(u_scale_g, t, 0), b = texelFetch(u_scale_b, t, 0);
      bvec4 in_ = bvec4(x >= lo.x && y >= lo.y, x + 1 < hi.x && y >= lo.y, x >= lo.x && y + 1 < hi.y, x + 1 < hi.x && y + 1 < hi.y);
      if (in_.x) add_pixel(ivec2(x, y), fly.x, vec3(r.x, gg.x, b.x), r0, r1);
      if (in_.y) add_pixel(ivec2(x + 1, y), fly.y, vec3(r.y, gg.y, b.y), r0, r1);
      if (in_.z) add_pixel(ivec2(x, y + 1), fly.z, vec3(r.z, gg.z, b.z), r0, r1);
      if (in_.w) add_pixel(ivec2(x + 1, y + 1), fly.w, vec3(r.w, gg.w, b.w), r0, r1);
    }
    s0 += r0;
    s1 += r1;
  }
  vec2 span = vec2(max(hi - lo, ivec2(0)));
  o_sums0 = s0;
  o_sums1 = vec4(s1, span.x * span.y, 0.0, 0.0);
}
