#include "scene/mesh_gltf.h"

#include <cmath>
#include <cstring>
#include <map>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE        // images are decoded by our own loader, by uri
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wconversion"
#endif
#include <tiny_gltf.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include "core/error.h"

namespace pt {
namespace {

bool keep_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

class Reader {
 public:
  Reader(const std::string& path, const tinygltf::Model& m) : path_(path), m_(m) {}

  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_, 0, what); }

  // An accessor's elements as floats (normalised integers mapped to [0, 1]), with every
  // offset and size checked against its buffer.
  std::vector<float> floats(int index, int want_components, const char* what) const {
    const tinygltf::Accessor& a = accessor(index, what);
    const int comps = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    if (comps != want_components) fail(std::string(what) + ": expected " + std::to_string(want_components) + " components");
    std::vector<float> out(a.count * size_t(comps));
    read(a, what, [&](const unsigned char* p, size_t i) {
      for (int c = 0; c < comps; ++c) {
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
          default: fail(std::string(what) + ": unsupported component type");
        }
        if (!std::isfinite(v)) fail(std::string(what) + ": element " + std::to_string(i) + " is not finite");
        out[i * size_t(comps) + size_t(c)] = v;
      }
    });
    return out;
  }

  std::vector<uint32_t> indices(int index) const {
    const tinygltf::Accessor& a = accessor(index, "indices");
    if (a.type != TINYGLTF_TYPE_SCALAR) fail("indices: not scalar");
    std::vector<uint32_t> out(a.count);
    read(a, "indices", [&](const unsigned char* p, size_t i) {
      switch (a.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: out[i] = p[0]; break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
          uint16_t s;
          std::memcpy(&s, p, 2);
          out[i] = s;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: std::memcpy(&out[i], p, 4); break;
        default: fail("indices: unsupported component type");
      }
    });
    return out;
  }

 private:
  const tinygltf::Accessor& accessor(int index, const char* what) const {
    if (index < 0 || size_t(index) >= m_.accessors.size()) fail(std::string(what) + ": no such accessor");
    const tinygltf::Accessor& a = m_.accessors[size_t(index)];
    if (a.sparse.isSparse) fail(std::string(what) + ": sparse accessors are not supported");
    if (a.bufferView < 0 || size_t(a.bufferView) >= m_.bufferViews.size()) fail(std::string(what) + ": no buffer view");
    return a;
  }

  template <class F>
  void read(const tinygltf::Accessor& a, const char* what, F&& element) const {
    const tinygltf::BufferView& v = m_.bufferViews[size_t(a.bufferView)];
    if (v.buffer < 0 || size_t(v.buffer) >= m_.buffers.size()) fail(std::string(what) + ": no buffer");
    const std::vector<unsigned char>& b = m_.buffers[size_t(v.buffer)].data;
    const int comp_size = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    const int comps = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    if (comp_size <= 0 || comps <= 0) fail(std::string(what) + ": bad accessor type");
    const size_t elem = size_t(comp_size) * size_t(comps);
    const size_t stride = v.byteStride ? v.byteStride : elem;
    const size_t start = v.byteOffset + a.byteOffset;
    if (a.count == 0) return;
    // Overflow-safe: the last element must end inside the view and the view inside the buffer.
    if (v.byteOffset > b.size() || v.byteLength > b.size() - v.byteOffset || stride < elem || a.byteOffset > v.byteLength ||
        (a.count - 1) > (v.byteLength - a.byteOffset - std::min(elem, v.byteLength - a.byteOffset)) / stride ||
        elem > v.byteLength - a.byteOffset)
      fail(std::string(what) + ": accessor runs past its buffer");
    for (size_t i = 0; i < a.count; ++i) element(b.data() + start + i * stride, i);
  }

  std::string path_;
  const tinygltf::Model& m_;
};

glm::mat4 node_matrix(const tinygltf::Node& n) {
  if (n.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = float(n.matrix[size_t(i)]);  // column-major, as glTF
    return m;
  }
  glm::mat4 m(1.0f);
  if (n.translation.size() == 3) m = glm::translate(m, glm::vec3(n.translation[0], n.translation[1], n.translation[2]));
  if (n.rotation.size() == 4)
    m *= glm::mat4_cast(glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2])));
  if (n.scale.size() == 3) m = glm::scale(m, glm::vec3(n.scale[0], n.scale[1], n.scale[2]));
  return m;
}

GltfMaterial material_of(const tinygltf::Model& model, int index) {
  GltfMaterial g;
  if (index < 0 || size_t(index) >= model.materials.size()) return g;
  const tinygltf::Material& m = model.materials[size_t(index)];
  const auto& pbr = m.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() >= 3) g.base_color = glm::vec3(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]);
  g.metallic = float(pbr.metallicFactor);
  g.roughness = float(pbr.roughnessFactor);
  if (m.emissiveFactor.size() == 3) g.emissive = glm::vec3(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]);
  if (auto t = m.extensions.find("KHR_materials_transmission"); t != m.extensions.end() && t->second.Has("transmissionFactor"))
    g.transmission = float(t->second.Get("transmissionFactor").GetNumberAsDouble());
  if (auto t = m.extensions.find("KHR_materials_ior"); t != m.extensions.end() && t->second.Has("ior"))
    g.ior = float(t->second.Get("ior").GetNumberAsDouble());
  return g;
}

}  // namespace

std::vector<GltfPart> load_gltf(const std::string& path) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keep_image, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const bool binary = path.size() > 4 && (path.compare(path.size() - 4, 4, ".glb") == 0 || path.compare(path.size() - 4, 4, ".GLB") == 0);
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, path) : loader.LoadASCIIFromFile(&model, &err, &warn, path);
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
    throw InputError(path, 0, err.empty() ? "cannot read the glTF file" : err);
  }
  const Reader r(path, model);
  // Keyed by the accessors a primitive reads: primitives (or meshes) that differ only in
  // material share one MeshData.
  std::map<std::vector<int>, std::shared_ptr<const MeshData>> cache;
  auto primitive = [&](int mesh, int prim) -> std::shared_ptr<const MeshData> {
    const tinygltf::Primitive& p = model.meshes[size_t(mesh)].primitives[size_t(prim)];
    std::vector<int> key{p.mode, p.indices};
    for (const char* a : {"POSITION", "NORMAL", "TEXCOORD_0"}) {
      const auto it = p.attributes.find(a);
      key.push_back(it == p.attributes.end() ? -1 : it->second);
    }
    auto& slot = cache[key];
    if (slot) return slot;
    if (p.mode != -1 && p.mode != TINYGLTF_MODE_TRIANGLES) return nullptr;  // points and lines: nothing to render
    auto d = std::make_shared<MeshData>();
    const auto pos = p.attributes.find("POSITION");
    if (pos == p.attributes.end()) r.fail("mesh " + std::to_string(mesh) + ": a primitive has no POSITION");
    const std::vector<float> v = r.floats(pos->second, 3, "POSITION");
    for (size_t i = 0; i + 2 < v.size(); i += 3) d->positions.emplace_back(v[i], v[i + 1], v[i + 2]);
    if (auto n = p.attributes.find("NORMAL"); n != p.attributes.end()) {
      const std::vector<float> f = r.floats(n->second, 3, "NORMAL");
      if (f.size() != v.size()) r.fail("NORMAL and POSITION counts differ");
      for (size_t i = 0; i + 2 < f.size(); i += 3) d->normals.emplace_back(f[i], f[i + 1], f[i + 2]);
    }
    if (auto t = p.attributes.find("TEXCOORD_0"); t != p.attributes.end()) {
      const std::vector<float> f = r.floats(t->second, 2, "TEXCOORD_0");
      if (f.size() / 2 != d->positions.size()) r.fail("TEXCOORD_0 and POSITION counts differ");
      for (size_t i = 0; i + 1 < f.size(); i += 2) d->uvs.emplace_back(f[i], f[i + 1]);
    }
    std::vector<uint32_t> idx;
    if (p.indices >= 0) {
      idx = r.indices(p.indices);
    } else {
      idx.resize(d->positions.size());
      for (size_t i = 0; i < idx.size(); ++i) idx[i] = uint32_t(i);
    }
    for (size_t i = 0; i + 2 < idx.size(); i += 3) {
      for (int k = 0; k < 3; ++k)
        if (idx[i + size_t(k)] >= d->positions.size()) r.fail("index " + std::to_string(idx[i + size_t(k)]) + " out of range");
      d->triangles.emplace_back(idx[i], idx[i + 1], idx[i + 2]);
    }
    slot = d;
    return slot;
  };
  std::vector<GltfPart> parts;
  // Depth-first over the node tree; the depth bound also stops cycles in a malformed file.
  struct Item {
    int node;
    glm::mat4 parent;
    int depth;
  };
  std::vector<Item> todo;
  const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (!model.scenes.empty()) {
    if (size_t(scene) >= model.scenes.size()) r.fail("no such default scene");
    for (int n : model.scenes[size_t(scene)].nodes) todo.push_back({n, glm::mat4(1.0f), 0});
  } else {
    for (size_t n = 0; n < model.nodes.size(); ++n) todo.push_back({int(n), glm::mat4(1.0f), 0});
  }
  while (!todo.empty()) {
    const Item it = todo.back();
    todo.pop_back();
    if (it.node < 0 || size_t(it.node) >= model.nodes.size()) r.fail("no such node " + std::to_string(it.node));
    if (it.depth > 64) r.fail("the node tree is deeper than 64 (a cycle?)");
    const tinygltf::Node& n = model.nodes[size_t(it.node)];
    const glm::mat4 world = it.parent * node_matrix(n);
    if (n.mesh >= 0) {
      if (size_t(n.mesh) >= model.meshes.size()) r.fail("node " + std::to_string(it.node) + ": no such mesh");
      const tinygltf::Mesh& mesh = model.meshes[size_t(n.mesh)];
      for (size_t p = 0; p < mesh.primitives.size(); ++p) {
        std::shared_ptr<const MeshData> d = primitive(n.mesh, int(p));
        if (d && !d->triangles.empty()) parts.push_back({d, world, material_of(model, mesh.primitives[p].material)});
      }
    }
    for (int c : n.children) todo.push_back({c, world, it.depth + 1});
  }
  if (parts.empty()) r.fail("no triangles in the default scene");
  return parts;
}

}  // namespace pt
