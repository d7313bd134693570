// Reading a glTF's accessors (vertex attributes and indices) and an image's bufferView
// out of the buffers that gltf_buffers.cpp read, each element checked as it is read.
#include "scene/gltf_accessors.h"

#include <cmath>
#include <cstring>

#include <glm/glm.hpp>

namespace pt::gltf {

template <typename T>
Resumable Reader::floats(int index, std::string user, std::vector<T>& out) const {
  constexpr int want_components = T::length();
  const tinygltf::Accessor& a = accessor(index, user);
  const std::string at = pointer("accessors", size_t(index));
  const int comps = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  if (comps != want_components) fail(at, "expected " + std::to_string(want_components) + " components (used by " + user + ")");
  const unsigned char* base = checked(a, at);
  out.clear();  // filled in the loop: touching a large array in one step is slow
  out.reserve(a.count);
  const size_t stride = stride_of(a);
  for (size_t i = 0; i < a.count; ++i) {
    const unsigned char* p = base + i * stride;
    T e;
    for (int c = 0; c < want_components; ++c) {
      float v = 0.0f;
      switch (a.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: std::memcpy(&v, p + 4 * c, 4); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: v = float(p[c]) / 255.0f; break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
          uint16_t s;
          std::memcpy(&s, p + 2 * c, 2);
          v = float(s) / 65535.0f;
          break;
        }
        default: fail(at, "unsupported component type " + std::to_string(a.componentType) + " (used by " + user + ")");
      }
      if (!std::isfinite(v)) fail(at, "element " + std::to_string(i) + " is not finite");
      e[c] = v;
    }
    out.push_back(e);
    if (i % kStep == kStep - 1) co_await Work{kStep};
  }
}
// The types the mesh reads (MeshData's positions and normals, uvs).
template Resumable Reader::floats<glm::vec2>(int, std::string, std::vector<glm::vec2>&) const;
template Resumable Reader::floats<glm::vec3>(int, std::string, std::vector<glm::vec3>&) const;
template Resumable Reader::floats<glm::vec4>(int, std::string, std::vector<glm::vec4>&) const;  // COLOR_0

Resumable Reader::indices(int index, std::string user, std::vector<uint32_t>& out) const {
  const tinygltf::Accessor& a = accessor(index, user);
  const std::string at = pointer("accessors", size_t(index));
  if (a.type != TINYGLTF_TYPE_SCALAR) fail(at, "indices must be scalars");
  const unsigned char* base = checked(a, at);
  out.clear();
  out.reserve(a.count);
  const size_t stride = stride_of(a);
  for (size_t i = 0; i < a.count; ++i) {
    const unsigned char* p = base + i * stride;
    switch (a.componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: out.push_back(p[0]); break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t s;
        std::memcpy(&s, p, 2);
        out.push_back(s);
        break;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t u;
        std::memcpy(&u, p, 4);
        out.push_back(u);
        break;
      }
      default: fail(at, "unsupported index component type " + std::to_string(a.componentType));
    }
    if (i % kStep == kStep - 1) co_await Work{kStep};
  }
}

std::string Reader::view(int index, const std::string& where) const {
  if (index < 0 || size_t(index) >= m_.bufferViews.size()) fail(where, "no bufferView " + std::to_string(index));
  const tinygltf::BufferView& v = m_.bufferViews[size_t(index)];
  if (v.buffer < 0 || size_t(v.buffer) >= buffers_.size()) fail(pointer("bufferViews", size_t(index)), "no buffer " + std::to_string(v.buffer));
  const Bytes b = buffers_[size_t(v.buffer)];
  if (v.byteOffset > b.size || v.byteLength > b.size - v.byteOffset) fail(where, "its bufferView runs past its buffer");
  return std::string(reinterpret_cast<const char*>(b.data) + v.byteOffset, v.byteLength);
}

const tinygltf::Accessor& Reader::accessor(int index, const std::string& user) const {
  if (index < 0 || size_t(index) >= m_.accessors.size()) fail(user, "no accessor " + std::to_string(index));
  const tinygltf::Accessor& a = m_.accessors[size_t(index)];
  const std::string at = pointer("accessors", size_t(index));
  if (a.sparse.isSparse) fail(at, "sparse accessors are not supported");
  if (a.bufferView < 0 || size_t(a.bufferView) >= m_.bufferViews.size()) fail(at, "no bufferView " + std::to_string(a.bufferView));
  return a;
}

size_t Reader::elem_of(const tinygltf::Accessor& a, const std::string& at) const {
  const int comp_size = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  const int comps = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  if (comp_size <= 0 || comps <= 0) fail(at, "bad componentType or type");
  return size_t(comp_size) * size_t(comps);
}

size_t Reader::stride_of(const tinygltf::Accessor& a) const {
  const tinygltf::BufferView& v = m_.bufferViews[size_t(a.bufferView)];
  return v.byteStride ? v.byteStride : size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType))) *
                                            size_t(tinygltf::GetNumComponentsInType(uint32_t(a.type)));
}

// The first element's address, once every element is known to lie inside the view and
// the view inside its buffer (overflow-safe: nothing is allocated before this).
const unsigned char* Reader::checked(const tinygltf::Accessor& a, const std::string& at) const {
  const tinygltf::BufferView& v = m_.bufferViews[size_t(a.bufferView)];
  if (v.buffer < 0 || size_t(v.buffer) >= m_.buffers.size()) fail(pointer("bufferViews", size_t(a.bufferView)), "no buffer " + std::to_string(v.buffer));
  const Bytes b = buffers_[size_t(v.buffer)];
  const size_t elem = elem_of(a, at);
  const size_t stride = stride_of(a);
  if (v.byteOffset > b.size || v.byteLength > b.size - v.byteOffset)
    fail(pointer("bufferViews", size_t(a.bufferView)), "runs past its buffer (" + std::to_string(b.size) + " bytes)");
  if (stride < elem) fail(at, "elements overlap (byteStride " + std::to_string(stride) + " < " + std::to_string(elem) + ")");
  if (a.count == 0) return nullptr;
  if (a.byteOffset > v.byteLength || elem > v.byteLength - a.byteOffset ||
      (a.count - 1) > (v.byteLength - a.byteOffset - elem) / stride)
    fail(at, std::to_string(a.count) + " elements run past the end of bufferView " + std::to_string(a.bufferView));
  return b.data + v.byteOffset + a.byteOffset;
}

}  // namespace pt::gltf
