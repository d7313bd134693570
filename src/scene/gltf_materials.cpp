// glTF's metallic-roughness materials (with KHR_materials_emissive_strength,
// _transmission, _ior, _specular, _clearcoat and _sheen) as GltfMaterial, and their image
// maps: from a bufferView, a data: URI or a file through the resolver, decoded by our own
// image reader.
#include "scene/gltf_materials.h"

#include <algorithm>
#include <cmath>
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
    // The extension's range: ior >= 1, or exactly 0 (the Fresnel term is 1 at every angle,
    // for the specular-glossiness workflow: f0 = ((0 - 1) / (0 + 1))^2 = 1 gives that).
    if (!(ior == 0.0 || (ior >= 1.0 && ior <= 100.0))) r_.fail(at + "/extensions/KHR_materials_ior", "ior must be 0 or in [1, 100]");
    g.ior = float(ior);
  }
  if (pbr.baseColorFactor.size() == 4) g.alpha = unit(pbr.baseColorFactor[3], "baseColorFactor");
  if (m.alphaMode == "MASK") g.alpha_mode = 1;
  else if (m.alphaMode == "BLEND") g.alpha_mode = 2;
  else if (!m.alphaMode.empty() && m.alphaMode != "OPAQUE") r_.fail(at + "/alphaMode", "must be OPAQUE, MASK or BLEND");
  if (!(m.alphaCutoff >= 0.0)) r_.fail(at + "/alphaCutoff", "must be >= 0");
  g.alpha_cutoff = float(std::min(m.alphaCutoff, 1.0));  // above 1 nothing passes, as at 1 (alpha <= 1)
  g.double_sided = m.doubleSided;
  g.base_color_map = info(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions,
                          at + "/pbrMetallicRoughness/baseColorTexture");
  g.metallic_roughness_map = info(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                                  pbr.metallicRoughnessTexture.extensions, at + "/pbrMetallicRoughness/metallicRoughnessTexture");
  g.normal_map = info(m.normalTexture.index, m.normalTexture.texCoord, m.normalTexture.extensions, at + "/normalTexture");
  if (g.normal_map) {
    if (!(std::abs(m.normalTexture.scale) <= 100.0)) r_.fail(at + "/normalTexture/scale", "must be in [-100, 100]");
    g.normal_map.strength = float(m.normalTexture.scale);
  }
  g.emissive_map = info(m.emissiveTexture.index, m.emissiveTexture.texCoord, m.emissiveTexture.extensions, at + "/emissiveTexture");
  read_lobes(m.extensions, at, g);
  // Read (it must be valid) and not used: a path tracer computes the occlusion (docs/gltf.md).
  g.occlusion_map = info(m.occlusionTexture.index, m.occlusionTexture.texCoord, m.occlusionTexture.extensions, at + "/occlusionTexture");
  return g;
}

// KHR_materials_specular, _clearcoat and _sheen: their factors (strictly in range) and maps.
void Materials::read_lobes(const tinygltf::ExtensionMap& ext, const std::string& at, GltfMaterial& g) {
  auto find = [&](const char* name) -> const tinygltf::Value* {
    auto e = ext.find(name);
    return e == ext.end() ? nullptr : &e->second;
  };
  auto number = [&](const tinygltf::Value& v, const char* key, float fallback, float hi, const std::string& xat) {
    if (!v.Has(key)) return fallback;
    const tinygltf::Value& n = v.Get(key);
    if (!n.IsNumber() || !(n.GetNumberAsDouble() >= 0.0 && n.GetNumberAsDouble() <= hi))
      r_.fail(xat + "/" + key, "must be a number in [0, " + std::to_string(int(hi)) + "]");
    return float(n.GetNumberAsDouble());
  };
  auto color = [&](const tinygltf::Value& v, const char* key, glm::vec3 fallback, float hi, const std::string& xat) {
    if (!v.Has(key)) return fallback;
    const tinygltf::Value& c = v.Get(key);
    if (!c.IsArray() || c.ArrayLen() != 3) r_.fail(xat + "/" + key, "must be an array of 3 numbers");
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) {
      const tinygltf::Value& n = c.Get(i);
      if (!n.IsNumber() || !(n.GetNumberAsDouble() >= 0.0 && n.GetNumberAsDouble() <= hi))
        r_.fail(xat + "/" + key + "/" + std::to_string(i), "must be a number in [0, " + std::to_string(int(hi)) + "]");
      out[i] = float(n.GetNumberAsDouble());
    }
    return out;
  };
  // An extension's textureInfo (index, texCoord, its own KHR_texture_transform).
  auto map = [&](const tinygltf::Value& v, const char* key, const std::string& xat, float* scale = nullptr) {
    if (!v.Has(key)) return GltfTexture{};
    const tinygltf::Value& t = v.Get(key);
    const std::string tat = xat + "/" + key;
    if (!t.IsObject() || !t.Has("index") || !t.Get("index").IsInt()) r_.fail(tat, "must be a textureInfo with an integer index");
    const int tex_coord = t.Has("texCoord") && t.Get("texCoord").IsInt() ? t.Get("texCoord").GetNumberAsInt() : 0;
    tinygltf::ExtensionMap inner;
    if (t.Has("extensions") && t.Get("extensions").IsObject())
      for (const std::string& k : t.Get("extensions").Keys()) inner[k] = t.Get("extensions").Get(k);
    GltfTexture out = info(t.Get("index").GetNumberAsInt(), tex_coord, inner, tat);
    if (scale && t.Has("scale")) {
      const tinygltf::Value& n = t.Get("scale");
      if (!n.IsNumber() || !(std::abs(n.GetNumberAsDouble()) <= 100.0)) r_.fail(tat + "/scale", "must be in [-100, 100]");
      *scale = float(n.GetNumberAsDouble());
    }
    return out;
  };
  if (const tinygltf::Value* v = find("KHR_materials_specular")) {
    const std::string xat = at + "/extensions/KHR_materials_specular";
    g.specular = number(*v, "specularFactor", 1.0f, 1.0f, xat);
    g.specular_color = color(*v, "specularColorFactor", glm::vec3(1.0f), 1000.0f, xat);
    g.specular_map = map(*v, "specularTexture", xat);
    g.specular_color_map = map(*v, "specularColorTexture", xat);
  }
  if (const tinygltf::Value* v = find("KHR_materials_clearcoat")) {
    const std::string xat = at + "/extensions/KHR_materials_clearcoat";
    g.clearcoat = number(*v, "clearcoatFactor", 0.0f, 1.0f, xat);
    g.clearcoat_roughness = number(*v, "clearcoatRoughnessFactor", 0.0f, 1.0f, xat);
    g.clearcoat_map = map(*v, "clearcoatTexture", xat);
    g.clearcoat_roughness_map = map(*v, "clearcoatRoughnessTexture", xat);
    float scale = 1.0f;
    g.clearcoat_normal_map = map(*v, "clearcoatNormalTexture", xat, &scale);
    g.clearcoat_normal_map.strength = scale;
  }
  if (const tinygltf::Value* v = find("KHR_materials_transmission"))
    g.transmission_map = map(*v, "transmissionTexture", at + "/extensions/KHR_materials_transmission");
  // KHR_materials_volume: a volume (not a thin wall) where thicknessFactor > 0 (the
  // extension's rule), and its absorption (Beer-Lambert inside: attenuationColor is what
  // is left after attenuationDistance). The thickness itself is a rasterizer's stand-in
  // for the geometry, which a path tracer traces (docs/gltf.md).
  if (const tinygltf::Value* v = find("KHR_materials_volume")) {
    const std::string xat = at + "/extensions/KHR_materials_volume";
    g.volume = number(*v, "thicknessFactor", 0.0f, 1e6f, xat) > 0.0f;
    g.attenuation_color = color(*v, "attenuationColor", glm::vec3(1.0f), 1.0f, xat);
    if (v->Has("attenuationDistance")) {
      const tinygltf::Value& d = v->Get("attenuationDistance");
      if (!d.IsNumber() || !(d.GetNumberAsDouble() > 0.0 && d.GetNumberAsDouble() <= 1e30))
        r_.fail(xat + "/attenuationDistance", "must be a number > 0");
      g.attenuation_distance = float(d.GetNumberAsDouble());
    }
  }
  if (const tinygltf::Value* v = find("KHR_materials_sheen")) {
    const std::string xat = at + "/extensions/KHR_materials_sheen";
    g.sheen_color = color(*v, "sheenColorFactor", glm::vec3(0.0f), 1.0f, xat);
    g.sheen_roughness = number(*v, "sheenRoughnessFactor", 0.0f, 1.0f, xat);
    g.sheen_color_map = map(*v, "sheenColorTexture", xat);
    g.sheen_roughness_map = map(*v, "sheenRoughnessTexture", xat);
  }
}

GltfTexture Materials::info(int texture, int tex_coord, const tinygltf::ExtensionMap& ext, const std::string& at) {
  GltfTexture t;
  if (texture < 0) return t;
  t.image = map(texture, at);
  t.tex_coord = tex_coord;
  if (auto x = ext.find("KHR_texture_transform"); x != ext.end()) {
    const tinygltf::Value& v = x->second;
    const std::string xat = at + "/extensions/KHR_texture_transform";
    auto number = [&](const tinygltf::Value& n, const char* what) {
      if (!n.IsNumber() || !(std::abs(n.GetNumberAsDouble()) <= 1e6)) r_.fail(xat, std::string(what) + " must be a number of magnitude <= 1e6");
      return float(n.GetNumberAsDouble());
    };
    auto pair = [&](const char* name, glm::vec2 fallback) {
      if (!v.Has(name)) return fallback;
      const tinygltf::Value& p = v.Get(name);
      if (!p.IsArray() || p.ArrayLen() != 2) r_.fail(xat, std::string(name) + " must be an array of 2 numbers");
      return glm::vec2(number(p.Get(0), name), number(p.Get(1), name));
    };
    t.offset = pair("offset", glm::vec2(0.0f));
    t.scale = pair("scale", glm::vec2(1.0f));
    if (v.Has("rotation")) t.rotation = number(v.Get("rotation"), "rotation");
    if (v.Has("texCoord")) t.tex_coord = int(number(v.Get("texCoord"), "texCoord"));
  }
  if (t.tex_coord != 0 && t.tex_coord != 1) r_.fail(at, "texCoord " + std::to_string(t.tex_coord) + " is not supported (TEXCOORD_0 and _1 are)");
  const int sampler = m_.textures[size_t(texture)].sampler;
  if (sampler >= 0) {
    if (size_t(sampler) >= m_.samplers.size()) r_.fail(pointer("textures", size_t(texture)), "no sampler " + std::to_string(sampler));
    const tinygltf::Sampler& s = m_.samplers[size_t(sampler)];
    auto wrap = [&](int mode, const char* what) {
      if (mode == TINYGLTF_TEXTURE_WRAP_REPEAT) return 0;
      if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return 1;
      if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return 2;
      r_.fail(pointer("samplers", size_t(sampler)), std::string(what) + " " + std::to_string(mode) + " is not a wrap mode");
    };
    t.wrap_s = wrap(s.wrapS, "wrapS");
    t.wrap_t = wrap(s.wrapT, "wrapT");
    t.nearest = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
  }
  return t;
}

std::shared_ptr<const GltfImage> Materials::map(int texture, const std::string& at) {
  if (texture < 0) return nullptr;
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
