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

// The surface step's hook (kResolvesAtHit).
void resolve_hit_gltf_pbr(inout Surface sf, Ray r, Hit h) {
  GltfPbrRec q = gltf_pbr_rec(sf.m);
  vec4 tangent;
  GltfUv g = gltf_uvs(sf.s, h, tangent);
  if (load_texinfo(q.maps + 2).code >= 0.0) {
    vec3 wo = -r.d;
    vec3 base = sf.fr.n;  // the shading normal so far (a mesh's interpolated one), on the ray's side
    vec3 n_out = dot(base, h.n) < 0.0 ? -base : base;
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
  sf.m = with_metallic_roughness_rec(m, MetallicRoughnessRec(q.metallic * mr.b, q.roughness * mr.g, q.f0));
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
