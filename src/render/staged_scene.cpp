#include "render/staged_scene.h"

#include <algorithm>
#include <string>
#include <vector>

namespace pt {
namespace {

void require_scene_textures(const GlLimits& limits, const PackedScene& p) {
  limits.require_texture(kDataWidth, p.shapes.rows(), "the scene's objects (" + std::to_string(p.shapes.count()) + ")");
  limits.require_texture(kDataWidth, p.materials.rows(), "the scene's materials");
  limits.require_texture(kDataWidth, p.lights.rows(), "the scene's lights");
  limits.require_texture(kDataWidth, p.nodes.rows(), "the scene's BVH (" + std::to_string(p.nodes.count()) + " nodes)");
  limits.require_texture(kDataWidth, p.prims.rows(), "the scene's primitives (" + std::to_string(p.prims.count()) + ")");
  limits.require_texture(kDataWidth, p.vertices.rows(), "the scene's mesh vertices");
}

}  // namespace

StagedScene::StagedScene(const GlLimits& limits, const PackedScene& packed) : p_(&packed) {
  require_scene_textures(limits, packed);
  for (int i = 0; i < kParts; ++i) {
    texture(i) = Texture(kDataWidth, records(i).rows(), GL_RGBA32F, nullptr);
    rows_total_ += records(i).rows();
  }
}

const RecordBuffer& StagedScene::records(int part) const {
  const RecordBuffer* r[kParts] = {&p_->shapes, &p_->materials, &p_->lights, &p_->nodes, &p_->prims, &p_->vertices};
  return *r[part];
}

Texture& StagedScene::texture(int part) {
  Texture* t[kParts] = {&shapes, &materials, &lights, &nodes, &prims, &vertices};
  return *t[part];
}

bool StagedScene::upload(int rows) {
  constexpr size_t kRowFloats = size_t(kDataWidth) * 4;
  while (rows > 0 && part_ < kParts) {
    const RecordBuffer& r = records(part_);
    const std::vector<float>& data = r.raw();
    const size_t full = data.size() / kRowFloats;  // rows the records fill completely
    const int n = std::min(rows, r.rows() - row_);
    glBindTexture(GL_TEXTURE_2D, texture(part_).id());
    const int whole = std::clamp(int(full) - row_, 0, n);
    if (whole > 0)
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, row_, kDataWidth, whole, GL_RGBA, GL_FLOAT, data.data() + size_t(row_) * kRowFloats);
    if (whole < n) {  // the last row, partly filled: padded with zeros as the texture is
      std::vector<float> last(kRowFloats, 0.0f);
      std::copy(data.begin() + std::ptrdiff_t(full * kRowFloats), data.end(), last.begin());
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, row_ + whole, kDataWidth, 1, GL_RGBA, GL_FLOAT, last.data());
    }
    PT_GL_CHECK("glTexSubImage2D");
    row_ += n;
    rows -= n;
    rows_done_ += n;
    if (row_ == r.rows()) {
      ++part_;
      row_ = 0;
    }
  }
  return done();
}

}  // namespace pt
