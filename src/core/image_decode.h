// Decoding of the float images a scene may reference (environment maps) and of the
// benchmark references: Radiance RGBE (.hdr), little-endian PFM, PNG. Strict: every
// error is an InputError naming the file and the header line or byte offset.
#pragma once
#include <string>
#include <vector>

namespace pt {

struct FloatImage {
  int width = 0, height = 0;
  std::vector<float> rgba;  // rows bottom to top (GL order)
};

// Images larger than this are refused before any pixel memory is allocated.
constexpr long long kMaxImagePixels = 1ll << 26;

FloatImage decode_radiance_hdr(const std::string& bytes, const std::string& path);
FloatImage decode_pfm(const std::string& bytes, const std::string& path);
// Walks a PNG's chunks (lengths, CRCs, IHDR size, IEND) so that a broken file is
// reported at its byte offset; returns the offset of the first IDAT chunk.
size_t check_png_structure(const std::string& bytes, const std::string& path);
FloatImage decode_png_float(const std::string& bytes, const std::string& path);  // image.cpp (stb)
// Chooses the decoder by signature ("#?", "PF\n", the PNG magic).
FloatImage decode_float_image(const std::string& bytes, const std::string& path);
FloatImage load_float_image(const std::string& path);  // throws InputError

}  // namespace pt
