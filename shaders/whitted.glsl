// whitted.glsl: the ray-tracer mode (Whitted 1980, with area lights). What it computes,
// per camera ray, following the ray through delta surfaces until a non-delta surface, the
// environment or the bounce limit:
//   - a ray that leaves the scene: the environment's radiance (map or constant colour);
//   - emission of every surface hit from its front side (camera and delta chains only);
//   - at a delta surface (Reflect, SmoothDielectric, Transmit, a mirror Metal, and
//     FresnelComposite resolved to one of those): the mirror or refracted ray, weighted by
//     the material, continues. Where a dielectric both reflects and refracts, one of the
//     two is taken per sample with probability F (exact Fresnel), so the running mean
//     converges to the sum over the whole Whitted tree of reflected and refracted rays;
//     FresnelComposite picks its child the same way;
//   - at a non-delta surface (Diffuse, textures, PhongSpecular, rough Metal): direct
//     light only, then the ray stops (no indirect light): every light-sampled emitter
//     (each <Light> and emitting box, triangle or sphere) gets one sample point and one
//     shadow ray per camera sample, f * Le / pdf when unoccluded; each punctual light
//     (point, spot, directional) one shadow ray, f * E when unoccluded; and the environment
//     one sample (a map: importance-sampled by luminance; a constant colour: a BSDF-
//     sampled direction) that counts when its shadow ray leaves the scene.
// Each delta or non-delta surface counts as one bounce; at the bounce limit the ray ends
// (it carries nothing further). Emitters that are not light-sampled (planes) light
// nothing directly. Inside an absorbing medium (HAS_MEDIA, media.glsl) each segment and
// shadow ray keeps exp(-sigma t), as in the path tracer. The estimate is the exact value of this model in expectation.
#include "camera_pass.glsl"
#ifdef HAS_MEDIA
#define WHITTED_MEDIUM(sigma, t) medium_transmittance(sigma, t)
#else
#define WHITTED_MEDIUM(sigma, t) 1.0
#endif

vec3 whitted_env(vec3 d) {
#ifdef HAS_ENV_MAP
  return env_radiance(d);
#else
  return u_env_color;
#endif
}

// Direct light reflected towards the viewer at p by the resolved non-delta surface sf.
vec3 whitted_direct(Surface sf, vec3 p, vec3 sigma) {
  MaterialRec m = sf.m;
  Frame fr = sf.fr;
  vec3 n = sf.n, wo = sf.wo;
  bool entering = sf.entering;
  vec3 L = vec3(0.0);
  float pdf_b;
  for (int li = 0; li < u_num_lights; ++li) {
    LightRec l = load_light(li);
    if (l.pmf == 0.0 && u_lights_uniform == 0) continue;  // sealed off from the camera (render/light_select.h)
    vec3 wi;
    float pdf, dist;
#ifdef HAS_PUNCTUAL
    if (l.shape < 0) {  // a punctual light: its irradiance when its shadow ray is clear
      vec3 e;
      if (!punctual_sample(l, p, wi, dist, e)) continue;
      vec3 wl = to_local(fr, wi);
      vec3 f = surface_sides_agree(sf, wi, wl) ? material_eval(m, wo, wl, entering, pdf_b) : vec3(0.0);
      if (max3(f) > 0.0 && light_visible(p, n, wi, dist, -1)) L += f * e * WHITTED_MEDIUM(sigma, dist);
      continue;
    }
#endif
    if (!light_sample_shape(load_shape(l.shape), p, next4().xy, wi, pdf, dist) || !(pdf > 0.0)) continue;
    vec3 wl = to_local(fr, wi);
    vec3 f = surface_sides_agree(sf, wi, wl) ? material_eval(m, wo, wl, entering, pdf_b) : vec3(0.0);
    if (max3(f) > 0.0 && light_visible(p, n, wi, dist, l.shape)) L += f * l.radiance / pdf * WHITTED_MEDIUM(sigma, dist);
  }
#ifdef HAS_ENV_MAP
  vec3 wi, rad;
  float pdf;
  if (env_sample(next4().xy, wi, pdf, rad)) {
    vec3 wl = to_local(fr, wi);
    vec3 f = surface_sides_agree(sf, wi, wl) ? material_eval(m, wo, wl, entering, pdf_b) : vec3(0.0);
    if (max3(f) > 0.0 && light_visible(p, n, wi, T_INF, -1)) L += f * rad / pdf;
  }
#else
  BsdfSample bs;
  if (max3(u_env_color) > 0.0 && material_sample(m, wo, entering, next4().xyz, bs)) {
    vec3 wi = normalize(from_local(fr, bs.wi));
    if (surface_sides_agree(sf, wi, bs.wi) && light_visible(p, n, wi, T_INF, -1)) L += bs.weight * u_env_color;
  }
#endif
  return L;
}

vec3 trace_path(Ray r) {
  vec3 L = vec3(0.0);
  vec3 beta = vec3(1.0);
  vec3 sigma = vec3(0.0);  // the medium the ray is in (HAS_MEDIA; the camera's: air)
  for (int bounce = 0;; ++bounce) {
    Hit h = scene_intersect(r);
    if (h.id >= 0) beta *= WHITTED_MEDIUM(sigma, h.t);
    if (h.id < 0) {
      L += beta * whitted_env(r.d);
      break;
    }
    Surface sf = surface_hit(r, h);
    L += beta * sf.emission;
    if (sf.absorbs) break;  // Emit+Absorb ends the ray
    if (bounce >= u_max_bounces) break;
    vec4 u = next4();  // xyz: delta lobe choice; w: a composite's child
    surface_resolve(sf, r, h, u.w);
    if (!material_is_delta(sf.m)) {
      L += beta * whitted_direct(sf, h.p, sigma);
      break;
    }
    BsdfSample bs;
    if (!material_sample(sf.m, sf.wo, sf.entering, u.xyz, bs)) break;
    beta *= bs.weight;
    vec3 wi = normalize(from_local(sf.fr, bs.wi));
    if (!surface_sides_agree(sf, wi, bs.wi)) break;  // would cross the geometric surface
#ifdef HAS_MEDIA
    medium_cross(sigma, sf, wi);
#endif
    r = Ray(offset_origin(h.p, sf.n, wi), wi);
  }
  return L;
}
