// FresnelComposite: <FresnelComposite na=".." nb=".."> reflective, transmissive
// </FresnelComposite>: a mixture of two materials weighted by the exact dielectric
// Fresnel reflectance F of the na|nb interface (nb inside). The surface step resolves it
// before shading: with probability F it shades with the first child, else with the
// second (choose_fresnel_composite, called by the generated resolve_composites), the
// one-sample estimator of the mixture, so the composite itself never scatters. GLSL has
// no recursion; nesting resolves up to kMaxCompositeDepth (4) deep.
#include "fresnel.glsl"

bool delta_fresnel_composite(MaterialRec m) { return true; }
vec3 albedo_fresnel_composite(MaterialRec m) { return m.tint; }

vec3 eval_fresnel_composite(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  return vec3(0.0);
}

bool sample_fresnel_composite(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) { return false; }

// Picks a child with u, rescaled to stay uniform for the next level.
MaterialRec choose_fresnel_composite(MaterialRec m, float cos_o, bool entering, inout float u) {
  FresnelCompositeRec q = fresnel_composite_rec(m);
  float f = fresnel_dielectric(cos_o, entering ? q.eta_inner / q.eta_outer : q.eta_outer / q.eta_inner);
  bool first = u < f;
  u = first ? u / max(f, 1e-30) : (u - f) / max(1.0 - f, 1e-30);
  return load_material(first ? q.child_a : q.child_b);
}
