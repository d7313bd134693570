// Textured: <Textured diffuse="wood.png" specular="wood_spec.png" normal="wood_n.png" n="50"
// uvScale="su sv" uvOffset="ou ov"/>: the seed's image-mapped material (its "Texturado":
// normal mapping and specular light from three textures: diffuse, specular, normal).
// At a surface point with texture coordinates uv' = uv * uvScale + uvOffset (the texture
// repeats with period 1 in uv'), with rho = tint * diffuse(uv') (white without a map)
// and s = specular(uv') (zero without a map), both linear RGB in [0, 1]:
//     f = (1 - s) rho / pi  +  s (n + 2) / (2 pi) cos^n(alpha)
// a Lambert lobe and the normalised modified Phong lobe of PhongSpecular (alpha: angle
// between wi and the mirror direction of wo), mixed per channel with weights 1 - s and
// s: each lobe's albedo is <= 1, so the mixture's is too (energy-conserving); at normal
// incidence the Phong lobe's albedo is exactly 1 and a white diffuse map gives albedo 1
// for any s. Both lobes live in the shading frame of the normal map (resolve_textured).
// Sampling picks a lobe with probability proportional to its summed weights (one-sample
// MIS with the mixture density, as pbrt's BSDF does).
// The image maps are layers of one texture array (render/image_maps.h); the record keeps
// their layer numbers. resolve_hit_textured (textured_resolve.glsl) replaces the record by
// its values at the hit: tint = (1 - s) rho and the hit field spec = s; the functions
// below read that.
#include "image_maps.glsl"

// Bilinear, wrap = repeat (the texture's own state); fract keeps the coordinates small
// where the hardware's sub-texel precision is (uv of a plane grows with distance).
vec3 map_lookup(int layer, vec2 uv) { return textureLod(u_maps, vec3(fract(uv), float(layer)), 0.0).rgb; }

bool delta_textured(MaterialRec m) { return false; }
// The albedo a mode shows (sh_irradiance.glsl): both lobes' weights, (1 - s) rho + s (the
// Phong lobe's albedo is 1 at normal incidence).
vec3 albedo_textured(MaterialRec m) { return m.tint + textured_rec(m).spec; }

// The Phong lobe of weight s as a PhongSpecular record.
MaterialRec textured_phong(MaterialRec m) {
  TexturedRec q = textured_rec(m);
  MaterialRec sm = m;
  sm.kind = MAT_PHONG_SPECULAR;
  sm.tint = q.spec;
  return with_phong_specular_rec(sm, PhongSpecularRec(q.exponent));
}

float textured_specular_probability(MaterialRec m) {
  vec3 spec = textured_rec(m).spec;
  float d = m.tint.r + m.tint.g + m.tint.b, sp = spec.r + spec.g + spec.b;
  return d + sp > 0.0 ? sp / (d + sp) : 0.0;
}

vec3 eval_textured(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  if (wi.z <= 0.0 || wo.z <= 0.0) return vec3(0.0);
  float ps = textured_specular_probability(m);
  float pd;
  vec3 f = eval_diffuse(m, wo, wi, entering, pd);
  pdf = (1.0 - ps) * pd;
  if (ps > 0.0) {
    float pp;
    f += eval_phong_specular(textured_phong(m), wo, wi, entering, pp);
    pdf += ps * pp;
  }
  return f;
}

bool sample_textured(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) {
  if (wo.z <= 0.0 || max3(m.tint) + max3(textured_rec(m).spec) <= 0.0) return false;
  BsdfSample lobe;
  bool ok = u.z < textured_specular_probability(m) ? sample_phong_specular(textured_phong(m), wo, entering, u, lobe)
                                                   : sample_diffuse(m, wo, entering, u, lobe);
  if (!ok) return false;
  s.wi = lobe.wi;
  s.delta = false;
  vec3 f = eval_textured(m, wo, s.wi, entering, s.pdf);
  s.weight = s.pdf > 0.0 ? f / s.pdf : vec3(0.0);
  return s.pdf > 0.0;
}
