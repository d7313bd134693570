// texture_common.glsl: what the procedural (solid) textures share. A texture kind is a
// Lambertian surface whose albedo varies in space: the surface step turns it into a
// Diffuse record at the hit point (resolve_hit_<kind>, materials/solid_texture.h), so it
// shades, light-samples and passes the furnace exactly as Diffuse does.
MaterialRec textured_diffuse(MaterialRec m, vec3 color2, float t) {
  MaterialRec d = m;
  d.kind = MAT_DIFFUSE;
  d.tint = mix(m.tint, color2, clamp(t, 0.0, 1.0));
  return d;
}

// Integer lattice hash to [0, 1)^3 (PCG-based), for cell features and gradients.
vec3 hash33(ivec3 c) {
  uint h = pcg_hash(uint(c.x) + pcg_hash(uint(c.y) + pcg_hash(uint(c.z))));
  uint h2 = pcg_hash(h);
  uint h3 = pcg_hash(h2);
  return vec3(float(h >> 8), float(h2 >> 8), float(h3 >> 8)) * (1.0 / 16777216.0);
}
