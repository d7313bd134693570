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

Resumable parse_gltf_steps(std::string bytes, std::string path, GltfResolver resolve, std::vector<GltfPart>& parts) {
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
  const gltf::Reader r(path, model, std::move(buffers));
  gltf::Materials materials(r, model, ctx);
  Resumable walk = gltf::scene_parts(model, r, materials, parts);
  while (!co_await walk) {
  }
  if (parts.empty()) throw InputError(path, 0, "no triangles in the default scene");
}

std::vector<GltfPart> parse_gltf(const std::string& bytes, const std::string& path, const GltfResolver& resolve) {
  std::vector<GltfPart> parts;
  parse_gltf_steps(bytes, path, resolve, parts).finish();
  return parts;
}

}  // namespace pt
