// RoughDielectric: <RoughDielectric ior="n" roughness="r" color="r g b"
// attenuationColor="r g b" attenuationDistance="d"/>: frosted glass in air, a GGX
// microfacet dielectric that reflects and refracts (Walter et al. 2007, "Microfacet Models
// for Refraction through Rough Surfaces"; pbrt-v4 9.7, DielectricBxDF), alpha = roughness^2
// as glTF's (at least 1e-3: roughness below 0.0316 acts as 0.0316; SmoothDielectric is the
// exact smooth one). Exact Fresnel F(wo.h) on each microfacet, height-correlated Smith G2:
//     reflection   f_r = D G2 F / (4 |n.o| |n.i|),         h = normalize(wo + wi)
//     refraction   f_t = D G2 (1 - F) |wi.h| |wo.h| / (|n.o| |n.i| (wi.h + wo.h / eta)^2) / eta^2,
//                  h = normalize(wo + eta wi) (eta = n_inside / n_outside seen from the side
//                  wo is on; / eta^2: radiance, pbrt-v4 9.5.2), tinted by `color`.
// Sampling: a visible normal (Heitz 2018), then reflection with probability F, else
// refraction; the density is that mixture's. Single scattering: a rough one loses what
// scatters more than once between microfacets (no furnace of 1). Inside, an absorbing medium
// (materials/medium.h). The glTF loader uses it for KHR_materials_volume materials that are
// rough (scene/xml_meshes.cpp). rough_dielectric.glsl has the code.
#pragma once
#include "materials/material.h"
#include "materials/medium.h"

namespace pt {

struct RoughDielectric {
  static constexpr const char* kXml = "RoughDielectric";
  // An example (tests loop over every kind's; albedo <= 1; files relative to assets/textures).
  static constexpr const char* kExample = "<RoughDielectric ior=\"1.5\" roughness=\"0.5\"/>";
  static constexpr bool kMedium = true;
  float ior = 1.5f;  // inside; outside is air (1)
  float roughness = 0.3f;
  glm::vec3 color{1.0f};
  glm::vec3 sigma{0.0f};  // the medium's absorption per unit length

#define PT_ROUGH_DIELECTRIC_FIELDS(F) F(float, eta_inner) F(float, alpha) F(vec3, sigma)
  PT_KIND_RECORD(PT_ROUGH_DIELECTRIC_FIELDS, PT_NO_FIELDS)

  unsigned features() const { return medium_features(sigma); }

  void parse(MaterialParse& p) {
    XmlAttrs& a = p.attrs;
    ior = parse_ior(a, "ior", 1.5f);
    roughness = a.number("roughness", 0.3f);
    if (!(roughness >= 0.0f && roughness <= 1.0f)) a.fail("'roughness' must be in [0, 1]");
    color = a.vec3("color", glm::vec3(1.0f));
    sigma = parse_medium(a);
  }
  void pack(MaterialWriter& w) const {
    w.tint *= color;
    w.set(rec::eta_inner, ior);
    w.set(rec::alpha, std::max(1e-3f, roughness * roughness));
    w.set(rec::sigma, sigma);
  }
  template <class E>
  bool edit(E& e, MaterialCommon&) {
    return any_changed({e.color("colour", color), e.slider("roughness", roughness, 0.0f, 1.0f), e.slider("ior", ior, 1.0f, 3.0f)});
  }
};

}  // namespace pt
