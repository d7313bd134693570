// integrator.glsl: the progressive path tracer's fragment program. Each fragment traces
// u_spp camera paths through its pixel and blends their mean into the running mean of
// the previous pass (ping-pong). Unbiased: next-event estimation to emissive shapes,
// combined with BSDF sampling by the power heuristic, and to punctual lights (delta: NEE
// alone, weight 1); Russian roulette after 3 bounces. With HAS_MEDIA the path knows the
// absorbing medium it travels in (one level: a medium's surface that the path crosses
// inwards sets it, outwards clears it; the camera is in air; materials/material.h
// kMedium): every segment, shadow rays included, keeps exp(-sigma t) (Beer-Lambert).
#include "camera_pass.glsl"

vec3 trace_path(Ray r) {
  vec3 L = vec3(0.0);
  vec3 beta = vec3(1.0);
  float prev_pdf = 0.0;
  bool prev_delta = true;
  vec3 prev_p = r.o;
#ifdef HAS_MEDIA
  vec3 sigma = vec3(0.0);  // the medium the path is in (the camera's: air)
#endif
  for (int bounce = 0;; ++bounce) {
    Hit h = scene_intersect(r);
#ifdef HAS_MEDIA
    if (h.id >= 0) beta *= medium_transmittance(sigma, h.t);  // (a miss inside a medium: an open surface; left as is)
#endif
    if (h.id < 0) {
      AUX_MISS(beta);
#ifdef HAS_ENV_MAP
      float w = 1.0;
      if (u_nee != 0 && !prev_delta) w = power_heuristic(prev_pdf, env_light_pdf(r.d));
      L += beta * env_radiance(r.d) * w;
#else
      L += beta * u_env_color;
#endif
      break;
    }
    Surface sf = surface_hit(r, h);
    AUX_SURFACE(sf, beta, h.t);
    vec3 p = h.p;
    vec3 n = sf.n;
    // Emission from the front side; weighted against light sampling when this shape is a
    // light and the direction was not a delta-lobe choice.
    if (max3(sf.emission) > 0.0) {
      float w = 1.0;
      if (u_nee != 0 && !prev_delta && sf.s.light >= 0) w = power_heuristic(prev_pdf, light_pdf(sf.s, prev_p, r.d, h.t, h.n));
      L += beta * sf.emission * w;
    }
    if (sf.absorbs) break;  // Emit+Absorb ends the path
    if (bounce >= u_max_bounces) break;
    vec4 u_light = next4();  // xyz: light choice and point; w: Russian roulette
    vec4 u_bsdf = next4();   // xyz: BSDF sample; w: choice of a composite's child
    surface_resolve(sf, r, h, u_bsdf.w);
    AUX_MATERIAL(sf, beta);
    MaterialRec m = sf.m;
    Frame fr = sf.fr;
    vec3 wo = sf.wo;
    bool entering = sf.entering;
    if (u_nee != 0 && have_lights() && !material_is_delta(m)) {
      LightSample ls;
      if (light_sample(p, u_light.xyz, ls)) {
        float pdf_b;
        vec3 wl = to_local(fr, ls.wi);
        vec3 f = material_eval(m, wo, wl, entering, pdf_b);
        if (!surface_sides_agree(sf, ls.wi, wl)) f = vec3(0.0);
        if (max3(f) > 0.0) {
#ifdef HAS_PUNCTUAL
          float w = ls.delta ? 1.0 : power_heuristic(ls.pdf, pdf_b);  // a delta light: no BSDF sample reaches it
#else
          float w = power_heuristic(ls.pdf, pdf_b);
#endif
          if (light_visible(p, n, ls.wi, ls.dist, ls.shape)) {
#ifdef HAS_MEDIA
            // A clear shadow ray crossed no surface: it stayed in this medium all the way
            // (a ray from inside that would leave it meets the medium's surface: occluded).
            f *= medium_transmittance(sigma, ls.dist);
#endif
            L += beta * f * ls.radiance * (w / ls.pdf);
          }
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
    if (!surface_sides_agree(sf, wi, bs.wi)) break;  // would cross the geometric surface
#ifdef HAS_MEDIA
    medium_cross(sigma, sf, wi);
#endif
    r = Ray(offset_origin(p, n, wi), wi);
    if (bounce >= 3) {
      float q = min(max3(beta), 0.95);
      if (u_light.w >= q) break;
      beta /= q;
    }
  }
  return L;
}
