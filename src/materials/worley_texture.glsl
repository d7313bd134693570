// WorleyTexture: <WorleyTexture color1=".." color2=".." scale="s"/>: cellular noise
// (Worley 1996) with one feature point per cell of size s; color2 marks the borders
// between cells (where the two nearest features are equally near), color1 the insides.
#include "texture_common.glsl"
bool delta_worley_texture(MaterialRec m) { return false; }
vec3 albedo_worley_texture(MaterialRec m) { return m.tint; }
vec3 eval_worley_texture(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) { pdf = 0.0; return vec3(0.0); }
bool sample_worley_texture(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) { return false; }
float worley_pattern(vec3 p, float scale) {
  vec3 q = p / scale;
  ivec3 base = ivec3(floor(q));
  float f1 = 1e9, f2 = 1e9;
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x) {
        ivec3 c = base + ivec3(x, y, z);
        vec3 d = vec3(c) + hash33(c) - q;
        float dist = dot(d, d);
        if (dist < f1) {
          f2 = f1;
          f1 = dist;
        } else if (dist < f2) {
          f2 = dist;
        }
      }
  return 1.0 - smoothstep(0.0, 0.15, sqrt(f2) - sqrt(f1));  // 1 on borders
}
void resolve_hit_worley_texture(inout Surface sf, Ray r, Hit h) {
  WorleyTextureRec q = worley_texture_rec(sf.m);
  sf.m = textured_diffuse(sf.m, q.color2, worley_pattern(h.p, q.scale));
}
