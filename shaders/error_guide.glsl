// error_guide.glsl: the guide of the error estimate's firefly test (core/metrics.h,
// error_guide): per pixel, x the median of the 3x3 neighbourhood's luminance (coordinates
// clamped to the image), y the largest luminance of the neighbours inside it (-1: none).
uniform highp sampler2D u_radiance;  // the mean RGB
uniform ivec2 u_size;
layout(location = 0) out vec4 o_guide;

float lum_at(ivec2 p) { return dot(texelFetch(u_radiance, clamp(p, ivec2(0), u_size - 1), 0).rgb, vec3(0.2126, 0.7152, 0.0722)); }

// Sorts a pair: a the smaller.
#define SORT2(a, b) { float t_ = min(a, b); b = max(a, b); a = t_; }

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float l0 = lum_at(p + ivec2(-1, -1)), l1 = lum_at(p + ivec2(0, -1)), l2 = lum_at(p + ivec2(1, -1));
  float l3 = lum_at(p + ivec2(-1, 0)), l4 = lum_at(p), l5 = lum_at(p + ivec2(1, 0));
  float l6 = lum_at(p + ivec2(-1, 1)), l7 = lum_at(p + ivec2(0, 1)), l8 = lum_at(p + ivec2(1, 1));
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
  o_guide = vec4(l4, most, 0.0, 0.0);
}
