// The error estimate's block sums on the GPU (render/tile_sums.h).
#include "render/tile_sums.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "shadergen/shadergen.h"

namespace pt {

void read_mean_variance(GLuint fbo, int w, int h, std::vector<float>& mean, std::vector<float>& variance) {
  mean = read_rgba_float(fbo, 0, w, h);
  variance = read_rgba_float(fbo, 1, w, h);
  const float lw[3] = {0.2126f, 0.7152f, 0.0722f};  // Rec. 709 luminance, as luminance() in common.glsl
  for (size_t i = 0; i < mean.size(); i += 4) {
    const float v[3] = {variance[i + 2], variance[i + 3], mean[i + 3]};
    float sd = 0.0f;
    for (int k = 0; k < 3; ++k) sd += lw[k] * std::sqrt(std::max(v[k], 0.0f));
    for (int k = 0; k < 3; ++k) variance[i + k] = v[k];
    variance[i + 3] = 0.0f;
    mean[i + 3] = sd * sd;
  }
}

void TileSums::fireflies(const Texture& radiance, int width, int height) {
  const int gw = (width + 1) / 2, gh = (height + 1) / 2;  // packed: a texel per 2x2 pixels
  if (guide_.width() != gw || guide_.height() != gh || !guide_.id()) {
    guide_ = Texture(gw, gh, GL_RGBA32F, nullptr);
    for (Texture& t : scale_) t = Texture(gw, gh, GL_RGBA32F, nullptr);
    depth_ = Texture(gw, gh, GL_DEPTH_COMPONENT16, nullptr);
    guide_fbo_ = Framebuffer(guide_);
    guide_fbo_.attach_depth(depth_);
    scale_fbo_ = Framebuffer(scale_[0], scale_[1], scale_[2]);
    scale_fbo_.attach_depth(depth_);
  }
  glViewport(0, 0, gw, gh);
  radiance.bind(0);
  // The guide, writing depth 0 at the texels with a firefly and 1 elsewhere.
  guide_program_.use();
  guide_program_.set("u_radiance", 0);
  guide_program_.set("u_size", glm::ivec2(width, height));
  glBindFramebuffer(GL_FRAMEBUFFER, guide_fbo_.id());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_TRUE);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  PT_GL_CHECK("glDrawArrays (error guide)");
  // The scales, drawn at depth 0.5 where it is greater than the guide's: only the texels
  // with a firefly run the shader (early depth test).
  scale_program_.use();
  scale_program_.set("u_radiance", 0);
  scale_program_.set("u_guide", 1);
  scale_program_.set("u_size", glm::ivec2(width, height));
  guide_.bind(1);
  glBindFramebuffer(GL_FRAMEBUFFER, scale_fbo_.id());
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  PT_GL_CHECK("glDrawArrays (error scale)");
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
}

BlockGrid TileSums::run(const Texture& radiance, const Texture& stats, GLuint fbo, const std::vector<Image>& snapshots, int width,
                        int height, int block, GLenum format, GLuint vao) {
  const size_t ns = std::min(snapshots.size(), size_t(BlockSums::kSnapshots));
  if (format != GL_RGBA32F) {
    std::vector<float> mean, var;
    read_mean_variance(fbo, width, height, mean, var);
    std::vector<std::vector<float>> images(ns);
    std::vector<const std::vector<float>*> snaps(ns, nullptr);
    for (size_t j = 0; j < ns; ++j)
      if (snapshots[j].texture) {
        images[j] = read_rgba_float(snapshots[j].fbo, 0, width, height);
        snaps[j] = &images[j];
      }
    return block_sums(mean, var, snaps, width, height, block);
  }
  BlockGrid g = BlockGrid::sized(width, height, block);
  if (out_[0].width() != g.blocks_x || out_[0].height() != g.blocks_y || !out_[0].id()) {
    for (Texture& t : out_) t = Texture(g.blocks_x, g.blocks_y, GL_RGBA32F, nullptr);
    fbo_ = Framebuffer(out_[0], out_[1]);
  }
  if (!program_.id()) {
    auto fragment = [](const char* file, const std::string& defines) {
      return Program(fullscreen_vertex(), resolve_includes("#version 300 es\nprecision highp float;\nprecision highp int;\n"
                                                           "precision highp sampler2D;\n" + defines + "#include \"" + file + "\"\n",
                                                           std::string("<generated ") + file + ">"));
    };
    // core/metrics.h's constants of the firefly test, one source for both sides.
    char defines[256];
    std::snprintf(defines, sizeof defines,
                  "#define FIREFLY_RATIO %#.9g\n#define FIREFLY_NEIGHBOUR %#.9g\n#define GUIDE_TOLERANCE %#.9g\n"
                  "#define GUIDE_FLOOR %#.9g\n#define FIREFLY_RADIUS %d\n",
                  double(kFireflyRatio), double(kFireflyNeighbour), double(kGuideTolerance), double(kGuideFloor), kFireflyRadius);
    program_ = fragment("tile_sums.glsl", defines);
    guide_program_ = fragment("error_guide.glsl", defines);
    scale_program_ = fragment("error_scale.glsl", defines);
  }
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(vao);
  fireflies(radiance, width, height);
  program_.use();
  program_.set("u_radiance", 0);
  program_.set("u_stats", 1);
  const char* names[BlockSums::kSnapshots] = {"u_snap0", "u_snap1", "u_snap2", "u_snap3"};
  for (int j = 0; j < BlockSums::kSnapshots; ++j) program_.set(names[j], 2 + j);
  const int unit = 2 + BlockSums::kSnapshots;
  program_.set("u_guide", unit);
  guide_.bind(unit);
  const char* planes[3] = {"u_scale_r", "u_scale_g", "u_scale_b"};
  for (int c = 0; c < 3; ++c) {
    program_.set(planes[c], unit + 1 + c);
    scale_[c].bind(unit + 1 + c);
  }
  program_.set("u_block", block);
  program_.set("u_size", glm::ivec2(width, height));
  radiance.bind(0);
  stats.bind(1);
  for (size_t j = 0; j < size_t(BlockSums::kSnapshots); ++j)
    (j < ns && snapshots[j].texture ? *snapshots[j].texture : radiance).bind(int(2 + j));
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, g.blocks_x, g.blocks_y);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  PT_GL_CHECK("glDrawArrays (tile sums)");
  const std::vector<float> s0 = read_rgba_float(fbo_.id(), 0, g.blocks_x, g.blocks_y);
  const std::vector<float> s1 = read_rgba_float(fbo_.id(), 1, g.blocks_x, g.blocks_y);
  for (size_t b = 0; b < g.sums.size(); ++b) {
    BlockSums& q = g.sums[b];
    q.var = s0[4 * b];
    for (int j = 0; j < 3; ++j) q.diff[j] = j < int(ns) && snapshots[size_t(j)].texture ? s0[4 * b + 1 + size_t(j)] : 0.0;
    q.diff[3] = ns > 3 && snapshots[3].texture ? s1[4 * b] : 0.0;
    q.pixels = s1[4 * b + 1];
  }
  return g;
}

}  // namespace pt
