// The accessors of a glTF read from its buffers (gltf_accessors.cpp): tinygltf checks
// none of them, so every offset, stride and count is checked against its buffer here,
// before anything is allocated. Messages name a JSON pointer ("model.gltf: /accessors/3: ...").
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/resumable.h"
#include "scene/gltf_buffers.h"

namespace pt::gltf {

class Reader {
 public:
  // `buffers`: each buffer of the model, as read (a BIN chunk, a file or a data: URI).
  Reader(const std::string& path, const tinygltf::Model& m, std::vector<Bytes> buffers)
      : path_(path), m_(m), buffers_(std::move(buffers)) {}

  // `where` is a JSON pointer into the file ("/accessors/3"): glTF has no line numbers
  // once parsed.
  [[noreturn]] void fail(const std::string& where, const std::string& what) const { throw InputError(path_, 0, where + ": " + what); }

  // An accessor's elements as floats (normalised integers mapped to [0, 1]), with every
  // offset and size checked against its buffer.
  // Resumable (a unit: one element); `out` must outlive it.
  // T: glm::vec2, vec3 or vec4, the accessor's type (VEC2, VEC3, VEC4); read into `out` directly.
  template <typename T>
  Resumable floats(int index, std::string user, std::vector<T>& out) const;

  Resumable indices(int index, std::string user, std::vector<uint32_t>& out) const;

  // An image's bufferView's bytes, checked against its buffer (`where`: the image).
  std::string view(int index, const std::string& where) const;

 private:
  const tinygltf::Accessor& accessor(int index, const std::string& user) const;
  size_t elem_of(const tinygltf::Accessor& a, const std::string& at) const;
  size_t stride_of(const tinygltf::Accessor& a) const;
  const unsigned char* checked(const tinygltf::Accessor& a, const std::string& at) const;

  std::string path_;
  const tinygltf::Model& m_;
  std::vector<Bytes> buffers_;
};

}  // namespace pt::gltf
