// Emit: <Emit><Absorb intensity="I" color="r g b"/></Emit>: emits radiance I * color
// from its front side and absorbs everything (the path ends there). The integrator adds
// the emission; as a BSDF it scatters nothing.
bool delta_emit(MaterialRec m) { return true; }
vec3 albedo_emit(MaterialRec m) { return vec3(0.0); }  // absorbs everything

vec3 eval_emit(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  return vec3(0.0);
}

bool sample_emit(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) {
  s.pdf = 0.0;
  s.delta = true;
  s.weight = vec3(0.0);
  s.wi = vec3(0.0, 0.0, 1.0);
  return false;
}
