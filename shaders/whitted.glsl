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
//     shadow ray per camera sample, f * Le / pdf when unoccluded; and the environment
//     one sample (a map: importance-sampled by luminance; a constant colour: a BSDF-
//     sampled direction) that counts when its shadow ray leaves the scene.
// Each delta or non-delta surface counts as one bounce; at the bounce limit the ray ends
// (it carries nothing further). Emitters that are not light-sampled (planes) light
// nothing directly. The estimate is the exact value of this model in expectation.
#include "camera_pass.glsl"

vec3 whitted_env(vec3 d) {
#ifdef HAS_ENV_MAP
  return env_radiance(d);
#else
  return u_env_color;
#endif
}

// Direct light reflected towards wo at p by non-delta material m.
vec3 whitted_direct(MaterialRec m, Frame fr, vec3 p, vec3 n, vec3 wo, bool entering) {
  vec3 L = vec3(0.0);
  float pdf_b;
  for (int li = 0; li < u_num_lights; ++li) {
    LightRec l = load_light(li);
    vec3 wi;
    float pdf, dist;
    if (!light_sample_shape(load_shape(l.shape), p, next4().xy, wi, pdf, dist) || !(pdf > 0.0)) continue;
    vec3 f = material_eval(m, wo, to_local(fr, wi), entering, pdf_b);
    if (max3(f) > 0.0 && light_visible(p, n, wi, dist, l.shape)) L += f * l.radiance / pdf;
  }
#ifdef HAS_ENV_MAP
  vec3 wi, rad;
  float pdf;
  if (env_sample(next4().xy, wi, pdf, rad)) {
    vec3 f = material_eval(m, wo, to_local(fr, wi), entering, pdf_b);
    if (max3(f) > 0.0 && light_visible(p, n, wi, T_INF, -1)) L += f * rad / pdf;
  }
#else
  BsdfSample bs;
  if (max3(u_env_color) > 0.0 && material_sample(m, wo, entering, next4().xyz, bs)) {
    vec3 wi = normalize(from_local(fr, bs.wi));
    if (light_visible(p, n, wi, T_INF, -1)) L += bs.weight * u_env_color;
  }
#endif
  return L;
}

vec3 trace_path(Ray r) {
  vec3 L = vec3(0.0);
  vec3 beta = vec3(1.0);
  for (int bounce = 0;; ++bounce) {
    Hit h = scene_intersect(r);
    if (h.id < 0) {
      L += beta * whitted_env(r.d);
      break;
    }
    ShapeRec s = load_shape(h.id);
    MaterialRec m = load_material(s.material);
    bool entering = dot(r.d, h.n) < 0.0;
    if (entering) L += beta * m.emission;
#ifdef HAS_MAT_EMIT
    if (m.kind == MAT_EMIT) break;  // Emit+Absorb ends the ray
#endif
    if (bounce >= u_max_bounces) break;
    vec3 n = entering ? h.n : -h.n;  // faces the side the ray came from
    Frame fr = frame_from(n);
    vec3 wo = to_local(fr, -r.d);
    vec4 u = next4();  // xyz: delta lobe choice; w: a composite's child
#ifdef HAS_MAT_FRESNEL_COMPOSITE
    m = resolve_fresnel_composite(m, wo.z, entering, u.w);
#endif
#ifdef HAS_TEXTURES
    m = resolve_texture(m, h.p);
#endif
    if (!material_is_delta(m)) {
      L += beta * whitted_direct(m, fr, h.p, n, wo, entering);
      break;
    }
    BsdfSample bs;
    if (!material_sample(m, wo, entering, u.xyz, bs)) break;
    beta *= bs.weight;
    vec3 wi = normalize(from_local(fr, bs.wi));
    r = Ray(offset_origin(h.p, n, wi), wi);
  }
  return L;
}
