// glTF's metallic-roughness materials (with KHR_materials_emissive_strength,
// _transmission and _ior) as GltfMaterial, and their image maps: from a bufferView, a
// data: URI or a file through the resolver, decoded by our own image reader.
#include "scene/gltf_materials.h"

#include <optional>

#include "core/file_io.h"
#include "core/image.h"

namespace pt::gltf {
namespace {

// An image file's bytes; false with *why when refused or unreadable.
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

}  // namespace

const GltfMaterial& Materials::get(int index, const std::string& user) {
  static const GltfMaterial kDefault;
  if (index < 0) return kDefault;
  if (size_t(index) >= m_.materials.size()) r_.fail(user, "no material " + std::to_string(index));
  auto& slot = materials_[index];
  if (!slot) slot = std::make_unique<GltfMaterial>(read(index));
  return *slot;
}

GltfMaterial Materials::read(int index) {
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

std::shared_ptr<const GltfImage> Materials::map(int texture, int tex_coord, const std::string& at) {
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
  } else if (!read_image_file(c_, url_decode(img.uri), &bytes, &why)) {
    r_.fail(where, why);
  }
  auto out = std::make_shared<GltfImage>();
  out->name = c_.path + "#" + where;
  if (!decode_image(bytes, &out->image, &why)) r_.fail(where, why);
  slot = out;
  return slot;
}

}  // namespace pt::gltf
