// camera_aux.glsl: the denoiser's first-hit auxiliaries (render/denoise.h), recorded by a
// mode's trace_path through AUX_SURFACE / AUX_MATERIAL / AUX_MISS and averaged over the
// pixel's samples by camera_pass.glsl (so edges are antialiased), only in a program built
// with PT_AUX (RenderSettings::aux); without it the hooks are empty.
//
// Which hit: the first one that is not a delta surface, following a chain of mirrors and
// glass from the camera (the convention of Open Image Denoise's auxiliary images), so a
// reflection or refraction gets the edges of what it shows:
//   - albedo: the throughput of the delta chain times material_albedo() of that hit (its
//     kind's albedo_<kind>, textures resolved); an Emit+Absorb hit or a ray that leaves the
//     scene: the chain's throughput (1 seen directly);
//   - normal: that hit's shading normal on the ray's side; 0 for a ray that leaves;
//   - depth: the path's length to that hit, times the cosine of the camera ray to the view
//     axis (the view depth for a direct hit); kAuxFar for a ray that leaves;
//   - seen: 1 where the camera ray's own hit absorbs (an Emit+Absorb light seen directly),
//     else 0; its mean over the samples is the part of the pixel that shows a light
//     itself. The denoiser leaves such pixels raw and keeps them out of the others' taps:
//     a light is not albedo x irradiance, and its rim mixes it with what is around it.
//     Not through a delta chain: there glass picks reflection or refraction per sample, so
//     such pixels are fireflies that the filter should still spread (the glTF scene's
//     tori: marked, its error rose 10% at 64 spp, docs/denoise.md).
#ifdef PT_AUX
const float kAuxFar = 1.0e5;
vec3 g_aux_albedo;
vec3 g_aux_normal;
float g_aux_length;
float g_aux_seen;
bool g_aux_done;
bool g_aux_camera;  // the next hit is the camera ray's own

void aux_start() {
  g_aux_albedo = vec3(1.0);
  g_aux_normal = vec3(0.0);
  g_aux_length = 0.0;
  g_aux_seen = 0.0;
  g_aux_done = false;
  g_aux_camera = true;
}
// At each hit, before the material is resolved: t the hit's distance along the ray.
void aux_surface(Surface sf, vec3 beta, float t) {
  if (g_aux_done) return;
  g_aux_length += t;
  g_aux_normal = sf.n;
  if (sf.absorbs) {
    g_aux_albedo = beta;
    g_aux_seen = g_aux_camera ? 1.0 : 0.0;
    g_aux_done = true;
  }
  g_aux_camera = false;
}
// Once the material is resolved: a non-delta one ends the chain.
void aux_material(Surface sf, vec3 beta) {
  if (g_aux_done) return;
  g_aux_normal = sf.fr.n;
  g_aux_albedo = beta * material_albedo(sf.m);
  g_aux_done = !material_is_delta(sf.m);
}
void aux_miss(vec3 beta) {
  if (g_aux_done) return;
  g_aux_albedo = beta;
  g_aux_normal = vec3(0.0);
  g_aux_length = kAuxFar;
  g_aux_done = true;
}
#define AUX_SURFACE(sf, beta, t) aux_surface(sf, beta, t)
#define AUX_MATERIAL(sf, beta) aux_material(sf, beta)
#define AUX_MISS(beta) aux_miss(beta)
#else
#define AUX_SURFACE(sf, beta, t)
#define AUX_MATERIAL(sf, beta)
#define AUX_MISS(beta)
#endif
