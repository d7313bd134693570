// parse_gltf_steps in the order of its work: the container (gltf_container.cpp), the
// buffers and tinygltf's parse (gltf_buffers.cpp), then the default scene's nodes into
// parts (gltf_nodes.cpp), reading accessors (gltf_accessors.cpp) and materials
// (gltf_materials.cpp) as they are used.
#include "scene/mesh_gltf.h"

#include <deque>

#include "core/error.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_buffers.h"
#include "scene/gltf_container.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_nodes.h"

namespace pt {

namespace {

// What this reader implements of glTF's extensions (docs/gltf.md).
constexpr const char* kSupportedExtensions[] = {"KHR_materials_emissive_strength", "KHR_materials_ior", "KHR_texture_transform",
                                                "KHR_materials_transmission", "KHR_materials_specular", "KHR_materials_clearcoat",
                                                "KHR_materials_sheen", "KHR_materials_volume", "KHR_lights_punctual"};

bool supported(const std::string& e) {
  for (const char* s : kSupportedExtensions)
    if (e == s) return true;
  return false;
}

}  // namespace

Resumable parse_gltf_steps(std::string bytes, std::string path, GltfResolver resolve, std::vector<GltfPart>& parts,
                           std::vector<std::string>* warnings, GltfCamera* camera) {
  parts.clear();
  const GltfJson json = gltf_json(bytes, path);
  gltf::Context ctx;
  ctx.path = path;
  ctx.resolve = &resolve;
  tinygltf::Model model;
  std::vector<gltf::Bytes> buffers;  // point into `bytes`, `files` and `model`
  std::deque<std::string> files;     // the buffer files read
  Resumable reading = gltf::read_model(bytes, json, ctx, model, buffers, files);
  while (!co_await reading) {
  }
  for (size_t i = 0; i < model.extensionsRequired.size(); ++i)
    if (!supported(model.extensionsRequired[i]))
      throw InputError(path, 0, gltf::pointer("extensionsRequired", i) + ": the extension " + model.extensionsRequired[i] +
                                    " is required and not supported");
  std::string unsupported;
  for (const std::string& e : model.extensionsUsed)
    if (!supported(e)) unsupported += (unsupported.empty() ? "" : ", ") + e;
  if (!unsupported.empty() && warnings)
    warnings->push_back(path + ": extensions not supported (their materials fall back to the core glTF material): " + unsupported);
  const gltf::Reader r(path, model, std::move(buffers));
  gltf::Materials materials(r, model, ctx);
  Resumable walk = gltf::scene_parts(model, r, materials, parts, camera);
  while (!co_await walk) {
  }
  if (parts.empty()) throw InputError(path, 0, "no triangles in the default scene");
}

std::vector<GltfPart> parse_gltf(const std::string& bytes, const std::string& path, const GltfResolver& resolve,
                                 std::vector<std::string>* warnings, GltfCamera* camera) {
  std::vector<GltfPart> parts;
  parse_gltf_steps(bytes, path, resolve, parts, warnings, camera).finish();
  return parts;
}

}  // namespace pt
