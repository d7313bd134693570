// textured_resolve.glsl: a Textured record at a hit becomes its values there (included
// after the generated surface_uv dispatch, see shadergen/textured_gen.cpp):
// resolve_hit_textured, which the surface step calls (surface.glsl).
//
// Normal mapping. The map holds the shading normal in tangent space (t, b, n): t = unit
// dp/du of the shape's uv map, b = w (n x t) = the side of dp/dv, n the outward geometric
// normal; components in [-1, 1] (the loader maps the codes, so (128, 128, 255) is exactly
// (0, 0, 1)); green is +v (OpenGL convention). The path tracer stays consistent with a
// shading normal n_s the way pbrt does it (Veach 1997, 5.3; pbrt-v3 9.1):
//  - the BSDF (both lobes and their cosines) is evaluated in the frame of n_s;
//  - the geometric normal decides the side: the integrator spawns rays off the geometric
//    surface, and a direction whose side differs between n_s and n_g carries no light
//    (no light leaks through the surface, none from below it);
//  - camera paths carry radiance, for which the shading-normal BSDF needs no adjoint
//    correction (Veach's correction applies to importance transport).
// Where the map tilts n_s away from the viewer (wo below the shading horizon, which would
// shade black), n_s is bent towards wo (n_s + (c_min - cos(wo, n_s)) wo, normalised, with
// c_min = min(0.05, cos(wo, n_g))) so that wo is above its horizon, as renderers commonly do (Cycles' ensure_valid_reflection is the same idea). A flat map
// leaves the normal bit for bit the geometric one, so it renders exactly as no map.
vec3 textured_normal(TexturedRec q, vec2 uv, vec3 n_out, vec4 tangent) {
  if (q.map_normal < 0) return n_out;
  vec3 nt = map_lookup(q.map_normal, uv);
  vec3 t = tangent.xyz * (q.uv_scale.x < 0.0 ? -1.0 : 1.0);  // a mirrored uv transform mirrors the frame
  vec3 b = cross(n_out, tangent.xyz) * tangent.w * (q.uv_scale.y < 0.0 ? -1.0 : 1.0);
  vec3 d = nt.x * t + nt.y * b;
  return dot(d, d) == 0.0 ? n_out : normalize(d + max(nt.z, 1e-3) * n_out);
}

// s, h: the hit's shape and the hit (h.n the outward normal); n: the geometric normal on
// the viewer's side; wo: unit direction to the viewer. Returns the record with
// tint = (1 - s) rho and spec = s, and sets fr to the shading frame.
MaterialRec resolve_textured(MaterialRec m, ShapeRec s, Hit h, vec3 n, vec3 wo, out Frame fr) {
  vec3 n_out = h.n;
  TexturedRec q = textured_rec(m);
  SurfaceUv su = surface_uv(s, h);
  vec2 uv = su.uv * q.uv_scale + q.uv_offset;
  vec3 ns = textured_normal(q, uv, n_out, su.tangent);
  if (dot(n, n_out) < 0.0) ns = -ns;  // the back side sees the same relief from below
  float c_min = min(0.05, dot(wo, n)), c_s = dot(wo, ns);
  if (c_s < c_min) ns = normalize(ns + (c_min - c_s) * wo);
  fr = frame_from(ns);
  vec3 rho = q.map_diffuse >= 0 ? m.tint * map_lookup(q.map_diffuse, uv) : m.tint;
  vec3 spec = q.map_specular >= 0 ? map_lookup(q.map_specular, uv) : vec3(0.0);
  q.spec = spec;
  m = with_textured_rec(m, q);
  m.tint = (1.0 - spec) * rho;
  return m;
}

// The surface step's hook (materials/textured.h: kResolvesAtHit): the image maps' values
// and the normal map's shading frame (whose side tests use the geometric normal).
void resolve_hit_textured(inout Surface sf, Ray r, Hit h) {
  sf.shading_normal = true;
  sf.m = resolve_textured(sf.m, sf.s, h, sf.n, -r.d, sf.fr);
  sf.wo = to_local(sf.fr, -r.d);
}
