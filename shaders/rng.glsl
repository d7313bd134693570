// rng.glsl: PCG (O'Neill 2014), one 32-bit stream per pixel and sample index.
uint g_rng_state;

uint pcg_hash(uint v) {
  uint s = v * 747796405u + 2891336453u;
  uint w = ((s >> ((s >> 28u) + 4u)) ^ s) * 277803737u;
  return (w >> 22u) ^ w;
}

void rng_init(uvec2 pixel, uint sample_index) {
  g_rng_state = pcg_hash(pixel.x + pcg_hash(pixel.y + pcg_hash(sample_index)));
}

// Uniform in [0, 1): the top 24 bits, exactly representable.
float rand01() {
  g_rng_state = g_rng_state * 747796405u + 2891336453u;
  uint s = g_rng_state;
  uint w = ((s >> ((s >> 28u) + 4u)) ^ s) * 277803737u;
  return float(((w >> 22u) ^ w) >> 8u) * (1.0 / 16777216.0);
}
