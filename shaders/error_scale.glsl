// error_scale.glsl: core/metrics.h's error_scale for the fireflies, packed as the guide
// (error_guide.glsl): one texel per 2x2 pixels, o_r, o_g, o_b the four pixels' red, green
// and blue. Drawn only where the guide pass left depth 0 (a firefly in the texel); the
// other texels are never read. Per firefly and channel the smaller of its mean m and the
// mean of the other pixels within FIREFLY_RADIUS whose guides are within the tolerance of
// its own (none: m); the constants are render/tile_sums.cpp's, from core/metrics.h.
uniform highp sampler2D u_radiance;  // the mean RGB
uniform highp sampler2D u_guide;     // error_guide.glsl's
uniform ivec2 u_size;
layout(location = 0) out vec4 o_r;
layout(location = 1) out vec4 o_g;
layout(location = 2) out vec4 o_b;

#include "firefly_mark.glsl"

// Pixel p's scale; `firefly` from its guide, g its median.
vec3 scale_of(ivec2 p, bool firefly, float g) {
  vec3 m = texelFetch(u_radiance, min(p, u_size - 1), 0).rgb;
  if (!firefly || any(greaterThanEqual(p, u_size))) return m;
  const int R = FIREFLY_RADIUS;
  float tol = GUIDE_TOLERANCE * (g + GUIDE_FLOOR);
  ivec2 lo = max(p - R, ivec2(0)), hi = min(p + R, u_size - 1);
  vec3 sum = vec3(0.0);
  float n = 0.0;
  // A texel of the guide at a time: four pixels' medians.
  for (int ty = lo.y >> 1; ty <= hi.y >> 1; ++ty)
    for (int tx = lo.x >> 1; tx <= hi.x >> 1; ++tx) {
      vec4 t = guide_medians(texelFetch(u_guide, ivec2(tx, ty), 0));
      for (int k = 0; k < 4; ++k) {
        ivec2 q = ivec2(tx, ty) * 2 + ivec2(k & 1, k >> 1);
        if (any(lessThan(q, lo)) || any(greaterThan(q, hi)) || q == p || !(abs(t[k] - g) <= tol)) continue;
        sum += texelFetch(u_radiance, q, 0).rgb;
        n += 1.0;
      }
    }
  return n > 0.0 ? min(m, sum / n) : m;
}

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec4 guide = texelFetch(u_guide, t, 0);
  bvec4 fly = fireflies(guide);
  vec4 g = guide_medians(guide);
  vec3 s0 = scale_of(t * 2, fly.x, g.x), s1 = scale_of(t * 2 + ivec2(1, 0), fly.y, g.y);
  vec3 s2 = scale_of(t * 2 + ivec2(0, 1), fly.z, g.z), s3 = scale_of(t * 2 + ivec2(1, 1), fly.w, g.w);
  o_r = vec4(s0.r, s1.r, s2.r, s3.r);
  o_g = vec4(s0.g, s1.g, s2.g, s3.g);
  o_b = vec4(s0.b, s1.b, s2.b, s3.b);
}
