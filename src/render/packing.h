// Scene -> the record buffers of render/records.h.
#pragma once
#include "render/records.h"
#include "scene/scene.h"

namespace pt {

struct PackedScene {
  RecordBuffer shapes{shape_rec::kTexels};
  RecordBuffer materials{material_rec::kTexels};
  RecordBuffer lights{light_rec::kTexels};
};

PackedScene pack_scene(const Scene& scene);

}  // namespace pt
