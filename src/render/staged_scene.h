// A packed scene's record textures uploaded a band of rows at a time, so that a page can
// spread a large scene's upload over frames (1.3 million triangles are about 130 MB of
// texels); Renderer::set_scene then swaps them in at once, and the previous scene renders
// until then.
#pragma once
#include "gpu/gl_check.h"
#include "gpu/texture.h"
#include "render/packing.h"

namespace pt {

class StagedScene {
 public:
  // Throws GlError, naming what is too large, when a record texture of the scene would
  // exceed the GPU's texture size; else allocates the textures. `packed`
  // must stay unchanged and alive until the upload is done.
  StagedScene(const GlLimits& limits, const PackedScene& packed);
  bool upload(int rows);  // up to `rows` more rows of texels; true once all are on the GPU
  bool done() const { return part_ == kParts; }
  double progress() const { return rows_total_ ? double(rows_done_) / double(rows_total_) : 1.0; }

  // The record textures (PackedScene's buffers of the same names), complete once done().
  Texture shapes, materials, lights, nodes, prims, vertices;

 private:
  static constexpr int kParts = 6;
  const RecordBuffer& records(int part) const;
  Texture& texture(int part);
  const PackedScene* p_;
  int part_ = 0, row_ = 0;  // the next row to upload, of that part
  int rows_done_ = 0, rows_total_ = 0;
};

}  // namespace pt
