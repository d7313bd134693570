// sampling.glsl: frames, warps of the unit square and their densities (solid angle).

// Orthonormal basis around unit n (Duff et al. 2017, "Building an orthonormal basis, revisited").
struct Frame { vec3 t; vec3 b; vec3 n; };
Frame frame_from(vec3 n) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float b = n.x * n.y * a;
  return Frame(vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x), vec3(b, s + n.y * n.y * a, -n.y), n);
}
vec3 to_local(Frame f, vec3 v) { return vec3(dot(v, f.t), dot(v, f.b), dot(v, f.n)); }
vec3 from_local(Frame f, vec3 v) { return v.x * f.t + v.y * f.b + v.z * f.n; }

// Cosine-weighted hemisphere (Malley): pdf = cos(theta) / pi.
vec3 sample_cosine_hemisphere(vec2 u) {
  float r = sqrt(u.x);
  float phi = TWO_PI * u.y;
  return vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u.x)));
}
float pdf_cosine_hemisphere(vec3 w) { return max(w.z, 0.0) * INV_PI; }

// Uniform hemisphere: pdf = 1 / (2 pi).
vec3 sample_uniform_hemisphere(vec2 u) {
  float z = u.x;
  float r = sqrt(max(0.0, 1.0 - z * z));
  float phi = TWO_PI * u.y;
  return vec3(r * cos(phi), r * sin(phi), z);
}
float pdf_uniform_hemisphere(vec3 w) { return w.z > 0.0 ? 0.5 * INV_PI : 0.0; }

// Uniform cone around +z given 1 - cos(theta_max), kept as such for precision when the
// cone is tiny (a far light): pdf = 1 / (2 pi (1 - cos theta_max)).
vec3 sample_uniform_cone(vec2 u, float one_minus_cos_max) {
  float omc = u.x * one_minus_cos_max;
  float cos_t = 1.0 - omc;
  float sin_t = sqrt(max(0.0, omc * (2.0 - omc)));
  float phi = TWO_PI * u.y;
  return vec3(sin_t * cos(phi), sin_t * sin(phi), cos_t);
}

// The weight of technique a against b. A density's square overflows float above 1.8e19
// (a small light seen from far: t^2 / (cos A) or 1 / (2 pi (1 - cos)) reaches 1e24), and
// inf / inf is NaN; a tiny one's underflows to 0. There the weight is taken in the form of
// the ratio of the two, which never overflows (otherwise the direct form, so images stay
// the same bit for bit).
float power_heuristic(float pdf_a, float pdf_b) {
  float a = pdf_a * pdf_a;
  float b = pdf_b * pdf_b;
  if (max(pdf_a, pdf_b) > 1e18 || (pdf_a > 0.0 && !(a + b > 0.0))) {
    if (!(pdf_a > 0.0)) return 0.0;
    if (isinf(pdf_a)) return isinf(pdf_b) ? 0.5 : 1.0;
    if (pdf_a >= pdf_b) {
      float r = pdf_b / pdf_a;
      return 1.0 / (1.0 + r * r);
    }
    float r = pdf_a / pdf_b;
    return r * r / (1.0 + r * r);
  }
  return a + b > 0.0 ? a / (a + b) : 0.0;
}
