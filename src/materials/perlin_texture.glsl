// PerlinTexture: <PerlinTexture color1=".." color2=".." scale="s"/>: gradient noise
// (Perlin 2002, quintic fade) summed over four octaves, mapping 0..1 to color1..color2.
#include "texture_common.glsl"
bool delta_perlin_texture(MaterialRec m) { return false; }
vec3 albedo_perlin_texture(MaterialRec m) { return m.tint; }
vec3 eval_perlin_texture(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) { pdf = 0.0; return vec3(0.0); }
bool sample_perlin_texture(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) { return false; }
float perlin_noise(vec3 q) {
  ivec3 c = ivec3(floor(q));
  vec3 f = q - floor(q);
  vec3 w = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  float n[8];
  for (int i = 0; i < 8; ++i) {
    ivec3 o = ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    vec3 g = normalize(hash33(c + o) * 2.0 - 1.0 + 1e-6);
    n[i] = dot(g, f - vec3(o));
  }
  float x0 = mix(mix(n[0], n[1], w.x), mix(n[2], n[3], w.x), w.y);
  float x1 = mix(mix(n[4], n[5], w.x), mix(n[6], n[7], w.x), w.y);
  return mix(x0, x1, w.z);  // in about [-0.87, 0.87]
}
float perlin_pattern(vec3 p, float scale) {
  float sum = 0.0, amp = 0.5, freq = 1.0;
  for (int o = 0; o < 4; ++o) {
    sum += amp * perlin_noise(p / scale * freq);
    amp *= 0.5;
    freq *= 2.0;
  }
  return 0.5 + sum;
}
void resolve_hit_perlin_texture(inout Surface sf, Ray r, Hit h) {
  PerlinTextureRec q = perlin_texture_rec(sf.m);
  sf.m = textured_diffuse(sf.m, q.color2, perlin_pattern(h.p, q.scale));
}
