// The materials of a glTF as GltfMaterial (mesh_gltf.h), read once per material and with
// their image maps decoded once per image, only those a part uses (gltf_materials.cpp).
#pragma once
#include <map>
#include <memory>
#include <string>

#include "scene/gltf_accessors.h"
#include "scene/gltf_buffers.h"
#include "scene/mesh_gltf.h"

namespace pt::gltf {

// Factors outside their ranges would make a material that creates energy or a NaN in
// the shader: refused, with the material's pointer.
class Materials {
 public:
  Materials(const Reader& r, const tinygltf::Model& m, const Context& c) : r_(r), m_(m), c_(c) {}

  // Material `index` (glTF's default for -1); `user` names the reference in messages.
  const GltfMaterial& get(int index, const std::string& user);

 private:
  GltfMaterial read(int index);
  void read_lobes(const tinygltf::ExtensionMap& ext, const std::string& at, GltfMaterial& g);
  std::shared_ptr<const GltfImage> map(int texture, const std::string& at);
  // A textureInfo (index, texCoord, KHR_texture_transform) with its texture's sampler.
  GltfTexture info(int texture, int tex_coord, const tinygltf::ExtensionMap& ext, const std::string& at);

  const Reader& r_;
  const tinygltf::Model& m_;
  const Context& c_;
  std::map<int, std::unique_ptr<GltfMaterial>> materials_;
  std::map<int, std::shared_ptr<const GltfImage>> images_;
};

}  // namespace pt::gltf
