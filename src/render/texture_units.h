// The texture units of the integrator and display programs, one list: the accumulator's
// two inputs (mean, statistics; the variance in their free channels), the denoiser's
// auxiliaries (albedo and depth, normal: with the first-hit auxiliaries on), adaptive sampling's tile counts, the scene's record textures, its environment and image maps.
#pragma once

namespace pt {

enum TextureUnit {
  kAccumUnit = 0, kShapeUnit = 1, kMaterialUnit = 2, kLightUnit = 3, kStatsUnit = 4, kEnvUnit = 5, kEnvCdfUnit = 6,
  kNodeUnit = 7, kPrimUnit = 8, kVertexUnit = 9, kMapsUnit = 10, kUvUnit = 11, kTexinfoUnit = 12,
  kAux0Unit = 13, kAux1Unit = 14, kTileCountsUnit = 15,  // adaptive sampling's per-tile counts
  kNumTextureUnits = 16  // WebGL 2 guarantees 16 in a fragment shader
};

}  // namespace pt
