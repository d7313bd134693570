// Transmit: <Transmit outerIor="n1" innerIor="n2"/>: the seed's pure refraction, with no
// Fresnel reflection (a non-physical but energy-preserving idealisation). Where Snell's
// law has no solution (total internal reflection) the ray reflects.
#include "refract.glsl"

bool delta_transmit(MaterialRec m) { return true; }
vec3 albedo_transmit(MaterialRec m) { return m.tint; }

vec3 eval_transmit(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  return vec3(0.0);
}

bool sample_transmit(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) {
  TransmitRec q = transmit_rec(m);
  float eta = entering ? q.eta_inner / q.eta_outer : q.eta_outer / q.eta_inner;
  s.pdf = 0.0;
  s.delta = true;
  vec3 wt;
  if (refract_local(wo, eta, wt)) {
    s.wi = wt;
    s.weight = m.tint / (eta * eta);
  } else {
    s.wi = vec3(-wo.x, -wo.y, wo.z);
    s.weight = m.tint;
  }
  return true;
}
