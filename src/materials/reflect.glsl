// Reflect: <Reflect color="r g b"/>: a perfect mirror (the seed's "Reflectivo"), a delta
// lobe of weight tint (1 unless coloured or wrapped in <Attenuate>).
bool delta_reflect(MaterialRec m) { return true; }
vec3 albedo_reflect(MaterialRec m) { return m.tint; }

vec3 eval_reflect(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {
  pdf = 0.0;
  return vec3(0.0);
}

bool sample_reflect(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) {
  s.wi = vec3(-wo.x, -wo.y, wo.z);
  s.weight = m.tint;
  s.pdf = 0.0;
  s.delta = true;
  return wo.z > 0.0;
}
