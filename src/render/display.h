// The display pass: the running mean, tone-mapped with its exposure, into the bound draw
// framebuffer. One small program per tone map, built on first use (a uniform switch
// over the maps made SwiftShader run every map for every pixel).
#pragma once
#include <cstdint>
#include <vector>

#include "core/tonemap.h"
#include "gpu/program.h"
#include "gpu/texture.h"

namespace pt {

class Display {
 public:
  explicit Display(ToneMap first);  // builds the first tone map's program now
  // `mean` tone-mapped into the bound draw framebuffer at viewport (x, y) and the mean's
  // size, drawn with the fullscreen triangle of vertex array `vao`. With scale > 1 the
  // mean is a coarse image (render/coarse.h) shown upscaled to a w x h viewport, nearest:
  // each texel as a block of scale x scale pixels (texelFetch, so no float-linear
  // filtering is needed, and no colour bleeds across an object's edge).
  void draw(const Texture& mean, ToneMap tonemap, float exposure, int x, int y, GLuint vao, int scale = 1, int w = 0, int h = 0) const;
  // The same into an 8-bit RGBA image (of the mean's size, or w x h), read back: rows bottom to top.
  std::vector<uint8_t> read(const Texture& mean, ToneMap tonemap, float exposure, GLuint vao, int scale = 1, int w = 0, int h = 0) const;

 private:
  mutable Program programs_[kNumToneMaps];
};

}  // namespace pt
