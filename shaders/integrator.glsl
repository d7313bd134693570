// integrator.glsl: the progressive path tracer's fragment program. Each fragment traces
// u_spp camera paths through its pixel and blends their mean into the running mean of
// the previous pass (ping-pong). Unbiased: next-event estimation to emissive shapes,
// combined with BSDF sampling by the power heuristic; Russian roulette after 3 bounces.
uniform highp sampler2D u_accum;
uniform highp sampler2D u_stats_in;
uniform float u_blend;       // weight of this pass: spp / (samples so far + spp)
uniform int u_spp;           // samples per pixel in this pass
uniform int u_sample_base;   // index of this pass's first sample
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

layout(location = 0) out vec4 o_accum;
// Running sums per pixel: x = non-finite samples (dropped), y = rays cast.
layout(location = 1) out vec4 o_stats;

// A sample is bad when any channel's exponent bits are all ones (NaN or Inf): a bit
// test, because a driver may assume finite math and fold isnan/isinf away.
bool non_finite(vec3 c) {
  uvec3 e = floatBitsToUint(c) & 0x7f800000u;
  return any(equal(e, uvec3(0x7f800000u)));
}

vec3 trace_path(Ray r) {
  vec3 L = vec3(0.0);
  vec3 beta = vec3(1.0);
  float prev_pdf = 0.0;
  bool prev_delta = true;
  vec3 prev_p = r.o;
  for (int bounce = 0;; ++bounce) {
    Hit h = scene_intersect(r);
    if (h.id < 0) {
#ifdef HAS_ENV_MAP
      float w = 1.0;
      if (u_nee != 0 && !prev_delta) w = power_heuristic(prev_pdf, env_light_pdf(r.d));
      L += beta * env_radiance(r.d) * w;
#else
      L += beta * u_env_color;
#endif
      break;
    }
    ShapeRec s = load_shape(h.id);
    MaterialRec m = load_material(s.material);
    vec3 p = h.p;
    bool entering = dot(r.d, h.n) < 0.0;
    // Emission from the front side; weighted against light sampling when this shape is a
    // light and the direction was not a delta-lobe choice.
    if (entering && max3(m.emission) > 0.0) {
      float w = 1.0;
      if (u_nee != 0 && !prev_delta && s.light >= 0) w = power_heuristic(prev_pdf, light_pdf(s, prev_p, r.d, h.t, h.n));
      L += beta * m.emission * w;
    }
#ifdef HAS_MAT_EMIT
    if (m.kind == MAT_EMIT) break;  // Emit+Absorb ends the path
#endif
    if (bounce >= u_max_bounces) break;
    vec3 n = entering ? h.n : -h.n;  // faces the side the ray came from
    Frame fr = frame_from(n);
    vec3 wo = to_local(fr, -r.d);
    vec4 u_light = next4();  // xyz: light choice and point; w: Russian roulette
    vec4 u_bsdf = next4();   // xyz: BSDF sample; w: choice of a composite's child
#ifdef HAS_MAT_FRESNEL_COMPOSITE
    m = resolve_fresnel_composite(m, wo.z, entering, u_bsdf.w);
#endif
#ifdef HAS_TEXTURES
    m = resolve_texture(m, p);
#endif
    // A shading normal (a mesh's interpolated vertex normals, a normal map) sets the BSDF's
    // frame; the geometric normal n still decides sides: a direction on different sides
    // of the two carries nothing, and rays leave off the geometric surface.
    bool shading_normal = false;
#ifdef HAS_SHAPE_MESH
    g_prim = h.prim;
    if (s.kind == SHAPE_MESH) {
      vec3 ns;
      vec2 uv_unused;
      if (mesh_attributes(h, ns, uv_unused) && dot(ns, ns) > 0.0) {
        ns = dot(ns, n) < 0.0 ? -ns : ns;  // onto the side the ray came from, as n
        if (dot(ns, -r.d) > 0.0) {  // a normal facing away from the viewer is not used
          fr = frame_from(ns);
          wo = to_local(fr, -r.d);
          shading_normal = true;
        }
      }
    }
#endif
#ifdef HAS_MAT_TEXTURED
    // Image maps: the record's values at the hit, and the shading frame of its normal map
    // (whose side tests below use the geometric normal: see textured_resolve.glsl).
    if (m.kind == MAT_TEXTURED) {
      shading_normal = true;
      m = resolve_textured(m, s, h.id, p, h.n, n, -r.d, fr);
      wo = to_local(fr, -r.d);
    }
#endif
    if (u_nee != 0 && have_lights() && !material_is_delta(m)) {
      LightSample ls;
      if (light_sample(p, u_light.xyz, ls)) {
        float pdf_b;
        vec3 wl = to_local(fr, ls.wi);
        vec3 f = material_eval(m, wo, wl, entering, pdf_b);
        if (shading_normal && (dot(ls.wi, n) > 0.0) != (wl.z > 0.0)) f = vec3(0.0);
        if (max3(f) > 0.0) {
          // Any hit short of the light's surface blocks it; the light itself is skipped, so
          // its own surface never shadows (the distance keeps a relative margin of 1e-4).
          if (!occluded(Ray(offset_origin(p, n, ls.wi), ls.wi), ls.dist * 0.9999, ls.shape))
            L += beta * f * ls.radiance * (power_heuristic(ls.pdf, pdf_b) / ls.pdf);
        }
      }
    }
    BsdfSample bs;
    if (!material_sample(m, wo, entering, u_bsdf.xyz, bs)) break;
    beta *= bs.weight;
    prev_pdf = bs.pdf;
    prev_delta = bs.delta;
    prev_p = p;
    vec3 wi = normalize(from_local(fr, bs.wi));
    if (shading_normal && (dot(wi, n) > 0.0) != (bs.wi.z > 0.0)) break;  // would cross the geometric surface
    r = Ray(offset_origin(p, n, wi), wi);
    if (bounce >= 3) {
      float q = min(max3(beta), 0.95);
      if (u_light.w >= q) break;
      beta /= q;
    }
  }
  return L;
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec3 sum = vec3(0.0);
  float sum_l2 = 0.0;
  float bad = 0.0;
  g_rays = 0;
  for (int s = 0; s < u_spp; ++s) {
    sampler_init(uvec2(px), uint(u_sample_base + s));
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
    vec3 c = trace_path(Ray(o, d));
    if (non_finite(c)) {
      bad += 1.0;
      c = vec3(0.0);
    }
    sum += c;
    float l = luminance(c);
    sum_l2 += l * l;
  }
  // rgb: mean radiance; a: mean squared luminance (for the per-pixel variance).
  vec4 cur = vec4(sum, sum_l2) / float(u_spp);
  o_accum = u_blend >= 1.0 ? cur : mix(texelFetch(u_accum, px, 0), cur, u_blend);
  vec4 prev_stats = u_blend >= 1.0 ? vec4(0.0) : texelFetch(u_stats_in, px, 0);
  o_stats = prev_stats + vec4(bad, float(g_rays), 0.0, 0.0);
}
