// sampler.glsl: the random numbers a path consumes, 4 dimensions at a time.
//   u_sampler = 0: independent uniform numbers (PCG), per pixel and sample index.
//   u_sampler = k > 0: the first k blocks are Owen-scrambled Sobol points (Burley, "Practical Hash-based Owen
//     Scrambling", JCGT 2020): each 4D block of a path (camera, then two per bounce)
//     draws point `index` of a 4D Sobol sequence whose order is shuffled and whose
//     values are nested-uniform scrambled with seeds hashed from the pixel and the block,
//     so pixels and blocks are decorrelated while each stays a (0,m,4)-style net.
//   Later blocks are independent: low-discrepancy sampling pays off in the first
//   dimensions (pixel area, direct light at the first hit) and costs 32-step Sobol
//   evaluations per block; docs/benchmarks.md measures k = 3 against all blocks.
// All are exact: the estimate is the same in expectation, only its error differs.
uniform int u_sampler;

uint g_index;
uint g_pixel_seed;
uint g_block;

void sampler_init(uvec2 pixel, uint index) {
  rng_init(pixel, index);
  g_index = index;
  g_pixel_seed = pcg_hash(pixel.x + pcg_hash(pixel.y + 0x68bc21ebu));
  g_block = 0u;
}

uint reverse_bits(uint x) {
  x = ((x >> 1u) & 0x55555555u) | ((x & 0x55555555u) << 1u);
  x = ((x >> 2u) & 0x33333333u) | ((x & 0x33333333u) << 2u);
  x = ((x >> 4u) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4u);
  x = ((x >> 8u) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8u);
  return (x >> 16u) | (x << 16u);
}

// Laine-Karras style permutation with Vegdahl's constants: a hash in which every bit
// depends only on the bits below it, so (on reversed bits) it is an Owen scramble.
uint laine_karras(uint x, uint seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

uint nested_uniform_scramble(uint x, uint seed) { return reverse_bits(laine_karras(reverse_bits(x), seed)); }

// Point `index` of the 4D Sobol sequence: dimension 0 is van der Corput (the bits
// reversed); 1..3 are sobol_dims123, generated (core/sobol.cpp glsl_sobol_dims) as 32
// branch-free steps with the direction numbers as immediates (the scrambled index has all
// 32 bits set at random: an early exit saves nothing). tests/sobol_test.cpp: equal to
// sobol_sample.
uvec4 sobol4(uint index) { return uvec4(reverse_bits(index), sobol_dims123(index)); }

vec4 owen_sobol4(uint index, uint seed) {
  uint i = nested_uniform_scramble(index, seed);
  uvec4 v = sobol4(i);
  v = uvec4(nested_uniform_scramble(v.x, pcg_hash(seed ^ 0xa511e9b3u)), nested_uniform_scramble(v.y, pcg_hash(seed ^ 0x63d83595u)),
            nested_uniform_scramble(v.z, pcg_hash(seed ^ 0x7feb352du)), nested_uniform_scramble(v.w, pcg_hash(seed ^ 0x846ca68bu)));
  return vec4(v >> 8u) * (1.0 / 16777216.0);
}

vec4 next4() {
  uint b = g_block++;
  if (b >= uint(u_sampler)) return vec4(rand01(), rand01(), rand01(), rand01());
  return owen_sobol4(g_index, pcg_hash(g_pixel_seed ^ (b * 0x9e3779b9u + 0x632be5abu)));
}
