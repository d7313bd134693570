// Direction numbers of the first four Sobol dimensions (Joe and Kuo's primitive
// polynomials and initial numbers), emitted into the shader as a constant table.
#pragma once
#include <array>
#include <cstdint>
#include <string>

namespace pt {

inline constexpr int kSobolDims = 4;
std::array<uint32_t, kSobolDims * 32> sobol_directions();
// Value of dimension `dim` at `index`, unscrambled, as a 32-bit fixed-point fraction.
uint32_t sobol_sample(uint32_t index, int dim);
// GLSL: uvec3 sobol_dims123(uint index), dimensions 1..3 of point `index` (as sobol_sample),
// the direction numbers written as immediates (shaders/sampler.glsl).
std::string glsl_sobol_dims();

}  // namespace pt
