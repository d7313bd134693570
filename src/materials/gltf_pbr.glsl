// GltfPbr: a glTF metallic-roughness material with its maps (materials/gltf_pbr.h). It
// never shades as itself: resolve_hit_gltf_pbr (gltf_pbr_resolve.glsl) turns it into the
// MetallicRoughness record of the hit. This file holds what the traversal needs before
// that: its maps' lookup and the hit cut (alpha, culled back faces).
#include "image_maps.glsl"

bool delta_gltf_pbr(MaterialRec m) { return false; }
vec3 albedo_gltf_pbr(MaterialRec m) { return m.tint; }
vec3 eval_gltf_pbr(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  return vec3(0.0);
}
bool sample_gltf_pbr(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) { return false; }

// The medium inside (kMedium): KHR_materials_volume's, where the material has one (its
// absorption: the texinfo record kVolume, materials/gltf_pbr.h).
bool medium_gltf_pbr(MaterialRec m, out vec3 sigma) {
  GltfPbrRec q = gltf_pbr_rec(m);
  sigma = q.volume > 0.0 ? load_texinfo(q.maps + 13).row0 : vec3(0.0);
  return q.volume > 0.0;
}

// The uv sets and vertex colour at a hit.
struct GltfUv { vec2 uv0; vec2 uv1; vec4 color; };

// A mesh triangle's vertex uv (both sets) and colour at point p; unchanged elsewhere.
void gltf_vertex_attributes(int prim, vec3 p, inout GltfUv g) {
#ifdef HAS_SHAPE_MESH
  PrimRec t = load_prim(prim);
  if (t.tag < 0 || t.attr.x < 0.0) return;
  vec3 b = mesh_barycentrics(t, p);
  VertexRec a = load_vertex(int(t.attr.x)), c = load_vertex(int(t.attr.y)), d = load_vertex(int(t.attr.z));
  g.uv0 = b.x * vec2(a.u, a.v) + b.y * vec2(c.u, c.v) + b.z * vec2(d.u, d.v);
  g.uv1 = b.x * vec2(a.u1, a.v1) + b.y * vec2(c.u1, c.v1) + b.z * vec2(d.u1, d.v1);
  g.color = b.x * vec4(a.color, a.alpha) + b.y * vec4(c.color, c.alpha) + b.z * vec4(d.color, d.alpha);
#endif
}

// A wrap mode (materials/gltf_map.h: 0 REPEAT, 1 CLAMP_TO_EDGE, 2 MIRRORED_REPEAT) on one
// coordinate of a layer n texels wide. REPEAT is left to the array's own repeat wrapping;
// the other two are clamped half a texel inside, where bilinear filtering reads only the
// edge texel, which is what both modes give there.
float gltf_wrap(float x, int mode, float n) {
  if (mode == 0) return fract(x);
  float y = mode == 1 ? clamp(x, 0.0, 1.0) : 1.0 - abs(2.0 * fract(0.5 * x) - 1.0);
  return clamp(y, 0.5 / n, 1.0 - 0.5 / n);
}

// Texinfo record `rec` read at the hit's uv (linear RGBA as decoded); `fallback` without a map.
vec4 gltf_map(int rec, GltfUv g, vec4 fallback) {
  TexinfoRec t = load_texinfo(rec);
  if (t.code < 0.0) return fallback;
  int code = int(t.code);
  vec2 uv = ((code >> 4) & 1) == 1 ? g.uv1 : g.uv0;
  vec2 st = vec2(dot(t.row0, vec3(uv, 1.0)), dot(t.row1, vec3(uv, 1.0)));
  vec2 size = vec2(textureSize(u_maps, 0).xy);
  st = vec2(gltf_wrap(st.x, (code >> 2) & 3, size.x), gltf_wrap(st.y, code & 3, size.y));
  if ((code & 32) != 0) st = (min(floor(st * size), size - 1.0) + 0.5) / size;  // NEAREST: the texel's centre
  return textureLod(u_maps, vec3(st, float(code >> 6)), 0.0);
}

// A uniform number in [0, 1) per ray and primitive: stochastic alpha (BLEND) decides a
// hit the same way for every traversal of the same ray (nearest and any-hit queries
// agree), independently for different rays (pbrt-v4's HashFloat(ray.o, ray.d) idea).
float gltf_alpha_hash(Ray r, int prim) {
  uvec3 o = floatBitsToUint(r.o), d = floatBitsToUint(r.d);
  uint x = pcg_hash(o.x ^ pcg_hash(o.y ^ pcg_hash(o.z ^ pcg_hash(d.x ^ pcg_hash(d.y ^ pcg_hash(d.z ^ uint(prim)))))));
  return float(x >> 8u) * (1.0 / 16777216.0);
}

// The traversal's question (kCutsHits; bvh.glsl under HAS_HIT_CUTS): is the candidate hit
// h of ray r on mesh triangle `prim` a surface? A back face of a single-sided material
// is not (culled), except a volume's (its inside is the boundary a path inside crosses
// out of: docs/gltf.md); alpha = alpha factor * base colour map alpha * COLOR_0 alpha, and MASK
// keeps the hit where alpha >= cutoff, BLEND with probability alpha.
bool hit_present_gltf_pbr(MaterialRec m, int prim, Ray r, Hit h) {
  GltfPbrRec q = gltf_pbr_rec(m);
  if (q.two_sided < 0.5 && q.volume <= 0.0 && dot(r.d, h.n) > 0.0) return false;
  if (q.cutoff == 0.0) return true;  // OPAQUE (a mask at 0 keeps every alpha)
  GltfUv g = GltfUv(vec2(0.0), vec2(0.0), vec4(1.0));
  gltf_vertex_attributes(prim, h.p, g);
  float a = q.alpha * g.color.a * gltf_map(q.maps, g, vec4(1.0)).a;
  return q.cutoff > 0.0 ? a >= q.cutoff : gltf_alpha_hash(r, prim) < a;
}
