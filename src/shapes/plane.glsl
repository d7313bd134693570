// Infinite plane: <Plane normal="x y z" d="d" velocity="..">, the points p with
// dot(normal, p) = d (the loader normalises the normal and scales d with it). A moving
// plane (HAS_MOTION): the ray is translated by -velocity * g_time and the hit point back;
// image maps read the point in the plane's frame at time 0 (it carries its texture).
void intersect_plane(ShapeRec s, int id, Ray r, inout Hit h) {
  PlaneRec k = plane_rec(s);
#ifdef HAS_MOTION
  vec3 off = k.velocity * g_time;
  r.o -= off;
#endif
  float denom = dot(k.normal, r.d);
  if (denom == 0.0) return;  // parallel: no hit, or the ray lies in the plane
  float t = (k.d - dot(k.normal, r.o)) / denom;
  if (t <= 0.0 || t >= h.t) return;
  h.t = t;
  h.id = id;
  h.n = k.normal;
  h.p = r.o + t * r.d;
  h.p -= k.normal * (dot(k.normal, h.p) - k.d);
#ifdef HAS_MOTION
  h.p += off;
#endif
}

#ifdef HAS_IMAGE_MAPS
// Image maps: planar in the plane's tangent frame frame_from(normal), in scene units
// (the material's uvScale sets the tile size): uv = (dot(p, t), dot(p, b)). For the floor
// (normal +y) t = +x and b = -z: u = x, v = -z.
vec2 uv_plane(ShapeRec s, vec3 p, vec3 n) {
  PlaneRec k = plane_rec(s);
#ifdef HAS_MOTION
  p -= k.velocity * g_time;
#endif
  Frame f = frame_from(k.normal);
  return vec2(dot(p, f.t), dot(p, f.b));
}
vec4 tangent_plane(ShapeRec s, vec3 p, vec3 n) {
  PlaneRec k = plane_rec(s);
  return vec4(frame_from(k.normal).t, 1.0);
}
#endif
