// libFuzzer target: the seed's JSON mesh format (parse_mesh_json).
#include <cstdint>
#include <string>

#include "core/error.h"
#include "scene/mesh_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    pt::parse_mesh_json(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const pt::InputError&) {
  }
  return 0;
}
