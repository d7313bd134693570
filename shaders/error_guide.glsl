// error_guide.glsl: the guide of the error estimate's firefly test (core/metrics.h,
// error_guide), packed: one texel per 2x2 pixels, component (y & 1) * 2 + (x & 1) the
// pixel's. Per pixel the median of its 3x3 neighbourhood's luminance (coordinates clamped
// to the image), its sign bit set where the pixel is a firefly: brighter than
// FIREFLY_RATIO times that median and at least FIREFLY_NEIGHBOUR times the brightest of
// its neighbours inside the image (error_scale.glsl and tile_sums.glsl read both).
//
// A 4x4 neighbourhood holds the four 3x3 ones: 16 fetches per four pixels, not 36, and a
// quarter of the fragments (at 1920x1080 on llvmpipe the unpacked pass took 55-60 ms).
uniform highp sampler2D u_radiance;  // the mean RGB
uniform ivec2 u_size;
layout(location = 0) out vec4 o_guide;

#include "firefly_mark.glsl"

float lum_at(ivec2 p) { return dot(texelFetch(u_radiance, clamp(p, ivec2(0), u_size - 1), 0).rgb, vec3(0.2126, 0.7152, 0.0722)); }

// Sorts a pair: a the smaller.
#define SORT2(a, b) { float t_ = min(a, b); b = max(a, b); a = t_; }

// Pixel c of the 4x4 block L (columns i, rows j: L[j * 4 + i]), c = (1, 1) + its offset.
float guide_of(float L[16], ivec2 c, ivec2 p) {
  float l0 = L[(c.y - 1) * 4 + c.x - 1], l1 = L[(c.y - 1) * 4 + c.x], l2 = L[(c.y - 1) * 4 + c.x + 1];
  float l3 = L[c.y * 4 + c.x - 1], l4 = L[c.y * 4 + c.x], l5 = L[c.y * 4 + c.x + 1];
  float l6 = L[(c.y + 1) * 4 + c.x - 1], l7 = L[(c.y + 1) * 4 + c.x], l8 = L[(c.y + 1) * 4 + c.x + 1];
  float l = l4;
  // The neighbours inside the image (a clamped coordinate repeats the pixel or an edge row).
  bvec4 in_ = bvec4(p.x > 0, p.x < u_size.x - 1, p.y > 0, p.y < u_size.y - 1);
  float most = -1.0;
  if (in_.y) most = max(most, l5);
  if (in_.x) most = max(most, l3);
  if (in_.z) most = max(most, l1);
  if (in_.w) most = max(most, l7);
  if (in_.x && in_.z) most = max(most, l0);
  if (in_.y && in_.z) most = max(most, l2);
  if (in_.x && in_.w) most = max(most, l6);
  if (in_.y && in_.w) most = max(most, l8);
  // The median of nine by a network of 19 exchanges (Paeth, Graphics Gems 1990): in l4.
  SORT2(l1, l2) SORT2(l4, l5) SORT2(l7, l8) SORT2(l0, l1) SORT2(l3, l4) SORT2(l6, l7)
  SORT2(l1, l2) SORT2(l4, l5) SORT2(l7, l8) SORT2(l0, l3) SORT2(l5, l8) SORT2(l4, l7)
  SORT2(l3, l6) SORT2(l1, l4) SORT2(l2, l5) SORT2(l4, l7) SORT2(l4, l2) SORT2(l6, l4)
  SORT2(l4, l2)
  bool firefly = l > FIREFLY_RATIO * l4 && l >= FIREFLY_NEIGHBOUR * most;
  return firefly ? mark_firefly(l4) : l4;
}

void main() {
  ivec2 base = ivec2(gl_FragCoord.xy) * 2;  // the texel's lower left pixel
  float L[16];
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) L[j * 4 + i] = lum_at(base + ivec2(i - 1, j - 1));
  o_guide = vec4(guide_of(L, ivec2(1, 1), base), guide_of(L, ivec2(2, 1), base + ivec2(1, 0)),
                 guide_of(L, ivec2(1, 2), base + ivec2(0, 1)), guide_of(L, ivec2(2, 2), base + ivec2(1, 1)));
  // Depth 0 where the texel holds a firefly: error_scale.glsl runs there only (early depth
  // test), 1 elsewhere.
  gl_FragDepth = any(fireflies(o_guide)) ? 0.0 : 1.0;
}
