// libFuzzer target: every float image decoder a scene or the CLI can reach (Radiance
// RGBE, PFM, PNG through our chunk walk and stb_image), chosen by signature as in use.
#include <cstdint>
#include <string>

#include "core/error.h"
#include "core/image_decode.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    pt::decode_float_image(std::string(reinterpret_cast<const char*>(data), size), "fuzz.img");
  } catch (const pt::InputError&) {
  }
  return 0;
}
