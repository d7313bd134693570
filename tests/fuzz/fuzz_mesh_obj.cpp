// libFuzzer target: Wavefront OBJ (our strict pass, then tinyobjloader), from memory:
// "mtllib" reads no file.
#include <cstdint>
#include <string>

#include "core/error.h"
#include "scene/mesh_obj.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    pt::parse_mesh_obj(std::string(reinterpret_cast<const char*>(data), size), "fuzz.obj");
  } catch (const pt::InputError&) {
  }
  return 0;
}
