// Our own Radiance RGBE and PFM readers: stb_image's HDR reader reports neither where a
// file is broken nor refuses a header that promises more pixels than the file holds.
// The RGBE conversion matches stb_image's (value * 2^(e - 136), no half-step offset).
#include "core/image_decode.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "core/error.h"
#include "core/file_io.h"

namespace pt {
namespace {

[[noreturn]] void fail_at(const std::string& path, size_t offset, const std::string& what) {
  throw InputError(path, 0, "byte " + std::to_string(offset) + ": " + what);
}

// A positive decimal integer at p (no sign, no spaces); advances p. -1 on failure.
long read_int(const char*& p, const char* end) {
  long v = 0;
  const char* start = p;
  while (p < end && *p >= '0' && *p <= '9' && p - start < 9) v = v * 10 + (*p++ - '0');
  return p == start || (p < end && *p >= '0' && *p <= '9') ? -1 : v;
}

}  // namespace

FloatImage decode_radiance_hdr(const std::string& b, const std::string& path) {
  size_t i = 0;
  int line = 0;
  auto next_line = [&]() {
    const size_t e = b.find('\n', i);
    if (e == std::string::npos) throw InputError(path, line + 1, "the header ends before its blank line and resolution");
    std::string l = b.substr(i, e - i);
    i = e + 1;
    ++line;
    return l;
  };
  const std::string magic = next_line();
  if (magic != "#?RADIANCE" && magic != "#?RGBE") throw InputError(path, 1, "not a Radiance HDR file (the first line must be #?RADIANCE)");
  bool format = false;
  for (std::string l = next_line(); !l.empty(); l = next_line()) {
    if (line > 1000) throw InputError(path, line, "header longer than 1000 lines");
    if (l.rfind("FORMAT=", 0) == 0) {
      if (l != "FORMAT=32-bit_rle_rgbe") throw InputError(path, line, "unsupported pixel format '" + l.substr(7) + "' (only 32-bit_rle_rgbe)");
      format = true;
    }
  }
  if (!format) throw InputError(path, line, "the header has no FORMAT=32-bit_rle_rgbe line");
  const std::string res = next_line();
  const char* p = res.c_str();
  const char* end = p + res.size();
  long h = -1, w = -1;
  if (res.rfind("-Y ", 0) == 0) {
    p += 3;
    h = read_int(p, end);
    if (std::strncmp(p, " +X ", 4) == 0 && p + 4 <= end) {
      p += 4;
      w = read_int(p, end);
    }
  }
  if (h < 0 || w < 0 || p != end) throw InputError(path, line, "resolution line must be \"-Y <height> +X <width>\": \"" + res + "\"");
  if (w < 1 || h < 1 || w > 32767 || h > 32767 || w * h > kMaxImagePixels)
    throw InputError(path, line, "unusable size " + std::to_string(w) + "x" + std::to_string(h));
  // A run-length scanline holds at least 4 header bytes and 2 bytes per 127 pixels and
  // channel: a file shorter than that cannot hold the image (checked before allocating).
  const size_t min_line = w < 8 || w > 32767 ? size_t(4 * w) : size_t(4 + 8 * ((w + 126) / 127));
  if (b.size() - i < min_line * size_t(h))
    fail_at(path, b.size(), "the file ends before " + std::to_string(w) + "x" + std::to_string(h) + " pixels");
  std::vector<unsigned char> rgbe(size_t(w) * size_t(h) * 4);
  const bool rle = w >= 8 && i + 4 <= b.size() && b[i] == 2 && b[i + 1] == 2 && !(b[i + 2] & 0x80);
  auto byte = [&](size_t at) -> unsigned char {
    if (at >= b.size()) fail_at(path, at, "the file ends inside the pixel data");
    return static_cast<unsigned char>(b[at]);
  };
  for (long y = 0; y < h; ++y) {
    unsigned char* row = &rgbe[size_t(y) * size_t(w) * 4];
    if (!rle) {
      for (long k = 0; k < 4 * w; ++k) row[k] = byte(i++);
      continue;
    }
    const size_t at = i;
    if (byte(i) != 2 || byte(i + 1) != 2 || (byte(i + 2) << 8 | byte(i + 3)) != w)
      fail_at(path, at, "scanline " + std::to_string(y) + " lacks its run-length header for width " + std::to_string(w));
    i += 4;
    for (int c = 0; c < 4; ++c) {
      for (long x = 0; x < w;) {
        const size_t run_at = i;
        const int count = byte(i++);
        // count > 128: a run of count - 128 copies of the next byte; else count literal bytes
        // (128 literals included: writers emit them). Only 0 is empty.
        if (count == 0) fail_at(path, run_at, "empty run in scanline " + std::to_string(y));
        const long n = count > 128 ? count - 128 : count;
        if (x + n > w) fail_at(path, run_at, "a run overruns scanline " + std::to_string(y));
        if (count > 128) {
          const unsigned char v = byte(i++);
          for (long k = 0; k < n; ++k) row[size_t(x + k) * 4 + size_t(c)] = v;
        } else {
          for (long k = 0; k < n; ++k) row[size_t(x + k) * 4 + size_t(c)] = byte(i++);
        }
        x += n;
      }
    }
  }
  FloatImage img;
  img.width = int(w);
  img.height = int(h);
  img.rgba.assign(rgbe.size(), 1.0f);
  for (long y = 0; y < h; ++y)  // the file runs top to bottom
    for (long x = 0; x < w; ++x) {
      const unsigned char* q = &rgbe[(size_t(y) * size_t(w) + size_t(x)) * 4];
      float* o = &img.rgba[(size_t(h - 1 - y) * size_t(w) + size_t(x)) * 4];
      const float f = q[3] ? std::ldexp(1.0f, int(q[3]) - 136) : 0.0f;
      for (int c = 0; c < 3; ++c) o[c] = float(q[c]) * f;
    }
  return img;
}

FloatImage decode_pfm(const std::string& b, const std::string& path) {
  // "PF\n<w> <h>\n<scale>\n" then little-endian RGB float32 rows, bottom to top.
  if (b.compare(0, 3, "PF\n") != 0) throw InputError(path, 1, "not a colour PFM file (the first line must be PF)");
  const char* p = b.c_str() + 3;
  const char* end = b.c_str() + b.size();
  const long w = read_int(p, end);
  if (w < 0 || p >= end || *p++ != ' ') throw InputError(path, 2, "size line must be \"<width> <height>\"");
  const long h = read_int(p, end);
  if (h < 0 || p >= end || *p++ != '\n') throw InputError(path, 2, "size line must be \"<width> <height>\"");
  if (w < 1 || h < 1 || w * h > kMaxImagePixels) throw InputError(path, 2, "unusable size " + std::to_string(w) + "x" + std::to_string(h));
  const char* scale_end = static_cast<const char*>(std::memchr(p, '\n', size_t(end - p)));
  if (!scale_end) throw InputError(path, 3, "missing scale line");
  char* parsed = nullptr;
  const std::string scale_text(p, scale_end);
  const double scale = std::strtod(scale_text.c_str(), &parsed);
  if (parsed != scale_text.c_str() + scale_text.size() || !(scale < 0.0))
    throw InputError(path, 3, "scale must be negative (little-endian): \"" + scale_text + "\"");
  const size_t header = size_t(scale_end + 1 - b.c_str());
  const size_t n = size_t(w) * size_t(h);
  if (b.size() - header != n * 12)
    fail_at(path, header, "pixel data holds " + std::to_string(b.size() - header) + " bytes, " + std::to_string(w) + "x" +
                              std::to_string(h) + " RGB floats need " + std::to_string(n * 12));
  FloatImage img;
  img.width = int(w);
  img.height = int(h);
  img.rgba.assign(n * 4, 1.0f);
  for (size_t k = 0; k < n; ++k)
    for (size_t c = 0; c < 3; ++c) std::memcpy(&img.rgba[k * 4 + c], b.data() + header + (k * 3 + c) * 4, 4);
  return img;
}

namespace {

uint32_t crc32(const unsigned char* p, size_t n) {
  static uint32_t table[256];
  static const bool ready = [] {
    for (uint32_t i = 0; i < 256; ++i) {
      uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
      table[i] = c;
    }
    return true;
  }();
  (void)ready;
  uint32_t c = 0xffffffffu;
  for (size_t i = 0; i < n; ++i) c = table[(c ^ p[i]) & 0xff] ^ (c >> 8);
  return c ^ 0xffffffffu;
}

uint32_t be32(const std::string& b, size_t at) {
  const auto* p = reinterpret_cast<const unsigned char*>(b.data() + at);
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
}

}  // namespace

size_t check_png_structure(const std::string& b, const std::string& path) {
  if (b.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) fail_at(path, 0, "not a PNG file (bad signature)");
  size_t at = 8, first_idat = 0;
  bool ihdr = false, iend = false;
  while (!iend) {
    if (b.size() - at < 12) fail_at(path, at, "the file ends inside a chunk header (truncated)");
    const uint32_t len = be32(b, at);
    const std::string type = b.substr(at + 4, 4);
    if (len > 0x7fffffffu || b.size() - at - 12 < len) fail_at(path, at, "chunk '" + type + "' runs past the end of the file");
    const uint32_t crc = be32(b, at + 8 + len);
    if (crc32(reinterpret_cast<const unsigned char*>(b.data() + at + 4), len + 4) != crc)
      fail_at(path, at, "CRC mismatch in chunk '" + type + "'");
    if (!ihdr) {
      if (type != "IHDR" || len != 13) fail_at(path, at, "the first chunk must be a 13-byte IHDR");
      const long long w = be32(b, at + 8), h = be32(b, at + 12);
      // Each side is bounded before the product: two 32-bit sides overflow a 64-bit product.
      if (w < 1 || h < 1 || w > kMaxImagePixels || h > kMaxImagePixels || w * h > kMaxImagePixels)
        fail_at(path, at + 8, "unusable size " + std::to_string(w) + "x" + std::to_string(h));
      ihdr = true;
    }
    if (type == "IDAT" && !first_idat) first_idat = at;
    iend = type == "IEND";
    at += 12 + len;
  }
  if (!first_idat) fail_at(path, at, "no IDAT chunk (no pixel data)");
  return first_idat;
}

FloatImage decode_float_image(const std::string& b, const std::string& path) {
  if (b.compare(0, 2, "#?") == 0) return decode_radiance_hdr(b, path);
  if (b.compare(0, 3, "PF\n") == 0) return decode_pfm(b, path);
  if (b.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) return decode_png_float(b, path);
  throw InputError(path, 0, "byte 0: not a Radiance HDR, PFM or PNG image");
}

FloatImage load_float_image(const std::string& path) {
  const auto bytes = read_file(path);
  if (!bytes) throw InputError(path, 0, "cannot open the image file");
  return decode_float_image(*bytes, path);
}

}  // namespace pt
