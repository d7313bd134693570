// gltf_pbr_resolve.glsl: a GltfPbr record at a hit becomes the MetallicRoughness record
// of its maps' values there (included after the generated surface_uv dispatch,
// shadergen/textured_gen.cpp), and its emission is read there (emission_hit_gltf_pbr).

GltfUv gltf_uvs(ShapeRec s, Hit h, out vec4 tangent) {
  SurfaceUv su = surface_uv(s, h);
  tangent = su.tangent;
  GltfUv g = GltfUv(su.uv, su.uv, vec4(1.0));
  gltf_vertex_attributes(h.prim, h.p, g);
  return g;
}

// Normal mapping (glTF 3.9.3): the map's vector in the tangent frame (t, b, n) of the hit,
// its xy times normalTexture.scale: n_s = normalize(x t + y b + z n). t = dp/du of
// TEXCOORD_0 (the shape's uv map, as Textured: textured_resolve.glsl), b = w (n x t), n
// the outward base normal (the mesh's interpolated one where it has them). glTF's +y is
// towards the image's top row, which is our +v (our v runs up: the loader flips glTF's).
vec3 gltf_normal(int rec, GltfUv g, vec3 n_out, vec4 tangent) {
  TexinfoRec ti = load_texinfo(rec);
  if (ti.code < 0.0) return n_out;
  vec3 nt = gltf_map(rec, g, vec4(0.0, 0.0, 1.0, 1.0)).xyz;
  vec3 t = tangent.xyz - n_out * dot(n_out, tangent.xyz);
  t = dot(t, t) > 0.0 ? normalize(t) : frame_from(n_out).t;
  vec3 b = cross(n_out, t) * tangent.w;
  vec3 d = ti.strength * (nt.x * t + nt.y * b);
  return dot(d, d) == 0.0 ? n_out : normalize(d + max(nt.z, 1e-3) * n_out);
}

// The clearcoat's normal (KHR_materials_clearcoat) in the shading frame fr, packed for the
// MetallicRoughness record (metallic_roughness.glsl mr_lobes): 0 when it is fr's own, else
// (x, y) + 1 on 2047 steps per unit, plus 1. n_base: the surface's normal on the ray's side
// before the base's normal map (the coat's when it has no map of its own).
float gltf_coat_normal(int rec, GltfUv g, Surface sf, vec3 n_base, Hit h, vec4 tangent) {
  vec3 nc = n_base;
  if (load_texinfo(rec).code >= 0.0) {
    vec3 n_out = dot(n_base, h.n) < 0.0 ? -n_base : n_base;
    nc = gltf_normal(rec, g, n_out, tangent);
    if (dot(sf.n, h.n) < 0.0) nc = -nc;
  }
  vec3 c = to_local(sf.fr, nc);
  if (c.z <= 0.0 || c.z >= 1.0 - 1e-7) return 0.0;
  return 1.0 + gltf_pack2((c.xy + 1.0) * (2047.0 / 4095.0));
}

// The surface step's hook (kResolvesAtHit).
void resolve_hit_gltf_pbr(inout Surface sf, Ray r, Hit h) {
  GltfPbrRec q = gltf_pbr_rec(sf.m);
  vec4 tangent;
  GltfUv g = gltf_uvs(sf.s, h, tangent);
  vec3 n_base = sf.fr.n;  // the shading normal so far (a mesh's interpolated one), on the ray's side
  if (load_texinfo(q.maps + 2).code >= 0.0) {
    vec3 wo = -r.d;
    vec3 n_out = dot(n_base, h.n) < 0.0 ? -n_base : n_base;
    vec3 ns = gltf_normal(q.maps + 2, g, n_out, tangent);
    if (dot(sf.n, h.n) < 0.0) ns = -ns;  // the back side sees the same relief from below
    // As textured_resolve.glsl: a normal facing away from the viewer is bent towards it.
    float c_min = min(0.05, dot(wo, sf.n)), c_s = dot(wo, ns);
    if (c_s < c_min) ns = normalize(ns + (c_min - c_s) * wo);
    sf.fr = frame_from(ns);
    sf.wo = to_local(sf.fr, wo);
    sf.shading_normal = true;
  }
  vec4 base_color = vec4(sf.m.tint, q.alpha) * g.color * gltf_map(q.maps, g, vec4(1.0));
  vec4 mr = gltf_map(q.maps + 1, g, vec4(1.0));
  MaterialRec m = sf.m;
  m.kind = MAT_METALLIC_ROUGHNESS;
  m.tint = base_color.rgb;
  // The extensions' values here (materials/gltf_pbr.h: the records from q.maps on).
  TexinfoRec factors = load_texinfo(q.maps + 11);
  vec3 f0 = vec3(q.f0);
  float specular = 1.0, coat = 0.0, sheen_br = 0.0, sheen_rg = 0.0, coat_normal = 0.0, transmission = 0.0, volume = 0.0;
#ifdef HAS_GLTF_SPECULAR
  specular = load_texinfo(q.maps + 4).strength * gltf_map(q.maps + 4, g, vec4(1.0)).a;
  f0 = min(q.f0 * factors.row0 * gltf_map(q.maps + 5, g, vec4(1.0)).rgb, vec3(1.0));
#endif
#ifdef HAS_GLTF_CLEARCOAT
  coat = gltf_pack2(vec2(load_texinfo(q.maps + 6).strength * gltf_map(q.maps + 6, g, vec4(1.0)).r,
                         load_texinfo(q.maps + 7).strength * gltf_map(q.maps + 7, g, vec4(1.0)).g));
  coat_normal = gltf_coat_normal(q.maps + 8, g, sf, n_base, h, tangent);
#endif
#ifdef HAS_GLTF_SHEEN
  vec3 sheen = factors.row1 * gltf_map(q.maps + 9, g, vec4(1.0)).rgb;
  sheen_rg = gltf_pack2(sheen.rg);
  sheen_br = gltf_pack2(vec2(sheen.b, load_texinfo(q.maps + 10).strength * gltf_map(q.maps + 10, g, vec4(1.0)).a));
#endif
#ifdef HAS_GLTF_TRANSMISSION
  transmission = load_texinfo(q.maps + 12).strength * gltf_map(q.maps + 12, g, vec4(1.0)).r;
#endif
#ifdef HAS_GLTF_VOLUME
  volume = q.volume;
#endif
  sf.m = with_metallic_roughness_rec(
      m, MetallicRoughnessRec(q.metallic * mr.b, q.roughness * mr.g, f0, specular, coat, sheen_rg, sheen_br, coat_normal, transmission, volume));
}

// The surface step's emission hook (kEmissionAtHit): a double-sided material emits from
// both sides (glTF shades a back face as a front one); the emissive map where there is one.
void emission_hit_gltf_pbr(inout Surface sf, Ray r, Hit h) {
  GltfPbrRec q = gltf_pbr_rec(sf.m);
  sf.emission = sf.entering || q.two_sided >= 0.5 ? sf.m.emission : vec3(0.0);
#ifdef HAS_EMISSION_MAPS
  if (max3(sf.emission) > 0.0) {
    vec4 tangent;
    GltfUv g = gltf_uvs(sf.s, h, tangent);
    sf.emission *= gltf_map(q.maps + 3, g, vec4(1.0)).rgb;
  }
#endif
}
