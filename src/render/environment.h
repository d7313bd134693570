// Importance sampling of an equirectangular environment map: a piecewise-constant 2D
// distribution over (u, v) proportional to luminance * sin(theta) (pbrt-v3, 13.6.5),
// as a marginal CDF over rows and a conditional CDF per row, packed in one texture.
#pragma once
#include <vector>

#include "scene/scene.h"

namespace pt {

struct EnvDistribution {
  int width = 0, height = 0;  // of the map
  // (width + 1) x (height + 1) texels, R channel: rows 0..h-1 hold each row's conditional
  // CDF (width + 1 entries, 0 .. 1); row h holds the marginal CDF over rows (h + 1 entries).
  std::vector<float> cdf_texels;
  // Mean of the sampled function over the unit square: the density of (u, v) in texel
  // (i, j) is f(i, j) / integral. Zero when the map is black.
  float integral = 0.0f;
};

// f(i, j) = luminance of texel (i, j) * sin(theta at the row's centre).
EnvDistribution build_env_distribution(const EnvImage& map);

}  // namespace pt
