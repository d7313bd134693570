#include "core/image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "core/error.h"
#include "core/file_io.h"
#include "core/image_decode.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_HDR
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wshadow"
#endif
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace pt {
namespace {

void append(void* ctx, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(ctx);
  const auto* p = static_cast<const uint8_t*>(data);
  out->insert(out->end(), p, p + size);
}

}  // namespace

std::vector<uint8_t> encode_png(int w, int h, const std::vector<uint8_t>& rgba) {
  std::vector<uint8_t> bytes;
  const uint8_t* last_row = rgba.data() + size_t(h - 1) * w * 4;
  if (!stbi_write_png_to_func(append, &bytes, w, h, 4, last_row, -w * 4)) bytes.clear();
  return bytes;
}

std::vector<uint8_t> encode_hdr(int w, int h, const std::vector<float>& rgba) {
  std::vector<float> rgb(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) rgb[(size_t(y) * w + x) * 3 + c] = rgba[(size_t(h - 1 - y) * w + x) * 4 + c];
  std::vector<uint8_t> bytes;
  if (!stbi_write_hdr_to_func(append, &bytes, w, h, 3, rgb.data())) bytes.clear();
  return bytes;
}

bool write_png(const std::string& path, int w, int h, const std::vector<uint8_t>& rgba) {
  const std::vector<uint8_t> bytes = encode_png(w, h, rgba);
  return !bytes.empty() && write_file_atomic(path, bytes.data(), bytes.size());
}

bool write_hdr(const std::string& path, int w, int h, const std::vector<float>& rgba) {
  const std::vector<uint8_t> bytes = encode_hdr(w, h, rgba);
  return !bytes.empty() && write_file_atomic(path, bytes.data(), bytes.size());
}

bool read_hdr(const std::string& path, int* w, int* h, std::vector<float>* rgba) {
  try {
    FloatImage img = load_float_image(path);
    *w = img.width;
    *h = img.height;
    *rgba = std::move(img.rgba);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

FloatImage decode_png_float(const std::string& bytes, const std::string& path) {
  const size_t idat = check_png_structure(bytes, path);
  if (bytes.size() > size_t(1) << 30) throw InputError(path, 0, "PNG file too large");
  int w = 0, h = 0, n = 0;
  float* p = stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w, &h, &n, 4);
  // The chunks are sound, so what stb_image refuses is the header's values or the
  // compressed pixel data; it reports no offset, the IDAT's is the best we know.
  if (!p) throw InputError(path, 0, "byte " + std::to_string(idat) + ": unreadable PNG pixel data: " + stbi_failure_reason());
  FloatImage img;
  img.width = w;
  img.height = h;
  img.rgba.assign(size_t(w) * size_t(h) * 4, 0.0f);
  for (int y = 0; y < h; ++y)
    std::memcpy(&img.rgba[size_t(h - 1 - y) * size_t(w) * 4], p + size_t(y) * size_t(w) * 4, size_t(w) * 4 * sizeof(float));
  stbi_image_free(p);
  return img;
}

bool read_image(const std::string& path, LoadedImage* out, std::string* error) {
  const auto bytes = read_file(path);
  if (!bytes) {
    *error = "no such file, or it cannot be opened";
    return false;
  }
  return decode_image(*bytes, out, error);
}

bool decode_image(const std::string& bytes, LoadedImage* out, std::string* error) {
  if (bytes.size() > size_t(1) << 30) {
    *error = "the image file has more than 1 GiB";
    return false;
  }
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = int(bytes.size());
  int w = 0, h = 0, n = 0;
  // The size is checked before stb_image allocates the pixels (a few bytes of header
  // may promise gigabytes); the float copies below are 16 bytes a pixel, twice.
  if (stbi_info_from_memory(data, size, &w, &h, &n) &&
      (w <= 0 || h <= 0 || w > 16384 || h > 16384 || (long long)w * h > kMaxMapPixels)) {
    *error = "unusable size " + std::to_string(w) + "x" + std::to_string(h) + " (at most " + std::to_string(kMaxMapPixels) +
             " pixels, 16384 a side)";
    return false;
  }
  std::vector<float> top_down;
  // 8- and 16-bit files keep their integer code values (v / max) so that the caller
  // decides what they encode (sRGB colour or a unit vector); HDR files are linear floats.
  if (stbi_is_hdr_from_memory(data, size)) {
    float* p = stbi_loadf_from_memory(data, size, &w, &h, &n, 4);
    if (p) top_down.assign(p, p + size_t(w) * size_t(h) * 4);
    stbi_image_free(p);
    out->bits = 0;
  } else if (stbi_is_16_bit_from_memory(data, size)) {
    stbi_us* p = stbi_load_16_from_memory(data, size, &w, &h, &n, 4);
    if (p)
      for (size_t i = 0; i < size_t(w) * size_t(h) * 4; ++i) top_down.push_back(float(p[i]) / 65535.0f);
    stbi_image_free(p);
    out->bits = 16;
  } else {
    stbi_uc* p = stbi_load_from_memory(data, size, &w, &h, &n, 4);
    if (p)
      for (size_t i = 0; i < size_t(w) * size_t(h) * 4; ++i) top_down.push_back(float(p[i]) / 255.0f);
    stbi_image_free(p);
    out->bits = 8;
  }
  if (top_down.empty() || w <= 0 || h <= 0) {
    const char* why = stbi_failure_reason();
    *error = std::string("not a PNG, JPEG or HDR image stb_image can decode (") + (why ? why : "unknown error") + ")";
    return false;
  }
  out->width = w;
  out->height = h;
  out->rgba.resize(top_down.size());
  const size_t row = size_t(w) * 4;
  for (int y = 0; y < h; ++y) std::copy_n(&top_down[size_t(h - 1 - y) * row], row, &out->rgba[size_t(y) * row]);
  return true;
}

bool write_pfm(const std::string& path, int w, int h, const std::vector<float>& rgba) {
  std::string bytes = "PF\n" + std::to_string(w) + " " + std::to_string(h) + "\n-1.0\n";
  const size_t header = bytes.size();
  bytes.resize(header + size_t(w) * h * 12);
  // The header's length is arbitrary: the floats are unaligned, so they are copied.
  for (size_t i = 0; i < size_t(w) * h; ++i)  // PFM rows run bottom to top, as GL's do
    for (size_t c = 0; c < 3; ++c) std::memcpy(&bytes[header + (i * 3 + c) * 4], &rgba[i * 4 + c], 4);
  return write_file_atomic(path, bytes.data(), bytes.size());
}

bool read_pfm(const std::string& path, int* w, int* h, std::vector<float>* rgba) {
  try {
    const auto bytes = read_file(path);
    if (!bytes) return false;
    FloatImage img = decode_pfm(*bytes, path);
    *w = img.width;
    *h = img.height;
    *rgba = std::move(img.rgba);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

ImageStats image_stats(const std::vector<float>& rgba) {
  ImageStats s;
  s.min_lum = std::numeric_limits<double>::infinity();
  s.max_lum = -s.min_lum;
  const size_t n = rgba.size() / 4;
  for (size_t i = 0; i < n; ++i) {
    const float* p = &rgba[i * 4];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      ++s.bad;
      continue;
    }
    s.mean += glm::dvec3(p[0], p[1], p[2]);
    const double l = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    s.min_lum = std::min(s.min_lum, l);
    s.max_lum = std::max(s.max_lum, l);
  }
  if (n > size_t(s.bad)) s.mean /= double(n - size_t(s.bad));
  return s;
}

}  // namespace pt

namespace pt {

double auto_exposure(const std::vector<float>& rgba, double key) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
    const double l = 0.2126 * rgba[i] + 0.7152 * rgba[i + 1] + 0.0722 * rgba[i + 2];
    if (!std::isfinite(l) || l < 0.0) continue;
    sum += std::log(1e-4 + l);
    ++n;
  }
  return n == 0 ? 1.0 : key / std::exp(sum / double(n));
}

}  // namespace pt
