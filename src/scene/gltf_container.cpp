#include "scene/gltf_container.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>

#include "core/error.h"

namespace pt {
namespace {

// tinygltf 2.7 checks the BIN chunk's length without its 8-byte header, so a BIN chunk
// claiming to reach the end of the file is read up to 8 bytes past it: the container is
// checked here first, strictly, with the byte offset of what is wrong.
void check_glb_structure(const std::string& b, const std::string& path) {
  auto fail = [&](size_t at, const std::string& what) { throw InputError(path, 0, "byte " + std::to_string(at) + ": " + what); };
  auto u32 = [&](size_t at) {
    uint32_t v;
    std::memcpy(&v, b.data() + at, 4);  // GLB is little-endian, as are our targets (x86-64, wasm)
    return v;
  };
  if (b.size() < 20) fail(b.size(), "the file ends inside the GLB header (truncated)");
  if (u32(4) != 2) fail(4, "GLB version " + std::to_string(u32(4)) + " (only version 2 is read)");
  if (u32(8) != b.size())
    fail(8, "the header says " + std::to_string(u32(8)) + " bytes, the file has " + std::to_string(b.size()) + " (truncated?)");
  if (u32(16) != 0x4E4F534Au) fail(16, "the first chunk is not JSON");
  const size_t json = u32(12);
  if (json > b.size() - 20) fail(12, "the JSON chunk runs past the end of the file");
  const size_t at = 20 + json;
  if (at == b.size()) return;
  if (b.size() - at < 8) fail(at, "the file ends inside a chunk header (truncated)");
  if (u32(at + 4) != 0x004E4942u) fail(at + 4, "the second chunk is not BIN");
  if (u32(at) > b.size() - at - 8) fail(at, "the BIN chunk runs past the end of the file");
}

// tinygltf turns extensions and extras into its own values recursively, one call per
// level: nesting is bounded here so that a deep file cannot exhaust the stack.
void check_json_depth(const char* s, size_t n, const std::function<void(size_t, const std::string&)>& fail) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < n; ++i) {
    const char c = s[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > 64) fail(i, "JSON nested more than 64 deep");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

}  // namespace

GltfJson gltf_json(const std::string& bytes, const std::string& path) {
  GltfJson j;
  j.binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
  if (j.binary) check_glb_structure(bytes, path);
  j.offset = j.binary ? 20 : 0;
  uint32_t chunk = 0;
  if (j.binary) std::memcpy(&chunk, bytes.data() + 12, 4);
  j.size = j.binary ? size_t(chunk) : bytes.size();
  j.text = bytes.data() + j.offset;
  if (j.binary && 20 + j.size < bytes.size()) {  // check_glb_structure checked the BIN chunk's header
    uint32_t bin = 0;
    std::memcpy(&bin, bytes.data() + 20 + j.size, 4);
    j.has_bin = true;
    j.bin_offset = 20 + j.size + 8;
    j.bin_size = bin;
  }
  check_json_depth(j.text, j.size, [&](size_t at, const std::string& what) {
    if (j.binary) throw InputError(path, 0, "byte " + std::to_string(j.offset + at) + ": " + what);
    throw InputError(path, 1 + int(std::count(j.text, j.text + at, '\n')), what);
  });
  if (bytes.size() > size_t(1) << 30) throw InputError(path, 0, "the file has more than 1 GiB");
  return j;
}

void fail_gltf_parse(std::string err, const std::string& path, const GltfJson& json) {
  for (char& c : err)
    if (c == '\n' || c == '\r') c = ' ';
  while (!err.empty() && err.back() == ' ') err.pop_back();
  if (err.empty()) err = "cannot read the glTF file";
  const size_t p = err.find("parse error at line ");
  int line = 0, column = 0, used = 0;
  if (p != std::string::npos && std::sscanf(err.c_str() + p, "parse error at line %d, column %d: %n", &line, &column, &used) == 2 &&
      used > 0 && line > 0) {
    const std::string what = "malformed JSON: " + err.substr(p + size_t(used));
    if (!json.binary) throw InputError(path, line, what);
    size_t at = 0;  // the byte of (line, column) in the chunk
    for (int l = 1; l < line && at < json.size; ++at)
      if (json.text[at] == '\n') ++l;
    throw InputError(path, 0, "byte " + std::to_string(json.offset + std::min(json.size, at + size_t(std::max(column, 1) - 1))) + ": " + what);
  }
  throw InputError(path, 0, err);
}

}  // namespace pt
