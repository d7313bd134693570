// The error estimate's sums over blocks of pixels, reduced on the GPU (issue 14): one
// fragment pass (shaders/tile_sums.glsl) writes a blocks_x x blocks_y float image of
// core/metrics.h's BlockSums, and only that is read back, not the mean, the variance and
// up to four snapshots at full size. At 1920x1080 those readbacks and their loops on the
// CPU cost 0.1-0.3 s each on the H100 (docs/benchmarks.md), and adaptive sampling reads the
// variance back whenever the mean count grows by a quarter (render/adaptive.h).
#pragma once
#include <vector>

#include "core/metrics.h"
#include "gpu/program.h"
#include "gpu/texture.h"

namespace pt {

// The accumulator's two targets (attachments 0 and 1 of `fbo`, w x h) read back as the mean
// (RGB; A a bound on the luminance's variance, as Accumulator::read_radiance) and the
// variance (RGB; A 0): Accumulator::read_mean_variance, and the half-float path below.
void read_mean_variance(GLuint fbo, int w, int h, std::vector<float>& mean, std::vector<float>& variance);

class TileSums {
 public:
  // An image's inputs: the mean (RGB; A the blue channel's variance) and the statistics
  // (z, w: the red and green channels' variance) as attachments 0 and 1 of `fbo`; each
  // snapshot's mean (RGB) as its texture and its framebuffer's attachment 0. `format`:
  // the targets' (GL_RGBA32F: on the GPU; half floats: read back and summed on the CPU,
  // block_sums, the sums being too large and too many for 11-bit mantissas).
  struct Image {
    const Texture* texture = nullptr;
    GLuint fbo = 0;
  };
  BlockGrid run(const Texture& radiance, const Texture& stats, GLuint fbo, const std::vector<Image>& snapshots, int width, int height,
                int block, GLenum format, GLuint vao);


 private:
  // The firefly test's passes (core/metrics.h, error_guide and error_scale): the guide and
  // the fireflies' scales at a texel per 2x2 pixels, the depth marking the texels with one.
  void fireflies(const Texture& radiance, int width, int height);
  Program program_, guide_program_, scale_program_;
  Texture out_[2], guide_, scale_[3], depth_;
  Framebuffer fbo_, guide_fbo_, scale_fbo_;
};

}  // namespace pt
