// libFuzzer target: glTF 2.0, binary (.glb) or JSON (.gltf) as the magic says, from
// memory (parse_gltf). Its buffers and images by file URI are refused without touching
// the disk (an empty resolver); data: URIs and GLB chunks are read.
#include <cstdint>
#include <string>

#include "core/error.h"
#include "scene/mesh_gltf.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    pt::parse_gltf(std::string(reinterpret_cast<const char*>(data), size), "fuzz.gltf", pt::GltfResolver());
  } catch (const pt::InputError&) {
  }
  return 0;
}
