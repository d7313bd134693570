// The outer layer of a glTF file, checked before tinygltf parses it (gltf_buffers.cpp), and
// tinygltf's error text made into our one-line messages. No tinygltf here: a small TU.
#pragma once
#include <cstddef>
#include <string>

namespace pt {

// The JSON text of a glTF file: the whole file, or the JSON chunk of a binary glTF (told
// by its magic "glTF"), whose container (header, chunk lengths and types) is checked
// first, strictly ("file: byte N: ..."). Nesting deeper than 64 is refused (tinygltf
// converts extras and extensions recursively). `text` points into `bytes`.
struct GltfJson {
  bool binary = false;
  const char* text = nullptr;
  size_t size = 0;
  size_t offset = 0;  // of the text in the file
  // A binary glTF's BIN chunk, when it has one: its data's offset in the file and size.
  bool has_bin = false;
  size_t bin_offset = 0, bin_size = 0;
};
GltfJson gltf_json(const std::string& bytes, const std::string& path);

// tinygltf's error (newlines, several lines) as one InputError; a JSON syntax error
// ("parse error at line L, column C") becomes "file:L:" (.gltf) or "file: byte N:" (.glb).
[[noreturn]] void fail_gltf_parse(std::string err, const std::string& path, const GltfJson& json);

}  // namespace pt
