// Infinite plane: <Plane normal="x y z" d="d">, the points p with dot(normal, p) = d
// (the loader normalises the normal and scales d with it).
void intersect_plane(ShapeRec s, int id, Ray r, inout Hit h) {
  float denom = dot(s.a, r.d);
  if (denom == 0.0) return;  // parallel: no hit, or the ray lies in the plane
  float t = (s.radius - dot(s.a, r.o)) / denom;
  if (t <= 0.0 || t >= h.t) return;
  h.t = t;
  h.id = id;
  h.n = s.a;
  h.p = r.o + t * r.d;
  h.p -= s.a * (dot(s.a, h.p) - s.radius);
}

#ifdef HAS_IMAGE_MAPS
// Image maps: planar in the plane's tangent frame frame_from(normal), in scene units
// (the material's uvScale sets the tile size): uv = (dot(p, t), dot(p, b)). For the floor
// (normal +y) t = +x and b = -z: u = x, v = -z.
vec2 uv_plane(ShapeRec s, vec3 p, vec3 n) {
  Frame f = frame_from(s.a);
  return vec2(dot(p, f.t), dot(p, f.b));
}
vec4 tangent_plane(ShapeRec s, vec3 p, vec3 n) { return vec4(frame_from(s.a).t, 1.0); }
#endif
