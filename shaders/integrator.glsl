// integrator.glsl: the progressive path tracer's fragment program. Each fragment traces
// u_spp camera paths through its pixel and blends their mean into the running mean of
// the previous pass (ping-pong). Unbiased: next-event estimation to emissive shapes,
// combined with BSDF sampling by the power heuristic; Russian roulette after 3 bounces.
#include "camera_pass.glsl"

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
    if (s.kind == SHAPE_MESH) {
      vec3 ns;
      vec2 uv_unused;
      if (mesh_attributes(h.prim, h.p, ns, uv_unused) && dot(ns, ns) > 0.0) {
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
      m = resolve_textured(m, s, h, n, -r.d, fr);
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
          if (light_visible(p, n, ls.wi, ls.dist, ls.shape))
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
