#include "scene/mesh_gltf.h"

#include <cmath>
#include <cstring>
#include <deque>
#include <map>
#include <memory>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE        // images are decoded by our own reader (keep_image)
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
#include "core/file_io.h"
#include "scene/gltf_container.h"

namespace pt {
namespace {

// What reading the files a glTF names needs: its path and the resolver.
struct Context {
  std::string path;  // the glTF file
  const GltfResolver* resolve = nullptr;
};

constexpr long kStep = 4096;  // elements between two checks of the work left

std::string pointer(const char* array, size_t index) { return std::string("/") + array + "/" + std::to_string(index); }

// tinygltf's file callbacks: it opens no file itself (its own search - its base folder,
// then the working directory - is never used).
bool file_exists(const std::string&, void*) { return true; }
std::string expand_path(const std::string& p, void*) { return p; }
bool write_file(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }
// The file a (URL-decoded) URI names, relative to the glTF's folder, through the
// resolver: its path, or nullopt with *why when refused.
std::optional<std::string> resolve_referenced(const Context& c, const std::string& uri, std::string* why) {
  const std::string rel = !uri.empty() && uri[0] == '/' ? uri : directory_of(c.path) + "/" + uri;
  if (!c.resolve || !*c.resolve) {
    *why = "file references are disabled for this glTF";
    return std::nullopt;
  }
  try {
    return (*c.resolve)(rel);
  } catch (const InputError& e) {
    *why = e.what();
  }
  return std::nullopt;
}

// An image file's bytes; false with *why when refused or unreadable (buffer files are
// read in slices by parse_gltf_steps).
bool read_image_file(const Context& c, const std::string& uri, std::string* out, std::string* why) {
  const std::optional<std::string> file = resolve_referenced(c, uri, why);
  if (!file) return false;
  if (auto bytes = read_file(*file)) {
    *out = std::move(*bytes);
    return true;
  }
  *why = "cannot open the image file " + *file;
  return false;
}

// Every buffer file is read by parse_gltf_steps before tinygltf parses (own_buffers):
// tinygltf is never to read one itself.
bool refuse_file(std::vector<unsigned char>*, std::string* err, const std::string&, void*) {
  *err = "buffer files are read before tinygltf parses";
  return false;
}

// Images: their bytes are kept, undecoded (image.as_is), and decoded by our own image
// reader when a material uses them. An image in a bufferView is read then too, from the
// buffers as the conversion has them (Reader::view; tinygltf may not hold the bytes).
bool keep_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes, int size, void*) {
  image->as_is = true;
  if (image->bufferView >= 0) return true;
  if (size < 0 || (size > 0 && !bytes)) return false;
  image->image.assign(bytes, bytes + size);
  return true;
}

// A buffer's bytes as the conversion reads them.
struct Bytes {
  const unsigned char* data = nullptr;
  size_t size = 0;
};

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
  // T: glm::vec2 or glm::vec3, the accessor's type (VEC2, VEC3); read into `out` directly.
  template <typename T>
  Resumable floats(int index, std::string user, std::vector<T>& out) const {
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

  Resumable indices(int index, std::string user, std::vector<uint32_t>& out) const {
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

 private:
  const tinygltf::Accessor& accessor(int index, const std::string& user) const {
    if (index < 0 || size_t(index) >= m_.accessors.size()) fail(user, "no accessor " + std::to_string(index));
    const tinygltf::Accessor& a = m_.accessors[size_t(index)];
    const std::string at = pointer("accessors", size_t(index));
    if (a.sparse.isSparse) fail(at, "sparse accessors are not supported");
    if (a.bufferView < 0 || size_t(a.bufferView) >= m_.bufferViews.size()) fail(at, "no bufferView " + std::to_string(a.bufferView));
    return a;
  }

  size_t elem_of(const tinygltf::Accessor& a, const std::string& at) const {
    const int comp_size = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    const int comps = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    if (comp_size <= 0 || comps <= 0) fail(at, "bad componentType or type");
    return size_t(comp_size) * size_t(comps);
  }
  size_t stride_of(const tinygltf::Accessor& a) const {
    const tinygltf::BufferView& v = m_.bufferViews[size_t(a.bufferView)];
    return v.byteStride ? v.byteStride : size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType))) *
                                              size_t(tinygltf::GetNumComponentsInType(uint32_t(a.type)));
  }

  // The first element's address, once every element is known to lie inside the view and
  // the view inside its buffer (overflow-safe: nothing is allocated before this).
  const unsigned char* checked(const tinygltf::Accessor& a, const std::string& at) const {
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

 public:
  // An image's bufferView's bytes, checked against its buffer (`where`: the image).
  std::string view(int index, const std::string& where) const {
    if (index < 0 || size_t(index) >= m_.bufferViews.size()) fail(where, "no bufferView " + std::to_string(index));
    const tinygltf::BufferView& v = m_.bufferViews[size_t(index)];
    if (v.buffer < 0 || size_t(v.buffer) >= buffers_.size()) fail(pointer("bufferViews", size_t(index)), "no buffer " + std::to_string(v.buffer));
    const Bytes b = buffers_[size_t(v.buffer)];
    if (v.byteOffset > b.size || v.byteLength > b.size - v.byteOffset) fail(where, "its bufferView runs past its buffer");
    return std::string(reinterpret_cast<const char*>(b.data) + v.byteOffset, v.byteLength);
  }

 private:
  std::string path_;
  const tinygltf::Model& m_;
  std::vector<Bytes> buffers_;
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

// Materials, with their image maps decoded once per image (only those a part uses).
// Factors outside their ranges would make a material that creates energy or a NaN in
// the shader: refused, with the material's pointer.
class Materials {
 public:
  Materials(const Reader& r, const tinygltf::Model& m, const Context& c) : r_(r), m_(m), c_(c) {}

  const GltfMaterial& get(int index, const std::string& user) {
    static const GltfMaterial kDefault;
    if (index < 0) return kDefault;
    if (size_t(index) >= m_.materials.size()) r_.fail(user, "no material " + std::to_string(index));
    auto& slot = materials_[index];
    if (!slot) slot = std::make_unique<GltfMaterial>(read(index));
    return *slot;
  }

 private:
  GltfMaterial read(int index) {
    GltfMaterial g;
    const std::string at = pointer("materials", size_t(index));
    const tinygltf::Material& m = m_.materials[size_t(index)];
    const auto& pbr = m.pbrMetallicRoughness;
    auto unit = [&](double v, const char* what) {
      if (!(v >= 0.0 && v <= 1.0)) r_.fail(at, std::string(what) + " must be in [0, 1]");
      return float(v);
    };
    if (pbr.baseColorFactor.size() >= 3)
      g.base_color = glm::vec3(unit(pbr.baseColorFactor[0], "baseColorFactor"), unit(pbr.baseColorFactor[1], "baseColorFactor"),
                               unit(pbr.baseColorFactor[2], "baseColorFactor"));
    g.metallic = unit(pbr.metallicFactor, "metallicFactor");
    g.roughness = unit(pbr.roughnessFactor, "roughnessFactor");
    if (m.emissiveFactor.size() == 3) {
      g.emissive = glm::vec3(unit(m.emissiveFactor[0], "emissiveFactor"), unit(m.emissiveFactor[1], "emissiveFactor"),
                             unit(m.emissiveFactor[2], "emissiveFactor"));
      if (auto t = m.extensions.find("KHR_materials_emissive_strength"); t != m.extensions.end() && t->second.Has("emissiveStrength")) {
        const double k = t->second.Get("emissiveStrength").GetNumberAsDouble();
        if (!(k >= 0.0 && k <= 1e6)) r_.fail(at, "emissiveStrength must be in [0, 1e6]");
        g.emissive *= float(k);
      }
    }
    if (auto t = m.extensions.find("KHR_materials_transmission"); t != m.extensions.end() && t->second.Has("transmissionFactor"))
      g.transmission = unit(t->second.Get("transmissionFactor").GetNumberAsDouble(), "transmissionFactor");
    if (auto t = m.extensions.find("KHR_materials_ior"); t != m.extensions.end() && t->second.Has("ior")) {
      const double ior = t->second.Get("ior").GetNumberAsDouble();
      if (!(ior >= 1.0 && ior <= 10.0)) r_.fail(at, "ior must be in [1, 10]");
      g.ior = float(ior);
    }
    g.base_color_map = map(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, at + "/pbrMetallicRoughness/baseColorTexture");
    g.metallic_roughness_map = map(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                                   at + "/pbrMetallicRoughness/metallicRoughnessTexture");
    g.normal_map = map(m.normalTexture.index, m.normalTexture.texCoord, at + "/normalTexture");
    return g;
  }

  std::shared_ptr<const GltfImage> map(int texture, int tex_coord, const std::string& at) {
    if (texture < 0) return nullptr;
    if (tex_coord != 0) r_.fail(at, "texCoord " + std::to_string(tex_coord) + " is not supported (only TEXCOORD_0)");
    if (size_t(texture) >= m_.textures.size()) r_.fail(at, "no texture " + std::to_string(texture));
    const int source = m_.textures[size_t(texture)].source;
    if (source < 0) r_.fail(pointer("textures", size_t(texture)), "no source (images of formats given by extensions are not read)");
    if (size_t(source) >= m_.images.size()) r_.fail(pointer("textures", size_t(texture)), "no image " + std::to_string(source));
    auto& slot = images_[source];
    if (slot) return slot;
    const std::string where = pointer("images", size_t(source));
    const tinygltf::Image& img = m_.images[size_t(source)];
    std::string bytes, why;
    if (img.bufferView >= 0) {
      bytes = r_.view(img.bufferView, where);
    } else if (img.as_is) {
      bytes.assign(img.image.begin(), img.image.end());  // embedded: a data: URI
    } else if (img.uri.empty()) {
      r_.fail(where, "no image data");
    } else if (!read_image_file(c_, tinygltf::dlib::urldecode(img.uri), &bytes, &why)) {
      r_.fail(where, why);
    }
    auto out = std::make_shared<GltfImage>();
    out->name = c_.path + "#" + where;
    if (!decode_image(bytes, &out->image, &why)) r_.fail(where, why);
    slot = out;
    return slot;
  }

  const Reader& r_;
  const tinygltf::Model& m_;
  const Context& c_;
  std::map<int, std::unique_ptr<GltfMaterial>> materials_;
  std::map<int, std::shared_ptr<const GltfImage>> images_;
};

const char* mode_name(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS: return "points";
    case TINYGLTF_MODE_LINE: return "lines";
    case TINYGLTF_MODE_LINE_LOOP: return "line loop";
    case TINYGLTF_MODE_LINE_STRIP: return "line strip";
    case TINYGLTF_MODE_TRIANGLE_STRIP: return "triangle strip";
    case TINYGLTF_MODE_TRIANGLE_FAN: return "triangle fan";
    default: return "unknown";
  }
}

// A buffer we read ourselves (parse_gltf_steps): stored in the GLB's BIN chunk, or in a
// file named by its (URL-decoded) uri.
struct OwnBuffer {
  size_t index = 0;
  bool bin_chunk = false;
  std::string uri;
  size_t length = 0;  // byteLength
};

// The buffers of the JSON that are ours to read - every one but data: URIs, which
// tinygltf decodes - and in *rewritten the JSON for tinygltf with each of them replaced
// by a 1-byte data: URI (left empty when there are none). JSON that does not parse is
// left to tinygltf, which reports where.
std::vector<OwnBuffer> own_buffers(const GltfJson& json, const std::string& path, std::string* rewritten) {
  std::vector<OwnBuffer> out;
  nlohmann::json doc = nlohmann::json::parse(json.text, json.text + json.size, nullptr, false);
  if (!doc.is_object() || !doc.contains("buffers") || !doc["buffers"].is_array()) return out;
  nlohmann::json& buffers = doc["buffers"];
  for (size_t i = 0; i < buffers.size(); ++i) {
    nlohmann::json& b = buffers[i];
    const std::string at = pointer("buffers", i);
    if (!b.is_object()) throw InputError(path, 0, at + ": not an object");
    if (!b.contains("byteLength") || !b["byteLength"].is_number_unsigned())
      throw InputError(path, 0, at + ": byteLength must be a whole number of bytes");
    OwnBuffer o;
    o.index = i;
    o.length = b["byteLength"].get<size_t>();
    if (!b.contains("uri")) {
      if (!json.binary) throw InputError(path, 0, at + ": no uri (only a binary glTF's buffers may have none)");
      if (!json.has_bin) throw InputError(path, 0, at + ": no uri, and the file has no BIN chunk");
      if (o.length > json.bin_size)
        throw InputError(path, 0, at + ": byteLength " + std::to_string(o.length) + " is more than the BIN chunk's " +
                                      std::to_string(json.bin_size) + " bytes");
      o.bin_chunk = true;
    } else {
      if (!b["uri"].is_string()) throw InputError(path, 0, at + ": uri is not a string");
      const std::string uri = b["uri"].get<std::string>();
      if (uri.rfind("data:", 0) == 0) continue;
      o.uri = tinygltf::dlib::urldecode(uri);
    }
    b["uri"] = "data:application/octet-stream;base64,AA==";
    b["byteLength"] = 1;
    out.push_back(std::move(o));
  }
  if (!out.empty()) *rewritten = doc.dump();
  return out;
}

}  // namespace

Resumable parse_gltf_steps(std::string bytes, std::string path, GltfResolver resolve, std::vector<GltfPart>& parts) {
  parts.clear();
  const GltfJson json = gltf_json(bytes, path);
  Context ctx;
  ctx.path = path;
  ctx.resolve = &resolve;
  // Buffers are ours: tinygltf would copy a GLB's BIN chunk (tens of MB, in one step) and
  // read a buffer file in one step. Each buffer stored in the BIN chunk or in a file is
  // read here instead (a file in slices; the chunk is used where it lies in `bytes`), and
  // tinygltf is given the JSON with that buffer replaced by a 1-byte data: URI. Buffers
  // that are data: URIs stay tinygltf's to decode (one step).
  std::string text;  // the JSON tinygltf parses, when rewritten
  const std::vector<OwnBuffer> ours = own_buffers(json, path, &text);
  std::vector<std::optional<Bytes>> own;
  std::deque<std::string> files;  // the buffer files read (a deque: growing moves none)
  for (const OwnBuffer& o : ours) {
    if (own.size() <= o.index) own.resize(o.index + 1);
    const std::string at = pointer("buffers", o.index);
    if (o.bin_chunk) {
      own[o.index] = Bytes{reinterpret_cast<const unsigned char*>(bytes.data()) + json.bin_offset, o.length};
      continue;
    }
    std::string why;
    const std::optional<std::string> file = resolve_referenced(ctx, o.uri, &why);
    if (!file) throw InputError(path, 0, at + ": " + why);
    std::optional<std::string> read;
    Resumable reading = read_file_steps(*file, read);
    while (!co_await reading) {
    }
    if (!read) throw InputError(path, 0, at + ": cannot open the buffer file " + *file);
    if (read->size() < o.length)
      throw InputError(path, 0, at + ": the buffer file " + *file + " has " + std::to_string(read->size()) + " bytes, byteLength says " +
                                    std::to_string(o.length));
    files.push_back(std::move(*read));
    own[o.index] = Bytes{reinterpret_cast<const unsigned char*>(files.back().data()), o.length};
  }
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keep_image, nullptr);
  loader.SetFsCallbacks({&file_exists, &expand_path, &refuse_file, &write_file, nullptr});
  std::string err, warn;
  const bool ok = !text.empty() ? loader.LoadASCIIFromString(&model, &err, &warn, text.data(), unsigned(text.size()), "")
                  : json.binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                              unsigned(bytes.size()), "")
                                : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), "");
  if (!ok) fail_gltf_parse(err, path, json);
  std::vector<Bytes> buffers;
  for (size_t i = 0; i < model.buffers.size(); ++i)
    buffers.push_back(i < own.size() && own[i] ? *own[i] : Bytes{model.buffers[i].data.data(), model.buffers[i].data.size()});
  const Reader r(path, model, std::move(buffers));
  Materials materials(r, model, ctx);
  // Keyed by the accessors a primitive reads: primitives (or meshes) that differ only in
  // material share one MeshData.
  std::map<std::vector<int>, std::shared_ptr<const MeshData>> cache;
  // A primitive's MeshData, through the cache; `slot` must outlive it.
  auto primitive = [&](int mesh, int prim, std::shared_ptr<const MeshData>& out) -> Resumable {
    const tinygltf::Primitive& p = model.meshes[size_t(mesh)].primitives[size_t(prim)];
    const std::string at = pointer("meshes", size_t(mesh)) + pointer("primitives", size_t(prim));
    // Points and lines have no area to render, strips and fans are not read: refused
    // rather than dropped, so that no part of a model goes missing silently.
    if (p.mode != -1 && p.mode != TINYGLTF_MODE_TRIANGLES)
      r.fail(at, "mode " + std::to_string(p.mode) + " (" + mode_name(p.mode) + ") is not supported: only triangles (mode 4)");
    std::vector<int> key{p.indices};
    for (const char* a : {"POSITION", "NORMAL", "TEXCOORD_0"}) {
      const auto it = p.attributes.find(a);
      key.push_back(it == p.attributes.end() ? -1 : it->second);
    }
    auto& slot = cache[key];
    if (slot) {
      out = slot;
      co_return;
    }
    auto d = std::make_shared<MeshData>();
    const auto pos = p.attributes.find("POSITION");
    if (pos == p.attributes.end()) r.fail(at, "no POSITION attribute");
    Resumable read = r.floats(pos->second, at + "/attributes/POSITION", d->positions);
    while (!co_await read) {
    }
    if (auto n = p.attributes.find("NORMAL"); n != p.attributes.end()) {
      read = r.floats(n->second, at + "/attributes/NORMAL", d->normals);
      while (!co_await read) {
      }
      if (d->normals.size() != d->positions.size()) r.fail(at, "NORMAL and POSITION counts differ");
    }
    if (auto t = p.attributes.find("TEXCOORD_0"); t != p.attributes.end()) {
      read = r.floats(t->second, at + "/attributes/TEXCOORD_0", d->uvs);
      while (!co_await read) {
      }
      if (d->uvs.size() != d->positions.size()) r.fail(at, "TEXCOORD_0 and POSITION counts differ");
      // glTF's v runs down from the image's top row, ours up from its bottom row.
      for (size_t i = 0; i < d->uvs.size(); ++i) {
        d->uvs[i].y = 1.0f - d->uvs[i].y;
        if (i % kStep == kStep - 1) co_await Work{kStep};
      }
    }
    std::vector<uint32_t> idx;
    if (p.indices >= 0) {
      read = r.indices(p.indices, at + "/indices", idx);
      while (!co_await read) {
      }
    } else {
      idx.reserve(d->positions.size());
      for (size_t i = 0; i < d->positions.size(); ++i) {
        idx.push_back(uint32_t(i));
        if (i % kStep == kStep - 1) co_await Work{kStep};
      }
    }
    if (idx.size() % 3 != 0) r.fail(at, std::to_string(idx.size()) + " indices are not whole triangles");
    d->triangles.reserve(idx.size() / 3);
    for (size_t i = 0; i + 2 < idx.size(); i += 3) {
      for (int k = 0; k < 3; ++k)
        if (idx[i + size_t(k)] >= d->positions.size())
          r.fail(p.indices >= 0 ? pointer("accessors", size_t(p.indices)) : at,
                 "index " + std::to_string(idx[i + size_t(k)]) + " is not a vertex (there are " + std::to_string(d->positions.size()) + ")");
      d->triangles.emplace_back(idx[i], idx[i + 1], idx[i + 2]);
      if (i % (3 * kStep) == 0) co_await Work{kStep};
    }
    slot = d;
    out = slot;
  };
  // Depth-first over the node tree. glTF requires a tree (no node has two parents), so a
  // node reached twice is an error: that stops cycles and exponential fan-outs alike.
  struct Item {
    int node;
    glm::mat4 parent;
    std::string from;
  };
  std::vector<Item> todo;
  std::vector<bool> seen(model.nodes.size(), false);
  const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (!model.scenes.empty()) {
    if (size_t(scene) >= model.scenes.size()) r.fail("/scene", "no scene " + std::to_string(scene));
    for (int n : model.scenes[size_t(scene)].nodes) todo.push_back({n, glm::mat4(1.0f), pointer("scenes", size_t(scene))});
  } else {
    for (size_t n = 0; n < model.nodes.size(); ++n) todo.push_back({int(n), glm::mat4(1.0f), "/nodes"});
  }
  while (!todo.empty()) {
    const Item it = todo.back();
    todo.pop_back();
    if (it.node < 0 || size_t(it.node) >= model.nodes.size()) r.fail(it.from, "no node " + std::to_string(it.node));
    const std::string at = pointer("nodes", size_t(it.node));
    if (seen[size_t(it.node)]) r.fail(at, "reached twice (the node hierarchy must be a tree)");
    seen[size_t(it.node)] = true;
    const tinygltf::Node& n = model.nodes[size_t(it.node)];
    const glm::mat4 world = it.parent * node_matrix(n);
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 4; ++k)
        if (!(std::abs(world[c][k]) <= 1e9f)) r.fail(at, "its transform is not finite or is absurdly large (> 1e9)");
    if (n.mesh >= 0) {
      if (size_t(n.mesh) >= model.meshes.size()) r.fail(at, "no mesh " + std::to_string(n.mesh));
      const tinygltf::Mesh& mesh = model.meshes[size_t(n.mesh)];
      for (size_t p = 0; p < mesh.primitives.size(); ++p) {
        std::shared_ptr<const MeshData> d;
        Resumable convert = primitive(n.mesh, int(p), d);
        while (!co_await convert) {
        }
        const std::string pat = pointer("meshes", size_t(n.mesh)) + pointer("primitives", p);
        const GltfMaterial& mat = materials.get(mesh.primitives[p].material, pat + "/material");
        if ((mat.base_color_map || mat.metallic_roughness_map || mat.normal_map) && d->uvs.empty())
          r.fail(pat, "its material has image maps, but it has no TEXCOORD_0");
        if (!d->triangles.empty()) parts.push_back({d, world, mat});
      }
    }
    for (int c : n.children) todo.push_back({c, world, at + "/children"});
  }
  if (parts.empty()) throw InputError(path, 0, "no triangles in the default scene");
}

std::vector<GltfPart> parse_gltf(const std::string& bytes, const std::string& path, const GltfResolver& resolve) {
  std::vector<GltfPart> parts;
  parse_gltf_steps(bytes, path, resolve, parts).finish();
  return parts;
}


}  // namespace pt
