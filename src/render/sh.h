// Order-2 spherical harmonics of the environment, for the irradiance render mode
// (Ramamoorthi and Hanrahan, "An Efficient Representation for Irradiance Environment
// Maps", SIGGRAPH 2001). The 9 coefficients L_lm = integral of L(w) Y_lm(w) over the
// sphere are computed on the CPU from whichever environment the scene has; the shader
// (shaders/sh.glsl) evaluates E(n) = sum_lm A_l L_lm Y_lm(n) with the clamped-cosine
// convolution factors A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4.
//
// Basis (real SH in world axes, the order of R&H's equations): 0: Y00; 1: Y1-1 ~ y;
// 2: Y10 ~ z; 3: Y11 ~ x; 4: Y2-2 ~ xy; 5: Y2-1 ~ yz; 6: Y20 ~ 3z^2 - 1; 7: Y21 ~ xz;
// 8: Y22 ~ x^2 - y^2. Irradiance does not depend on which axis is the SH pole.
#pragma once
#include <array>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace pt {

using ShCoeffs = std::array<glm::vec3, 9>;

inline constexpr float kShA[3] = {3.14159265f, 2.09439510f, 0.78539816f};  // A_0, A_1, A_2

// Y_lm(d) for unit d, in the order above.
std::array<float, 9> sh_basis(glm::vec3 d);
// The band (l) of coefficient i.
inline int sh_band(int i) { return i == 0 ? 0 : i < 4 ? 1 : 2; }

// Projection of the environment the shader sees: the map as a piecewise-constant function
// (each texel's exact integral of Y_lm over its solid angle, in closed form, so a
// constant map gives exactly 4 pi L Y00), with rotation and intensity applied; or the
// constant colour.
ShCoeffs project_sh(const Environment& env);

// E(n) from the coefficients (the CPU twin of sh_irradiance in shaders/sh.glsl).
glm::vec3 sh_irradiance(const ShCoeffs& c, glm::vec3 n);

}  // namespace pt
