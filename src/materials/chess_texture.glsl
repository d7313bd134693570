// ChessTexture: <ChessTexture color1=".." color2=".." scale="s"/>: 3D cells of size s,
// alternating color1 and color2 (the seed's "cubos" of two colours).
#include "texture_common.glsl"
bool delta_chess_texture(MaterialRec m) { return false; }
vec3 albedo_chess_texture(MaterialRec m) { return m.tint; }
vec3 eval_chess_texture(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) { pdf = 0.0; return vec3(0.0); }
bool sample_chess_texture(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) { return false; }
float chess_pattern(vec3 p, float scale) {
  ivec3 c = ivec3(floor(p / scale));
  return float((c.x + c.y + c.z) & 1);
}
void resolve_hit_chess_texture(inout Surface sf, Ray r, Hit h) {
  ChessTextureRec q = chess_texture_rec(sf.m);
  sf.m = textured_diffuse(sf.m, q.color2, chess_pattern(h.p, q.scale));
}
