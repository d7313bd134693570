// FormulaTexture: <FormulaTexture color1=".." color2=".." scale="s"/>: the seed's texture
// "from an equation": 0.5 + 0.5 sin(x/s) sin(y/s) sin(z/s), a smooth 3D egg-crate.
#include "texture_common.glsl"
bool delta_formula_texture(MaterialRec m) { return false; }
vec3 albedo_formula_texture(MaterialRec m) { return m.tint; }
vec3 eval_formula_texture(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) { pdf = 0.0; return vec3(0.0); }
bool sample_formula_texture(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) { return false; }
float formula_pattern(vec3 p, float scale) {
  vec3 q = p / scale;
  return 0.5 + 0.5 * sin(q.x) * sin(q.y) * sin(q.z);
}
void resolve_hit_formula_texture(inout Surface sf, Ray r, Hit h) {
  FormulaTextureRec q = formula_texture_rec(sf.m);
  sf.m = textured_diffuse(sf.m, q.color2, formula_pattern(h.p, q.scale));
}
