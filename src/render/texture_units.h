// The texture units of the integrator and display programs, one list: the accumulator's
// three inputs (mean, statistics, variance), the scene's record textures, its environment and image maps.
#pragma once

namespace pt {

enum TextureUnit {
  kAccumUnit = 0, kShapeUnit = 1, kMaterialUnit = 2, kLightUnit = 3, kStatsUnit = 4, kEnvUnit = 5, kEnvCdfUnit = 6,
  kNodeUnit = 7, kPrimUnit = 8, kVertexUnit = 9, kMapsUnit = 10, kUvUnit = 11,
  kVarianceUnit = 12, kNumTextureUnits = 13
};

}  // namespace pt
