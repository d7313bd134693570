// glTF's nodes and meshes: the default scene's tree walked depth-first, each node's
// transform (a matrix, or translation * rotation * scale), each primitive made a MeshData
// from its accessors (gltf_accessors.cpp) once, and its material (gltf_materials.cpp).
#include "scene/gltf_nodes.h"

#include <cmath>
#include <map>
#include <memory>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace pt::gltf {
namespace {

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

// Keyed by the accessors a primitive reads: primitives (or meshes) that differ only in
// material share one MeshData.
using MeshCache = std::map<std::vector<int>, std::shared_ptr<const MeshData>>;

// A primitive's MeshData, through the cache. Resumable; every argument must outlive it.
Resumable primitive(const tinygltf::Model& model, const Reader& r, MeshCache& cache, int mesh, int prim,
                    std::shared_ptr<const MeshData>& out) {
  const tinygltf::Primitive& p = model.meshes[size_t(mesh)].primitives[size_t(prim)];
  const std::string at = pointer("meshes", size_t(mesh)) + pointer("primitives", size_t(prim));
  // Points and lines have no area to render, strips and fans are not read: refused
  // rather than dropped, so that no part of a model goes missing silently.
  if (p.mode != -1 && p.mode != TINYGLTF_MODE_TRIANGLES)
    r.fail(at, "mode " + std::to_string(p.mode) + " (" + mode_name(p.mode) + ") is not supported: only triangles (mode 4)");
  std::vector<int> key{p.indices};
  for (const char* a : {"POSITION", "NORMAL", "TEXCOORD_0", "TEXCOORD_1", "COLOR_0"}) {
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
  if (auto t = p.attributes.find("TEXCOORD_1"); t != p.attributes.end()) {
    read = r.floats(t->second, at + "/attributes/TEXCOORD_1", d->uvs1);
    while (!co_await read) {
    }
    if (d->uvs1.size() != d->positions.size()) r.fail(at, "TEXCOORD_1 and POSITION counts differ");
    for (size_t i = 0; i < d->uvs1.size(); ++i) {
      d->uvs1[i].y = 1.0f - d->uvs1[i].y;  // as TEXCOORD_0
      if (i % kStep == kStep - 1) co_await Work{kStep};
    }
  }
  if (auto c = p.attributes.find("COLOR_0"); c != p.attributes.end()) {
    const std::string cat = at + "/attributes/COLOR_0";
    // VEC3 or VEC4 (alpha 1 when VEC3); linear, in [0, 1] (a colour cannot add energy).
    if (c->second >= 0 && size_t(c->second) < model.accessors.size() && model.accessors[size_t(c->second)].type == TINYGLTF_TYPE_VEC3) {
      std::vector<glm::vec3> rgb;
      read = r.floats(c->second, cat, rgb);
      while (!co_await read) {
      }
      d->colors.reserve(rgb.size());
      for (const glm::vec3& v : rgb) d->colors.emplace_back(v, 1.0f);
    } else {
      read = r.floats(c->second, cat, d->colors);
      while (!co_await read) {
      }
    }
    if (d->colors.size() != d->positions.size()) r.fail(at, "COLOR_0 and POSITION counts differ");
    for (const glm::vec4& v : d->colors)
      if (!(glm::all(glm::greaterThanEqual(v, glm::vec4(0.0f))) && glm::all(glm::lessThanEqual(v, glm::vec4(1.0f)))))
        r.fail(pointer("accessors", size_t(c->second)), "COLOR_0 values must be in [0, 1]");
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
}

// The punctual light of node n (KHR_lights_punctual), at its world transform's origin,
// pointing down its -z (the extension: scale does not change the light's properties).
// Units: a glTF intensity (candela for point and spot, lux for directional) becomes our
// radiant intensity (irradiance) one to one (kGltfLightUnit, docs/gltf.md).
constexpr float kGltfLightUnit = 1.0f;

void node_light(const tinygltf::Model& model, const Reader& r, const tinygltf::Node& n, const glm::mat4& world,
                const std::string& at, std::vector<PunctualLight>& out) {
  const auto e = n.extensions.find("KHR_lights_punctual");
  if (e == n.extensions.end()) return;
  const std::string xat = at + "/extensions/KHR_lights_punctual";
  if (!e->second.IsObject() || !e->second.Has("light") || !e->second.Get("light").IsNumber())
    r.fail(xat, "needs the index of a light ('light')");
  const int li = e->second.Get("light").GetNumberAsInt();
  if (li < 0 || size_t(li) >= model.lights.size()) r.fail(xat + "/light", "no light " + std::to_string(li));
  const tinygltf::Light& l = model.lights[size_t(li)];
  const std::string lat = "/extensions/KHR_lights_punctual/lights/" + std::to_string(li);
  glm::vec3 color(1.0f);
  if (!l.color.empty()) {
    if (l.color.size() != 3) r.fail(lat + "/color", "must have 3 components");
    color = glm::vec3(float(l.color[0]), float(l.color[1]), float(l.color[2]));
    if (!(color.x >= 0.0f && color.y >= 0.0f && color.z >= 0.0f && color.x <= 1e9f && color.y <= 1e9f && color.z <= 1e9f))
      r.fail(lat + "/color", "must be finite and >= 0");
  }
  if (!(l.intensity >= 0.0 && l.intensity <= 1e9)) r.fail(lat + "/intensity", "must be finite and >= 0");
  if (!(l.range >= 0.0 && l.range <= 1e9)) r.fail(lat + "/range", "must be positive");
  const glm::vec3 intensity = color * float(l.intensity) * kGltfLightUnit;
  const glm::vec3 position = glm::vec3(world[3]), axis = -glm::vec3(world[2]);
  if (!(glm::length(axis) > 0.0f)) r.fail(at, "its transform has no -z axis to aim the light");
  const glm::vec3 direction = glm::normalize(axis);
  const int line = 0;
  if (l.type == "point") {
    out.push_back({PointLight{.position = position, .intensity = intensity, .range = float(l.range)}, line});
  } else if (l.type == "spot") {
    const double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
    if (!(inner >= 0.0 && inner < outer && outer <= 1.5707963268))
      r.fail(lat + "/spot", "needs 0 <= innerConeAngle < outerConeAngle <= pi/2");
    out.push_back({SpotLight{.position = position, .direction = direction, .intensity = intensity, .inner = float(inner),
                             .outer = float(outer), .range = float(l.range)},
                   line});
  } else if (l.type == "directional") {
    out.push_back({DirectionalLight{.direction = direction, .intensity = intensity}, line});
  } else {
    r.fail(lat + "/type", "must be \"point\", \"spot\" or \"directional\"");
  }
}

}  // namespace

Resumable scene_parts(const tinygltf::Model& model, const Reader& r, Materials& materials, std::vector<GltfPart>& parts,
                      GltfCamera* camera) {
  if (camera) *camera = GltfCamera{};
  MeshCache cache;
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
        Resumable convert = primitive(model, r, cache, n.mesh, int(p), d);
        while (!co_await convert) {
        }
        const std::string pat = pointer("meshes", size_t(n.mesh)) + pointer("primitives", p);
        const GltfMaterial& mat = materials.get(mesh.primitives[p].material, pat + "/material");
        if (mat.uses_texcoord(0) && d->uvs.empty()) r.fail(pat, "its material has image maps on TEXCOORD_0, but it has no TEXCOORD_0");
        if (mat.uses_texcoord(1) && d->uvs1.empty()) r.fail(pat, "its material has image maps on TEXCOORD_1, but it has no TEXCOORD_1");
        if (!d->triangles.empty()) parts.push_back({d, world, mat});
      }
    }
    if (n.camera >= 0 && camera && (camera->node < 0 || it.node < camera->node)) {
      if (size_t(n.camera) >= model.cameras.size()) r.fail(at, "no camera " + std::to_string(n.camera));
      const tinygltf::Camera& c = model.cameras[size_t(n.camera)];
      const std::string cat = pointer("cameras", size_t(n.camera));
      GltfCamera g{.node = it.node, .transform = world, .perspective = c.type == "perspective", .yfov = 0.0f};
      if (g.perspective) {
        g.yfov = float(c.perspective.yfov);
        if (!(g.yfov > 0.0f && g.yfov < 3.1415f)) r.fail(cat + "/perspective/yfov", "must be in (0, pi) radians");
      } else if (c.type != "orthographic") {
        r.fail(cat + "/type", "must be \"perspective\" or \"orthographic\"");
      }
      g.lights = std::move(camera->lights);
      *camera = g;
    }
    if (camera) node_light(model, r, n, world, at, camera->lights);
    for (int c : n.children) todo.push_back({c, world, at + "/children"});
  }
}

}  // namespace pt::gltf
