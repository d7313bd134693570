// sh_irradiance.glsl: the spherical-harmonics irradiance mode. What it computes, per
// camera ray:
//   - a ray that leaves the scene: the environment's radiance (map or constant colour);
//   - at the first surface hit: emission (front side) + albedo * E(n) / pi, where E is
//     the environment's irradiance from its 9 order-2 SH coefficients (sh.glsl) and n
//     the geometric normal facing the viewer. albedo is the material's tint after
//     texture and FresnelComposite resolution (Diffuse: its albedo; other kinds are
//     shaded as if Lambertian with their tint; Emit+Absorb shows only its emission).
// As in the classic technique, visibility is ignored: no shadows, no occlusion, no
// interreflection, and the scene's own emitters (lights, Emit) light nothing: only the
// environment illuminates. The bounce limit does not apply (one hit).
#include "camera_pass.glsl"
#include "sh.glsl"

vec3 trace_path(Ray r) {
  Hit h = scene_intersect(r);
  if (h.id < 0) {
#ifdef HAS_ENV_MAP
    return env_radiance(r.d);
#else
    return u_env_color;
#endif
  }
  ShapeRec s = load_shape(h.id);
  MaterialRec m = load_material(s.material);
  bool entering = dot(r.d, h.n) < 0.0;
  vec3 n = entering ? h.n : -h.n;
  vec3 L = entering ? m.emission : vec3(0.0);
#ifdef HAS_MAT_EMIT
  if (m.kind == MAT_EMIT) return L;
#endif
#ifdef HAS_MAT_FRESNEL_COMPOSITE
  m = resolve_fresnel_composite(m, dot(-r.d, n), entering, next4().x);
#endif
#ifdef HAS_TEXTURES
  m = resolve_texture(m, h.p);
#endif
  return L + m.tint * sh_irradiance(n) * INV_PI;
}
