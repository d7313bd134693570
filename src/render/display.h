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
  // size, drawn with the fullscreen triangle of vertex array `vao`.
  void draw(const Texture& mean, ToneMap tonemap, float exposure, int x, int y, GLuint vao) const;
  // The same into an 8-bit RGBA image, read back: rows bottom to top.
  std::vector<uint8_t> read(const Texture& mean, ToneMap tonemap, float exposure, GLuint vao) const;

 private:
  mutable Program programs_[kNumToneMaps];
};

}  // namespace pt
