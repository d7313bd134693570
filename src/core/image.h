// Image files: tone-mapped PNG and linear Radiance HDR, written atomically; simple
// statistics used by the CLI and the tests.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace pt {

// Pixels are RGBA, rows bottom to top (GL order); files are written top to bottom.
// encode_* return the file's bytes (empty on failure); write_* write them atomically.
std::vector<uint8_t> encode_png(int w, int h, const std::vector<uint8_t>& rgba);
std::vector<uint8_t> encode_hdr(int w, int h, const std::vector<float>& rgba);
bool write_png(const std::string& path, int w, int h, const std::vector<uint8_t>& rgba);
bool write_hdr(const std::string& path, int w, int h, const std::vector<float>& rgba);
// Reads a Radiance .hdr (or anything stb_image reads as float) into RGBA, rows bottom to top.
bool read_hdr(const std::string& path, int* w, int* h, std::vector<float>* rgba);
// Any image stb_image reads (PNG, JPEG, Radiance HDR) as RGBA float, rows bottom to top.
// bits = 8 or 16: integer code values divided by 255 or 65535 (not decoded: the caller
// knows whether they are sRGB colours or vectors); bits = 0: linear floats (HDR).
// On failure, *error says why (missing file, or the decoder's reason).
struct LoadedImage {
  int width = 0, height = 0, bits = 8;
  std::vector<float> rgba;
};
bool read_image(const std::string& path, LoadedImage* out, std::string* error);
bool decode_image(const std::string& bytes, LoadedImage* out, std::string* error);  // from memory
// Image maps larger than this (16M pixels, 4096 x 4096) are refused before decoding.
constexpr long long kMaxMapPixels = 1ll << 24;
// Portable float map (little-endian RGB float32): lossless linear images, used for
// benchmark references where RGBE's 8-bit mantissa would put a floor under the error.
bool write_pfm(const std::string& path, int w, int h, const std::vector<float>& rgba);
bool read_pfm(const std::string& path, int* w, int* h, std::vector<float>* rgba);

struct ImageStats {
  glm::dvec3 mean{0.0};
  long bad = 0;  // NaN or Inf values
  double min_lum = 0.0, max_lum = 0.0;
};
ImageStats image_stats(const std::vector<float>& rgba);

// Exposure that maps the image's log-average luminance to `key` (Reinhard et al. 2002,
// "Photographic tone reproduction"): a display choice, the radiance is untouched.
double auto_exposure(const std::vector<float>& rgba, double key = 0.18);

}  // namespace pt
