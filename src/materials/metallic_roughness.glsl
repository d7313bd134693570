// MetallicRoughness: the glTF 2.0 metallic-roughness BSDF (Appendix B; the model and the
// XML: metallic_roughness.h) with its extension lobes (materials/gltf_lobes.h). With
// s5 = (1 - v.h)^5, the dielectric's F_d = F0 + (1 - F0) s5 (F0 a colour under
// KHR_materials_specular, weight w = specular) and the metal's F_m = tint + (1 - tint) s5:
//     f_base = (1 - metallic) [(1 - w max(F_d)) tint / pi + w F_d f_s] + metallic F_m f_s,
//     f_s = D G2 / (4 |n.l| |n.v|)   (GGX, height-correlated Smith: ggx.glsl)
// then the sheen over it (gltf_sheen.glsl) and the clearcoat over that (gltf_clearcoat.glsl),
// each compiled in only when a material of the scene uses it (HAS_GLTF_*).
// Sampling picks the clearcoat with probability p_c (its Fresnel-weighted share at wo,
// clamped to [0.1, 0.9]), else the base's specular lobe (GGX visible normals, Heitz 2018)
// with probability p_s from the lobes' Fresnel-weighted albedos at wo (clamped to
// [0.1, 0.9] when both carry light), else the cosine-weighted hemisphere (the diffuse and
// sheen lobes); the pdf is the mixture's (one-sample MIS, as pbrt's BSDFs do). Below
// roughness 0.03 a specular lobe is a mirror chosen with its probability, weight F / p;
// the material is a delta one only when every lobe it has is.
// With KHR_materials_volume (HAS_GLTF_VOLUME; the hit field volume = the volume's index of
// refraction) the transmission is not a thin wall: that share of the dielectric, (1 -
// metallic) transmission, is the GGX microfacet dielectric of Walter et al. 2007 (the
// exact Fresnel of eta = ior entering, 1 / ior leaving, reflecting and refracting:
// ggx_dielectric.glsl; below roughness 0.03 the smooth one), tinted by the base colour at
// each refraction, and the layer over a diffuse base keeps the rest, (1 - transmission):
//     f = metallic f_metal + (1 - metallic) [(1 - transmission) f_layer + transmission f_walter]
// It is the same from both sides (the path inside sees the diffuse and metal shares
// reflect inwards), sampled as the transmission's lobe; the medium inside is GltfPbr's
// (gltf_pbr.glsl medium_gltf_pbr). Blender's Principled BSDF mixes its glass lobe the same way.
// With HAS_GLTF_MS (the default; materials/gltf_ms.glsl) the GGX lobes' multiple scattering
// is compensated (Kulla and Conty 2017): the metal gains F_ms (1 - E(n.v)) (1 - E(n.l)) /
// (pi (1 - E_avg)) and the dielectric's base is weighted by (1 - E_s(n.v)) (1 - E_s(n.l)) /
// (1 - E_s,avg) instead of (1 - w max(F_d)), both reciprocal and cosine-sampled with the
// diffuse lobe; without it, the specification's single-scattering model above.
#include "ggx.glsl"

// Two unit numbers of one slot (materials/gltf_lobes.h gltf_pack2: 12 bits each).
vec2 gltf_unpack2(float v) {
  float hi = floor(v * (1.0 / 4096.0));
  return vec2(v - hi * 4096.0, hi) * (1.0 / 4095.0);
}
float gltf_pack2(vec2 a) {
  vec2 q = floor(clamp(a, 0.0, 1.0) * 4095.0 + 0.5);
  return q.x + 4096.0 * q.y;
}

// The record's lobes, decoded; the lobes a program lacks are absent (zero).
struct MrLobes {
  float metallic;
  float roughness;
  vec3 f0;         // the dielectric's F0 (colour)
  float specular;  // its weight
  float coat;
  float coat_roughness;
  vec3 coat_n;     // the coat's normal in the shading frame
  vec3 sheen;
  float sheen_roughness;
  float transmission;  // KHR_materials_transmission
  float volume;        // KHR_materials_volume's index of refraction; 0: thin-walled
#ifdef HAS_GLTF_MS
  vec2 ms_eo;    // (E, E2) of the base's GGX lobe at wo (mr_lobes_at)
  vec2 ms_eavg;  // their averages
#endif
};

MrLobes mr_lobes(MaterialRec m) {
  MetallicRoughnessRec q = metallic_roughness_rec(m);
  MrLobes l;
  l.metallic = q.metallic;
  l.roughness = q.roughness;
#ifdef HAS_GLTF_SPECULAR
  l.f0 = q.f0;
  l.specular = q.specular;
#else
  l.f0 = vec3(q.f0.x);
  l.specular = 1.0;
#endif
  l.coat = 0.0;
  l.coat_roughness = 0.0;
  l.coat_n = vec3(0.0, 0.0, 1.0);
#ifdef HAS_GLTF_CLEARCOAT
  vec2 c = gltf_unpack2(q.coat);
  l.coat = c.x;
  l.coat_roughness = c.y;
  if (q.coat_normal > 0.0) {  // packed (x, y) + 1 on 2047 steps per unit (gltf_pbr_resolve.glsl)
    vec2 xy = gltf_unpack2(q.coat_normal - 1.0) * (4095.0 / 2047.0) - 1.0;
    l.coat_n = normalize(vec3(xy, sqrt(max(1e-6, 1.0 - dot(xy, xy)))));
  }
#endif
  l.sheen = vec3(0.0);
  l.sheen_roughness = 1.0;
#ifdef HAS_GLTF_SHEEN
  vec2 rg = gltf_unpack2(q.sheen_rg), br = gltf_unpack2(q.sheen_br);
  l.sheen = vec3(rg, br.x);
  l.sheen_roughness = gltf_sheen_roughness(br.y);
#endif
  l.transmission = 0.0;
  l.volume = 0.0;
#ifdef HAS_GLTF_TRANSMISSION
  l.transmission = q.transmission;
#endif
#ifdef HAS_GLTF_VOLUME
  l.volume = q.volume;
#endif
  return l;
}

#ifdef HAS_GLTF_VOLUME
bool mr_volume(MrLobes l) { return l.volume > 0.0 && l.transmission > 0.0; }
#else
bool mr_volume(MrLobes l) { return false; }
#endif

bool mr_smooth(float roughness) { return roughness < 0.03; }

bool delta_metallic_roughness(MaterialRec m) {
  MrLobes l = mr_lobes(m);
  return mr_smooth(l.roughness) && (l.metallic >= 1.0 || l.transmission >= 1.0) && (l.coat <= 0.0 || mr_smooth(l.coat_roughness)) && max3(l.sheen) <= 0.0;
}
vec3 albedo_metallic_roughness(MaterialRec m) { return m.tint; }

float mr_schlick5(float c) {
  float s = clamp(1.0 - c, 0.0, 1.0), s2 = s * s;
  return s2 * s2 * s;
}

// The base's reflectance at v.h = c: its dielectric layer (weight included) and its metal.
vec3 mr_fresnel_layer(MrLobes l, float c) { return l.specular * (l.f0 + (1.0 - l.f0) * mr_schlick5(c)); }
vec3 mr_fresnel_metal(MaterialRec m, float c) { return m.tint + (1.0 - m.tint) * mr_schlick5(c); }

#ifdef HAS_GLTF_MS
// (E, E2) of the base's GGX lobe at mu and their averages (gltf_ms.glsl); a mirror's exactly:
// E = 1, E2 = (1 - mu)^5, averages 1 and 1/21.
vec2 mr_ms_e(MrLobes l, float mu) { return mr_smooth(l.roughness) ? vec2(1.0, mr_schlick5(mu)) : gltf_ms_e(mu, l.roughness); }
vec2 mr_ms_eavg(MrLobes l) { return mr_smooth(l.roughness) ? vec2(1.0, 1.0 / 21.0) : gltf_ms_eavg(l.roughness); }
// The dielectric layer's albedo specular (f0 E + (1 - f0) E2), f0 = max(F0) (its largest channel's).
float mr_layer_albedo(MrLobes l, vec2 e) {
  float f0 = max3(l.f0);
  return l.specular * (f0 * e.x + (1.0 - f0) * e.y);
}
// The metal's Fresnel colour of the compensation lobe, F_avg^2 E_avg / (1 - F_avg (1 - E_avg)).
vec3 mr_ms_fresnel(MaterialRec m, float eavg) {
  vec3 favg = m.tint + (1.0 - m.tint) * (1.0 / 21.0);
  return favg * favg * eavg / (1.0 - favg * (1.0 - eavg));
}
// (the dielectric base's weight, the metal's compensation lobe without its colour) at wo, wi
// (cosines co, ci): (1 - E_s(co)) (1 - E_s(ci)) / (1 - E_s,avg), (1 - E(co)) (1 - E(ci)) / (pi (1 - E_avg)).
// (The table is a uniform block, gltf_ms.glsl; the lookups at wo are made once per call, in
// mr_lobes_at, and sample_metallic_roughness evaluates the BSDF at one place.)
vec2 mr_ms_weights(MrLobes l, float ci) {
  vec2 eo = l.ms_eo, ei = mr_ms_e(l, ci), ea = l.ms_eavg;
  float so = mr_layer_albedo(l, eo), si = mr_layer_albedo(l, ei), sa = mr_layer_albedo(l, ea);
  float kd = sa < 1.0 - 1e-6 ? (1.0 - so) * (1.0 - si) / (1.0 - sa) : 0.0;
  float km = ea.x < 1.0 - 1e-6 ? (1.0 - eo.x) * (1.0 - ei.x) / (PI * (1.0 - ea.x)) : 0.0;
  return vec2(kd, km);
}
#endif

// The lobes with what the compensation needs at wo.
MrLobes mr_lobes_at(MaterialRec m, vec3 wo) {
  MrLobes l = mr_lobes(m);
#ifdef HAS_GLTF_MS
  l.ms_eo = mr_ms_e(l, wo.z);
  l.ms_eavg = mr_ms_eavg(l);
#endif
  return l;
}

// What the layers over the base leave of it: the coat's (1 - clearcoat F_c(n_c.wo)) and
// the sheen's albedo scaling (its min over wo and wi).
float mr_coat_weight(MrLobes l, vec3 wo) {
#ifdef HAS_GLTF_CLEARCOAT
  return l.coat * gltf_coat_fresnel(dot(l.coat_n, wo));
#else
  return 0.0;
#endif
}
float mr_sheen_scale(MrLobes l, float cos_o, float cos_i) {
#ifdef HAS_GLTF_SHEEN
  float s = max3(l.sheen);
  if (s <= 0.0) return 1.0;
  return max(0.0, 1.0 - s * max(gltf_sheen_albedo(cos_o, l.sheen_roughness), gltf_sheen_albedo(cos_i, l.sheen_roughness)));
#else
  return 1.0;
#endif
}

// The lobe choice at wo: x = p_c (the coat), y = p_s (the base's specular lobe, of what
// the coat leaves), z = p_t (the transmission, of what the specular lobe leaves); the
// rest is the cosine-weighted hemisphere.
vec3 mr_probabilities(MaterialRec m, MrLobes l, vec3 wo) {
  float ws = l.metallic * luminance(mr_fresnel_metal(m, wo.z)) + (1.0 - l.metallic) * max3(mr_fresnel_layer(l, wo.z));
#ifdef HAS_GLTF_MS
  // the base's albedo at wo (1 - E_s(wo)) and the metal's compensation lobe's, F_ms (1 - E(wo))
  vec2 eo = l.ms_eo, ea = l.ms_eavg;
  float wd = (1.0 - l.metallic) * (1.0 - mr_layer_albedo(l, eo)) * luminance(m.tint);
  float wm = l.metallic * (1.0 - eo.x) * luminance(mr_ms_fresnel(m, ea.x));
#else
  float wd = (1.0 - l.metallic) * (1.0 - max3(mr_fresnel_layer(l, wo.z))) * luminance(m.tint);
#endif
  float wc = mr_coat_weight(l, wo), wt = 0.0;
#ifdef HAS_GLTF_TRANSMISSION
  if (mr_volume(l)) {  // the transmission's share is a dielectric of its own: the layer keeps the rest
    ws -= (1.0 - l.metallic) * max3(mr_fresnel_layer(l, wo.z)) * l.transmission;
    wt = (1.0 - l.metallic) * l.transmission;
    wd *= 1.0 - l.transmission;
  } else {
    wt = wd * l.transmission;
    wd -= wt;
  }
#endif
#ifdef HAS_GLTF_MS
  wd += wm;  // cosine-sampled with the diffuse lobe
#endif
#ifdef HAS_GLTF_SHEEN
  float e = max3(l.sheen) * gltf_sheen_albedo(wo.z, l.sheen_roughness);
  float keep = max(0.0, 1.0 - e);
  ws *= keep;
  wt *= keep;
  wd = wd * keep + e;
#endif
  // no cosine-sampled or transmitted light: all specular; no specular light: none
  float ps = wd + wt <= 0.0 ? 1.0 : ws <= 0.0 ? 0.0 : clamp(ws / (ws + wd + wt), 0.1, 0.9);
  float pt = wt <= 0.0 ? 0.0 : wd <= 0.0 ? 1.0 : clamp(wt / (wt + wd), 0.1, 0.9);
  float pc = l.coat <= 0.0 ? 0.0 : clamp(wc / (wc + (1.0 - wc) * (ws + wd + wt)), 0.1, 0.9);
  return vec3(pc, ps, pt);
}

// The smooth base lobe's reflectance at incidence cos_o (a mirror: h = n); a volume's
// share of the dielectric reflects in its own lobe.
vec3 mr_mirror_fresnel(MaterialRec m, MrLobes l, float cos_o) {
  return (1.0 - l.metallic) * (mr_volume(l) ? 1.0 - l.transmission : 1.0) * mr_fresnel_layer(l, cos_o) +
         l.metallic * mr_fresnel_metal(m, cos_o);
}

#ifdef HAS_GLTF_VOLUME
// The volume's lobe (f |n.i| and its density within the lobe; wi on either side) for a
// rough surface: (1 - metallic) transmission f_walter, before what the layers over it
// leave. Zero for a smooth one (a delta lobe: sample_metallic_roughness).
float mr_volume_eta(MrLobes l, bool entering) { return entering ? l.volume : 1.0 / l.volume; }
vec3 mr_eval_volume(MaterialRec m, MrLobes l, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  if (mr_smooth(l.roughness)) return vec3(0.0);
  float alpha = l.roughness * l.roughness;
  return ggx_dielectric_eval(alpha, mr_volume_eta(l, entering), m.tint, wo, wi, pdf) * ((1.0 - l.metallic) * l.transmission);
}
#endif

#ifdef HAS_GLTF_TRANSMISSION
// The thin-walled transmission (wi below the surface): the GGX lobe of wi mirrored through
// the surface, wr = (wi.x, wi.y, -wi.z), tinted by the base colour and weighted by what the
// layers over it leave: (1 - metallic) transmission (1 - specular max(F(v.h))) tint D G2 / (4 n.v).
// With a volume, its refraction instead (mr_eval_volume).
vec3 mr_eval_transmission(MaterialRec m, MrLobes l, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  if (l.transmission <= 0.0 || mr_smooth(l.roughness)) return vec3(0.0);
  vec3 p = mr_probabilities(m, l, wo);
#ifdef HAS_GLTF_VOLUME
  if (mr_volume(l)) {
    vec3 f = mr_eval_volume(m, l, wo, wi, entering, pdf) * (mr_sheen_scale(l, wo.z, -wi.z) * (1.0 - mr_coat_weight(l, wo)));
    pdf *= (1.0 - p.x) * (1.0 - p.y) * p.z;
    return f;
  }
#endif
  vec3 wr = vec3(wi.xy, -wi.z);
  vec3 h = normalize(wo + wr);
  float alpha = l.roughness * l.roughness, a2 = alpha * alpha;
  vec3 f = (1.0 - l.metallic) * l.transmission * (1.0 - max3(mr_fresnel_layer(l, dot(wo, h)))) * m.tint *
           (ggx_d(h.z, a2) * ggx_g2(wo.z, wr.z, a2) / (4.0 * wo.z));
  f *= mr_sheen_scale(l, wo.z, wr.z) * (1.0 - mr_coat_weight(l, wo));
  pdf = (1.0 - p.x) * (1.0 - p.y) * p.z * pdf_ggx_vndf(wo, h, a2);
  return f;
}
#endif

vec3 eval_metallic_roughness(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  if (wo.z <= 0.0) return vec3(0.0);
  MrLobes l = mr_lobes_at(m, wo);
#ifdef HAS_GLTF_TRANSMISSION
  if (wi.z < 0.0) return mr_eval_transmission(m, l, wo, wi, entering, pdf);
#endif
  if (wi.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(wo + wi);
  float vh = dot(wo, h);
  vec3 fd = mr_fresnel_layer(l, vh);
  vec3 p = mr_probabilities(m, l, wo);
#ifdef HAS_GLTF_MS
  vec2 k = mr_ms_weights(l, wi.z);
  vec3 f = (1.0 - l.metallic) * k.x * m.tint * (INV_PI * wi.z);
#else
  vec3 f = (1.0 - l.metallic) * (1.0 - max3(fd)) * m.tint * (INV_PI * wi.z);
#endif
  float pdf_base = (1.0 - p.y) * pdf_cosine_hemisphere(wi);
#ifdef HAS_GLTF_TRANSMISSION
  f *= 1.0 - l.transmission;
  pdf_base *= 1.0 - p.z;
#endif
#ifdef HAS_GLTF_MS
  f += l.metallic * k.y * mr_ms_fresnel(m, l.ms_eavg.x) * wi.z;  // the metal's multiple scattering
#endif
  if (!mr_smooth(l.roughness)) {
    float alpha = l.roughness * l.roughness, a2 = alpha * alpha;
    vec3 fresnel = (1.0 - l.metallic) * fd * (mr_volume(l) ? 1.0 - l.transmission : 1.0) + l.metallic * mr_fresnel_metal(m, vh);
    f += fresnel * (ggx_d(h.z, a2) * ggx_g2(wo.z, wi.z, a2) / (4.0 * wo.z));  // f_s |n.l|
    pdf_base += p.y * pdf_ggx_vndf(wo, h, a2);
  }
#ifdef HAS_GLTF_VOLUME
  if (mr_volume(l)) {  // the volume's reflection (the layers over it scale f below)
    float pdf_v;
    f += mr_eval_volume(m, l, wo, wi, entering, pdf_v);
    pdf_base += (1.0 - p.y) * p.z * pdf_v;
  }
#endif
#ifdef HAS_GLTF_SHEEN
  f = f * mr_sheen_scale(l, wo.z, wi.z) + l.sheen * gltf_sheen_eval(l.sheen_roughness, wo, wi);
#endif
  pdf = (1.0 - p.x) * pdf_base;
#ifdef HAS_GLTF_CLEARCOAT
  if (l.coat > 0.0) {
    float wc = mr_coat_weight(l, wo);
    f *= 1.0 - wc;
    if (!mr_smooth(l.coat_roughness)) {
      float pdf_c;
      f += vec3(wc * gltf_coat_eval(l.coat_n, l.coat_roughness * l.coat_roughness, wo, wi, pdf_c));
      pdf += p.x * pdf_c;
    }
  }
#endif
  return f;
}

bool sample_metallic_roughness(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) {
  if (wo.z <= 0.0) return false;
  MrLobes l = mr_lobes_at(m, wo);
  vec3 p = mr_probabilities(m, l, wo);
  float uz = u.z;
  s.delta = false;
  bool chosen = false;  // s.wi is the coat's: evaluate it (below, the one call of eval: each inlined copy costs compile time)
#ifdef HAS_GLTF_CLEARCOAT
  if (uz < p.x) {
    bool smooth_coat = mr_smooth(l.coat_roughness);
    s.wi = gltf_coat_sample(l.coat_n, l.coat_roughness * l.coat_roughness, wo, u.xy, smooth_coat);
    if (s.wi.z <= 0.0 || dot(l.coat_n, s.wi) <= 0.0) return false;  // below the surface or the coat
    if (smooth_coat) {
      s.weight = vec3(mr_coat_weight(l, wo) / p.x);
      s.pdf = 0.0;
      s.delta = true;
      return true;
    }
    chosen = true;
  }
  uz = (uz - p.x) / (1.0 - p.x);
#endif
  if (!chosen) {
    bool specular = uz < p.y;
    if (specular && mr_smooth(l.roughness)) {
      s.wi = vec3(-wo.x, -wo.y, wo.z);
      s.weight = mr_mirror_fresnel(m, l, wo.z) / p.y;
#if defined(HAS_GLTF_CLEARCOAT) || defined(HAS_GLTF_SHEEN)
      s.weight *= (1.0 - mr_coat_weight(l, wo)) * mr_sheen_scale(l, wo.z, wo.z) / (1.0 - p.x);
#endif
      s.pdf = 0.0;
      s.delta = true;
      return true;
    }
    bool transmitted = false;
#ifdef HAS_GLTF_TRANSMISSION
    float ut = (uz - p.y) / (1.0 - p.y);
    if (!specular && ut < p.z) {  // the transmission
#ifdef HAS_GLTF_VOLUME
      if (mr_volume(l)) {  // into (or out of) the volume: the dielectric's lobe
        float eta = mr_volume_eta(l, entering), uf = ut / p.z;
        if (mr_smooth(l.roughness)) {  // the smooth interface (smooth_interface.glsl, as SmoothDielectric)
          float scale = (1.0 - l.metallic) * l.transmission * (1.0 - mr_coat_weight(l, wo)) / ((1.0 - p.x) * (1.0 - p.y) * p.z);
          bool refracted = sample_smooth_interface(wo, eta, uf, s.wi);
          float w = scale * mr_sheen_scale(l, wo.z, abs(s.wi.z));
          s.weight = refracted ? m.tint * (w / (eta * eta)) : vec3(w);
          s.pdf = 0.0;
          s.delta = true;
          return true;
        }
        if (!ggx_dielectric_sample(l.roughness * l.roughness, eta, wo, u.xy, uf, s.wi)) return false;
        transmitted = true;  // (either side: evaluated below)
      }
#endif
      if (!transmitted) {  // thin-walled
        if (mr_smooth(l.roughness)) {  // straight through
          s.wi = -wo;
          s.weight = (1.0 - l.metallic) * l.transmission * (1.0 - max3(mr_fresnel_layer(l, wo.z))) * m.tint *
                     ((1.0 - mr_coat_weight(l, wo)) * mr_sheen_scale(l, wo.z, wo.z) / ((1.0 - p.x) * (1.0 - p.y) * p.z));
          s.pdf = 0.0;
          s.delta = true;
          return true;
        }
        vec3 wr = reflect(-wo, sample_ggx_vndf(wo, l.roughness * l.roughness, u.xy));
        if (wr.z <= 0.0) return false;
        s.wi = vec3(wr.xy, -wr.z);
        transmitted = true;
      }
    }
#endif
    if (!transmitted) {
      s.wi = specular ? reflect(-wo, sample_ggx_vndf(wo, l.roughness * l.roughness, u.xy)) : sample_cosine_hemisphere(u.xy);
#ifdef HAS_GLTF_TRANSMISSION
      if (s.wi.z <= 0.0) return false;  // a reflection below the horizon (not the transmission's)
#endif
    }
  }
  vec3 f = eval_metallic_roughness(m, wo, s.wi, entering, s.pdf);
  s.weight = s.pdf > 0.0 ? f / s.pdf : vec3(0.0);
  return s.pdf > 0.0;
}
