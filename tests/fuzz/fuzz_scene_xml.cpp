// libFuzzer target: the XML scene loader on arbitrary text. File references are refused
// (allow_files = false), so the fuzzer never reads the disk; meshes and images have
// their own targets. Only InputError may come out: anything else is a finding.
// Generated meshes are capped at 2^18 triangles per scene (three level-6 icospheres): a
// legal level-9 one (5.2 million triangles) takes seconds under ASan, which libFuzzer
// reports as a hang; generation is tested exhaustively in mesh_generate_test.cpp.
#include <cstdint>
#include <string>

#include "core/error.h"
#include "scene/xml_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    pt::load_scene_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz.xml", false, 1ll << 18);
  } catch (const pt::InputError&) {
  }
  return 0;
}
