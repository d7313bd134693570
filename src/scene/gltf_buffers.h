// The buffers of a glTF and tinygltf's parse (gltf_buffers.cpp), and what the glTF files
// share: messages' JSON pointers, the resolver of the files a glTF names, the unit of work.
// The files of the reader, in the order of parse_gltf_steps (mesh_gltf.cpp):
// gltf_container (the GLB chunks, the JSON's depth), gltf_buffers, then gltf_nodes (the
// node tree into parts), which reads gltf_accessors and gltf_materials.
#pragma once
#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "core/resumable.h"
#include "scene/gltf_container.h"
#include "scene/mesh_gltf.h"
#include "scene/tinygltf.h"

namespace pt::gltf {

constexpr long kStep = 4096;  // elements between two checks of the work left

// Where a message says the problem is ("/accessors/3"): glTF has no line numbers once parsed.
inline std::string pointer(const char* array, size_t index) { return std::string("/") + array + "/" + std::to_string(index); }

// What reading the files a glTF names needs: its path and the resolver.
struct Context {
  std::string path;  // the glTF file
  const GltfResolver* resolve = nullptr;
};

// The file a (URL-decoded) URI names, relative to the glTF's folder, through the
// resolver: its path, or nullopt with *why when refused.
std::optional<std::string> resolve_referenced(const Context& c, const std::string& uri, std::string* why);
// A URI of the JSON as a path (tinygltf's decoding).
std::string url_decode(const std::string& uri);

// A buffer's bytes as the conversion reads them.
struct Bytes {
  const unsigned char* data = nullptr;
  size_t size = 0;
};

// tinygltf's model of the file and, in `buffers`, each of its buffers' bytes (a BIN chunk
// where it lies in `bytes`, a file read in slices into `files`, or a data: URI that
// tinygltf decoded into `model`). Resumable: every argument must outlive it, and `bytes`,
// `files` and `model` the buffers.
Resumable read_model(const std::string& bytes, const GltfJson& json, const Context& ctx, tinygltf::Model& model,
                     std::vector<Bytes>& buffers, std::deque<std::string>& files);

}  // namespace pt::gltf
