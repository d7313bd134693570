// media.glsl: the absorbing media a path travels in (HAS_MEDIA: some material's surface
// bounds one, materials/material.h kMedium). One level: crossing a medium's surface inwards
// enters it, outwards leaves it into air; the camera is in air. Included after the
// generated material_medium dispatch; used by integrator.glsl and whitted.glsl.
// What a segment of length t keeps in a medium of absorption sigma (exactly 1 in air, also
// for an infinite t: no 0 * inf).
vec3 medium_transmittance(vec3 sigma, float t) { return max3(sigma) > 0.0 ? exp(-sigma * t) : vec3(1.0); }
// After a scattering at a surface of material m, towards wi: crossing a medium's surface
// (wi on the other side of n, the normal on the side the path came from) enters the
// medium (arriving on the outer side) or leaves it into air.
void medium_cross(inout vec3 sigma, MaterialRec m, bool entering, vec3 n, vec3 wi) {
  vec3 s;
  if (dot(wi, n) < 0.0 && material_medium(m, s)) sigma = entering ? s : vec3(0.0);
}
