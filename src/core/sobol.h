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
std::string glsl_sobol_table();

}  // namespace pt
