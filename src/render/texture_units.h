// The texture units of the integrator and display programs, one list: the accumulator's
// three inputs (mean, statistics, variance), the scene's record textures, its environment and image maps.
#pragma once

namespace pt {

enum TextureUnit {
  kAccumUnit = 0, kShapeUnit = 1, kMaterialUnit = 2, kLightUnit = 3, kStatsUnit = 4, kEnvUnit = 5, kEnvCdfUnit = 6,
  kNodeUnit = 7, kPrimUnit = 8, kVertexUnit = 9, kMapsUnit = 10, kUvUnit = 11, kTexinfoUnit = 12,
  kVarianceUnit = 13, kNumTextureUnits = 14  // WebGL 2 guarantees 16 in a fragment shader
};

}  // namespace pt
