// FormulaPowTexture: <FormulaPowTexture color1=".." color2=".." scale="s"/>: the seed's
// "barcode" stripes, |sin(x/s + sin(z/(2s)))|^8: thin lines of color1 on color2.
#include "texture_common.glsl"
bool delta_formula_pow_texture(MaterialRec m) { return false; }
vec3 albedo_formula_pow_texture(MaterialRec m) { return m.tint; }
vec3 eval_formula_pow_texture(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) { pdf = 0.0; return vec3(0.0); }
bool sample_formula_pow_texture(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) { return false; }
float formula_pow_pattern(vec3 p, float scale) {
  return 1.0 - pow(abs(sin(p.x / scale + sin(p.z / (2.0 * scale)))), 8.0);
}
void resolve_hit_formula_pow_texture(inout Surface sf, Ray r, Hit h) {
  FormulaPowTextureRec q = formula_pow_texture_rec(sf.m);
  sf.m = textured_diffuse(sf.m, q.color2, formula_pow_pattern(h.p, q.scale));
}
