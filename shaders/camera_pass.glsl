// camera_pass.glsl: what every render mode's program shares: the pass's uniforms, the
// camera rays (pixel box filter, thin lens, shutter time), the NaN/Inf guard and the
// blend into the running mean and the samples' variance (ping-pong), and with PT_AUX the
// first-hit auxiliaries of the denoiser (render/denoise.h). Each mode's root file (integrator.glsl,
// whitted.glsl, sh_irradiance.glsl; shadergen picks it) includes this first and then
// defines trace_path: the radiance arriving along a camera ray.
uniform highp sampler2D u_accum;
uniform highp sampler2D u_stats_in;
#ifdef PT_AUX
uniform highp sampler2D u_aux0_in;
uniform highp sampler2D u_aux1_in;
#endif
uniform float u_blend;       // weight of this pass: spp / (samples so far + spp)
uniform int u_spp;           // samples per pixel in this pass
uniform int u_sample_base;   // index of this pass's first sample
#ifdef PT_ADAPTIVE
// Adaptive sampling (render/adaptive.h): per tile of u_count_tile pixels, (samples so far,
// samples this pass), in place of u_sample_base and u_spp; the blend is each tile's own.
uniform highp sampler2D u_tile_counts;
uniform int u_count_tile;
#endif
uniform int u_max_bounces;   // scattering events per path
uniform int u_nee;           // 1: next-event estimation + MIS; 0: BSDF sampling only
uniform vec3 u_cam_pos;
uniform vec3 u_cam_right;    // scaled by tan(fov/2) * aspect
uniform vec3 u_cam_up;       // scaled by tan(fov/2)
uniform vec3 u_cam_fwd;
uniform vec2 u_size;
uniform float u_lens_radius;     // thin lens: 0 = pinhole
uniform float u_focal_distance;  // along u_cam_fwd
uniform float u_shutter;         // camera samples are spread over [0, u_shutter]
uniform vec3 u_env_color;

// Outputs, two targets: accum = (the running mean RGB, the blue channel's variance);
// stats = (non-finite samples, dropped; rays cast; the red and green channels' variance),
// x and y running sums, the variance per channel that of the pixel's samples about their
// mean (sum of squared deviations / samples). The variance once had a third target of its
// own; these free channels hold it at no extra bandwidth (docs/benchmarks.md). The fragment
// pass writes colour targets; the compute kernel (PT_COMPUTE: native GL ES 3.1+) the same
// textures as images, over 8x8-pixel groups covering the tile [u_origin, u_end) (columns
// x, rows y). With PT_AUX, two more: aux0 = (albedo RGB, view depth), aux1 = (shading
// normal, the part that sees a light itself), running means over the samples like the radiance (camera_aux.glsl).
#ifdef PT_COMPUTE
layout(rgba32f, binding = 0) writeonly uniform highp image2D o_accum_image;
layout(rgba32f, binding = 1) writeonly uniform highp image2D o_stats_image;
#ifdef PT_AUX
layout(rgba32f, binding = 2) writeonly uniform highp image2D o_aux0_image;
layout(rgba32f, binding = 3) writeonly uniform highp image2D o_aux1_image;
#endif
uniform ivec2 u_origin;
uniform ivec2 u_end;
#ifdef PT_ADAPTIVE
uniform int u_ordered;  // 1: a whole sweep tile by tile, the most samples first (render/adaptive.h)
#endif
#else
layout(location = 0) out vec4 o_accum;
layout(location = 1) out vec4 o_stats;
#ifdef PT_AUX
layout(location = 2) out vec4 o_aux0;
layout(location = 3) out vec4 o_aux1;
#endif
#endif

// A sample is bad when any channel's exponent bits are all ones (NaN or Inf): a bit
// test, because a driver may assume finite math and fold isnan/isinf away.
bool non_finite(vec3 c) {
  uvec3 e = floatBitsToUint(c) & 0x7f800000u;
  return any(equal(e, uvec3(0x7f800000u)));
}

#include "surface.glsl"
#include "camera_aux.glsl"

vec3 trace_path(Ray r);

#ifdef PT_AUX
vec4 g_aux0, g_aux1;  // this pass's mean of the auxiliaries, blended into the running one below
#endif

void render_pixel(ivec2 px, out vec4 accum, out vec4 stats) {
#ifdef PT_ADAPTIVE
  ivec2 counts = ivec2(texelFetch(u_tile_counts, px / u_count_tile, 0).xy);
  int base = counts.x, spp = counts.y;
  float blend = float(spp) / float(base + spp);
  if (spp == 0) {  // no samples for this tile in this pass: the pixel as it was
    accum = texelFetch(u_accum, px, 0);
    stats = texelFetch(u_stats_in, px, 0);
#ifdef PT_AUX
    g_aux0 = texelFetch(u_aux0_in, px, 0);
    g_aux1 = texelFetch(u_aux1_in, px, 0);
#endif
    return;
  }
#else
  int base = u_sample_base, spp = u_spp;
  float blend = u_blend;
#endif
  vec3 sum = vec3(0.0);
#ifdef PT_AUX
  vec4 aux0 = vec4(0.0), aux1 = vec4(0.0);
#endif
  vec3 w_mean = vec3(0.0), w_m2 = vec3(0.0);  // Welford: this pass's mean and squared deviations
  float bad = 0.0;
  g_rays = 0;
#ifdef PT_COUNT_OPS
  g_box_tests = g_prim_tests = 0;
#endif
  for (int s = 0; s < spp; ++s) {
    sampler_init(uvec2(px), uint(base + s));
    vec4 u_cam = next4();  // xy: position in the pixel (box filter); zw: lens
    g_time = u_shutter * rand01();
    vec2 ndc = (vec2(px) + u_cam.xy) / u_size * 2.0 - 1.0;
    vec3 d = normalize(u_cam_fwd + ndc.x * u_cam_right + ndc.y * u_cam_up);
    vec3 o = u_cam_pos;
    if (u_lens_radius > 0.0) {
      // Thin lens: every ray through the lens point meets the pinhole ray on the plane in
      // focus, perpendicular to the view direction.
      vec3 focus = o + d * (u_focal_distance / dot(d, u_cam_fwd));
      float r = u_lens_radius * sqrt(u_cam.z);
      float phi = TWO_PI * u_cam.w;
      o += r * (cos(phi) * normalize(u_cam_right) + sin(phi) * normalize(u_cam_up));
      d = normalize(focus - o);
    }
#ifdef PT_AUX
    aux_start();
#endif
    vec3 c = trace_path(Ray(o, d));
#ifdef PT_AUX
    aux0 += vec4(g_aux_albedo, g_aux_length * dot(d, u_cam_fwd));
    aux1 += vec4(g_aux_normal, g_aux_seen);
#endif
    if (non_finite(c)) {
      bad += 1.0;
      c = vec3(0.0);
    }
    sum += c;
    vec3 dev = c - w_mean;
    w_mean += dev / float(s + 1);
    w_m2 += dev * (c - w_mean);
  }
  vec3 cur = sum / float(spp);
  vec4 prev = blend >= 1.0 ? vec4(0.0) : texelFetch(u_accum, px, 0);
  vec4 prev_stats = blend >= 1.0 ? vec4(0.0) : texelFetch(u_stats_in, px, 0);
  // The variance about the mean of all samples so far, from the old one and this pass's
  // (Chan, Golub and LeVeque's pairwise update, on variances: b = this pass's share):
  // S = (1 - b) S_old + b S_pass + b (1 - b) (mean_pass - mean_old)^2.
  vec3 s_pass = w_m2 / float(spp);
  vec3 dm = cur - prev.rgb;
  vec3 s_old = vec3(prev_stats.zw, prev.a);
  vec3 var = mix(s_old, s_pass, blend) + blend * (1.0 - blend) * dm * dm;
  accum = vec4(blend >= 1.0 ? cur : mix(prev.rgb, cur, blend), var.b);
  stats = vec4(prev_stats.xy + vec2(bad, float(g_rays)), var.rg);
#ifdef PT_COUNT_OPS
  stats.zw = prev_stats.zw + vec2(float(g_box_tests), float(g_prim_tests));  // not the variance
#endif
#ifdef PT_AUX
  aux0 /= float(spp);
  aux1 /= float(spp);
  g_aux0 = blend >= 1.0 ? aux0 : mix(texelFetch(u_aux0_in, px, 0), aux0, blend);
  g_aux1 = blend >= 1.0 ? aux1 : mix(texelFetch(u_aux1_in, px, 0), aux1, blend);
#endif
}

void main() {
#ifdef PT_COMPUTE
  ivec2 px = u_origin + ivec2(gl_GlobalInvocationID.xy);
#ifdef PT_ADAPTIVE
  if (u_ordered != 0) {  // tile by tile in the order of the counts' z, w (Accumulator::ordered_dispatch)
    int per_side = u_count_tile / 8;
    int linear = int(gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x);
    int i = linear / (per_side * per_side), sub = linear - i * per_side * per_side;
    int w = textureSize(u_tile_counts, 0).x;
    ivec2 tile = ivec2(texelFetch(u_tile_counts, ivec2(i % w, i / w), 0).zw);
    px = tile * u_count_tile + 8 * ivec2(sub % per_side, sub / per_side) + ivec2(gl_LocalInvocationID.xy);
  }
#endif
  if (any(greaterThanEqual(px, u_end))) return;
  vec4 accum, stats;
  render_pixel(px, accum, stats);
  imageStore(o_accum_image, px, accum);
  imageStore(o_stats_image, px, stats);
#ifdef PT_AUX
  imageStore(o_aux0_image, px, g_aux0);
  imageStore(o_aux1_image, px, g_aux1);
#endif
#else
  render_pixel(ivec2(gl_FragCoord.xy), o_accum, o_stats);
#ifdef PT_AUX
  o_aux0 = g_aux0;
  o_aux1 = g_aux1;
#endif
#endif
}
