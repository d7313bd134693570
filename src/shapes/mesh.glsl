// Mesh: <Mesh src="model.gltf|.glb|.obj|.json" position=".." rotation=".." scale="..">,
// an instance of a triangle mesh. Its triangles are BVH primitives with world-space
// vertices inline (see bvh.glsl and the prim record; a moving instance's at time 0,
// triangle.glsl translating the ray); this file holds what a hit on one
// needs afterwards: the interpolated per-vertex attributes (shading normal, uv).
// Barycentrics of p (on the triangle's plane) from the sub-triangle areas.
// A moving instance's hit point is where it is at the path's time: back to time 0 first.
vec3 mesh_barycentrics(PrimRec t, vec3 p) {
#ifdef HAS_MOTION
  p -= prim_offset(t);
#endif
  vec3 e1 = t.v1 - t.v0, e2 = t.v2 - t.v0, q = p - t.v0;
  vec3 n = cross(e1, e2);
  float nn = dot(n, n);
  if (!(nn >= 1e-30)) {
    // A tiny triangle (edges below about 1e-8): |n|^2 leaves float's normal range and
    // 1 / |n|^2 is inf (NaN barycentrics). Against n / max|n| the sums stay in range.
    float s = max_abs(n);
    if (!(s > 0.0)) return vec3(1.0 / 3.0);
    vec3 m = n / s;
    nn = dot(n, m);
    n = m;
  }
  float inv = 1.0 / nn;
  float b1 = dot(cross(q, e2), n) * inv;
  float b2 = dot(cross(e1, q), n) * inv;
  return vec3(1.0 - b1 - b2, b1, b2);
}

// The interpolated shading normal (unit; vec3(0) when the mesh has no normals) and uv at
// point p of mesh triangle `prim`; false when the mesh has no vertex attributes.
bool mesh_attributes(int prim, vec3 p, out vec3 ns, out vec2 uv) {
  ns = vec3(0.0);
  uv = vec2(0.0);
  PrimRec t = load_prim(prim);
  if (t.attr.x < 0.0) return false;
  vec3 b = mesh_barycentrics(t, p);
  VertexRec a = load_vertex(int(t.attr.x)), c = load_vertex(int(t.attr.y)), d = load_vertex(int(t.attr.z));
  vec3 n = b.x * a.normal + b.y * c.normal + b.z * d.normal;
  ns = dot(n, n) > 0.0 ? normalize(n) : vec3(0.0);
  uv = b.x * vec2(a.u, a.v) + b.y * vec2(c.u, c.v) + b.z * vec2(d.u, d.v);
  return true;
}

// The surface step's hook (shapes/mesh.h: kShadingNormal): the vertex normals interpolated
// at the hit, when the mesh has them (surface.glsl orients and checks it).
bool shading_normal_mesh(ShapeRec s, Hit h, out vec3 ns) {
  vec2 uv_unused;
  return mesh_attributes(h.prim, h.p, ns, uv_unused) && dot(ns, ns) > 0.0;
}

#ifdef HAS_IMAGE_MAPS
// Image maps on meshes: the vertex uv interpolated at the hit, and the tangent along
// dp/du from the triangle's uv parameterisation (w: the handedness of dp/dv).
vec2 uv_mesh(ShapeRec s, int prim, vec3 p, vec3 n) {
  vec3 ns;
  vec2 uv;
  mesh_attributes(prim, p, ns, uv);
  return uv;
}

vec4 tangent_mesh(ShapeRec s, int prim, vec3 p, vec3 n) {
  PrimRec t = load_prim(prim);
  vec4 fallback = vec4(frame_from(n).t, 1.0);
  if (t.attr.x < 0.0) return fallback;
  VertexRec a = load_vertex(int(t.attr.x)), b = load_vertex(int(t.attr.y)), c = load_vertex(int(t.attr.z));
  vec2 d1 = vec2(b.u - a.u, b.v - a.v), d2 = vec2(c.u - a.u, c.v - a.v);
  float det = d1.x * d2.y - d1.y * d2.x;
  if (abs(det) < 1e-20) return fallback;
  vec3 e1 = t.v1 - t.v0, e2 = t.v2 - t.v0;
  vec3 dpdu = (e1 * d2.y - e2 * d1.y) / det, dpdv = (e2 * d1.x - e1 * d2.x) / det;
  vec3 tu = dpdu - n * dot(n, dpdu);
  if (!(dot(tu, tu) > 0.0)) return fallback;
  tu = normalize(tu);
  return vec4(tu, dot(cross(n, tu), dpdv) < 0.0 ? -1.0 : 1.0);
}
#endif
