// sh_irradiance.glsl: the spherical-harmonics irradiance mode. What it computes, per
// camera ray:
//   - a ray that leaves the scene: the environment's radiance (map or constant colour);
//   - at the first surface hit: emission (front side) + albedo * E(n) / pi, where E is
//     the environment's irradiance from its 9 order-2 SH coefficients (sh.glsl) and n
//     the shading normal facing the viewer (a mesh's interpolated normal, a normal map).
//     The surface is the one every mode sees (surface.glsl: composites, procedural and
//     image textures resolved); albedo is its kind's albedo_<kind> (Diffuse: its albedo;
//     Textured: (1 - s) rho + s; other kinds are shaded as if Lambertian with their
//     tint; Emit+Absorb shows only its emission).
// As in the classic technique, visibility is ignored: no shadows, no occlusion, no
// interreflection, and the scene's own emitting shapes (<Light>, Emit) light nothing:
// the environment illuminates, and so do the punctual lights (point, spot, directional:
// albedo * E * max(cos, 0) / pi from each, their closed-form irradiance, unshadowed).
// The bounce limit does not apply (one hit).
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
  Surface sf = surface_hit(r, h);
  if (sf.absorbs) return sf.emission;
  surface_resolve(sf, r, h, next4().x);
  vec3 E = sh_irradiance(sf.fr.n);
#ifdef HAS_PUNCTUAL
  for (int li = 0; li < u_num_lights; ++li) {
    LightRec l = load_light(li);
    vec3 wi, e;
    float dist;
    if (l.shape < 0 && punctual_sample(l, h.p, wi, dist, e)) E += e * max(dot(sf.fr.n, wi), 0.0);
  }
#endif
  return sf.emission + material_albedo(sf.m) * E * INV_PI;
}
