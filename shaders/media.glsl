// media.glsl: the absorbing media a path travels in (HAS_MEDIA: some material's surface
// bounds one, materials/material.h kMedium). One level: crossing a medium's surface inwards
// enters it, outwards leaves it into air; the camera is in air. Included after the
// generated material_medium dispatch; used by integrator.glsl and whitted.glsl. The
// surface step asks the material for its medium (sf.medium, sf.sigma) after choosing a
// composite's child and before a kind resolved at the hit becomes what shades there
// (GltfPbr's volume is the GltfPbr's, not its hit's MetallicRoughness record's).
// What a segment of length t keeps in a medium of absorption sigma (exactly 1 in air, also
// for an infinite t: no 0 * inf).
vec3 medium_transmittance(vec3 sigma, float t) { return max3(sigma) > 0.0 ? exp(-sigma * t) : vec3(1.0); }
// After a scattering at surface sf, towards wi: crossing a medium's surface (wi on the
// other side of sf.n, the normal on the side the path came from) enters the medium
// (arriving on the outer side) or leaves it into air.
void medium_cross(inout vec3 sigma, Surface sf, vec3 wi) {
  if (sf.medium && dot(wi, sf.n) < 0.0) sigma = sf.entering ? sf.sigma : vec3(0.0);
}
