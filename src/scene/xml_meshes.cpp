// <Mesh> elements: their sources (files read once per scene, or generated), the
// instances they place, and the materials a glTF file brings (scene/xml_walk.h).
#include <cctype>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/file_io.h"
#include "scene/mesh_generate.h"
#include "scene/mesh_json.h"
#include "scene/mesh_obj.h"
#include "scene/textured_loader.h"
#include "scene/xml_walk.h"

namespace pt {

using tinyxml2::XMLElement;

bool has_extension(const std::string& path, const char* ext) {
  const size_t n = std::strlen(ext);
  if (path.size() <= n) return false;
  for (size_t i = 0; i < n; ++i)
    if (std::tolower(static_cast<unsigned char>(path[path.size() - n + i])) != ext[i]) return false;
  return true;
}

Resumable load_mesh_steps(MeshSource m, MeshEntry& e) {
  e = MeshEntry();
  try {
    auto d = std::make_shared<MeshData>();
    if (m.src.empty()) {
      Resumable g = generate_icosphere_steps(m.level, m.displace, *d);
      while (!co_await g) {
      }
      e.parts.push_back({std::move(d), glm::mat4(1.0f), {}});
    } else {
      std::optional<std::string> bytes;
      Resumable read = read_file_steps(m.src, bytes);
      while (!co_await read) {
      }
      if (!bytes) throw InputError(m.src, 0, "cannot open the mesh file");
      if (has_extension(m.src, ".gltf") || has_extension(m.src, ".glb")) {
        // The glTF's own buffer and image files are dependencies too (watch reloads on their change).
        Resumable g = parse_gltf_steps(std::move(*bytes), m.src, [&e](const std::string& f) {
          e.files.push_back(f);
          return f;
        }, e.parts, &e.warnings, &e.camera);
        while (!co_await g) {
        }
      } else if (has_extension(m.src, ".obj")) {
        Resumable o = parse_mesh_obj_steps(std::move(*bytes), m.src, *d);
        while (!co_await o) {
        }
        e.parts.push_back({std::move(d), glm::mat4(1.0f), {}});
      } else {
        e.parts.push_back({std::make_shared<const MeshData>(parse_mesh_json(*bytes, m.src)), glm::mat4(1.0f), {}});  // the seed's small meshes: one step
      }
    }
  } catch (const InputError& err) {
    e.parts.clear();
    e.error = err.what();
  }
  e.loaded = true;
}


int Loader::mesh_index(const std::shared_ptr<const MeshData>& d) {
  for (size_t i = 0; i < scene.meshes.size(); ++i)
    if (scene.meshes[i] == d) return int(i);
  scene.meshes.push_back(d);
  return int(scene.meshes.size()) - 1;
}

int Loader::gltf_material(const GltfMaterial& g, XmlAttrs& a) {
  Material m;
  m.line = a.line();
  m.emission = g.emissive;  // with the base colour: both shade (docs/gltf.md)
  GltfPbr p;
  p.baseColor = g.base_color;
  p.alpha = g.alpha;
  p.metallic = g.metallic;
  p.roughness = g.roughness;
  p.ior = g.ior;
  p.alphaMode = g.alpha_mode;
  p.alphaCutoff = g.alpha_cutoff;
  p.doubleSided = g.double_sided;
  p.volume = g.volume;  // KHR_materials_volume: the transmission refracts into it (materials/gltf_pbr.h)
  p.sigma = sigma_from(g.attenuation_color, g.attenuation_distance);
  // The maps' images, decoded once per scene and decoding: colour maps sRGB (alpha linear),
  // the metallic-roughness map linear, the normal map onto [-1, 1].
  enum Decoding { kSrgb, kLinear, kNormal };
  auto add = [&](const GltfTexture& t, Decoding d, GltfMap& out) {
    if (!t) return;
    const GltfImage& img = *t.image;
    auto fail = [&](const std::string& what) { a.fail("'" + img.name + "' " + what); };
    out.image = d == kLinear ? add_linear_image_map(scene, img.name, img.image, a.line(), fail)
                             : add_image_map(scene, img.name, img.image, d == kNormal, a.line(), fail);
    out.tex_coord = t.tex_coord;
    out.wrap_s = t.wrap_s;
    out.wrap_t = t.wrap_t;
    out.nearest = t.nearest;
    out.offset = t.offset;
    out.scale = t.scale;
    out.rotation = t.rotation;
    out.strength = t.strength;
  };
  add(g.base_color_map, kSrgb, p.base);
  add(g.metallic_roughness_map, kLinear, p.metal_rough);
  add(g.normal_map, kNormal, p.normal);
  add(g.emissive_map, kSrgb, p.emissive);
  p.lobes = GltfLobes{.specular = g.specular, .specularColor = g.specular_color, .clearcoat = g.clearcoat,
                      .clearcoatRoughness = g.clearcoat_roughness, .sheenColor = g.sheen_color, .sheenRoughness = g.sheen_roughness,
                      .transmission = g.transmission};
  add(g.specular_map, kLinear, p.specular);  // its alpha
  add(g.specular_color_map, kSrgb, p.specular_color);
  add(g.clearcoat_map, kLinear, p.clearcoat);
  add(g.clearcoat_roughness_map, kLinear, p.clearcoat_roughness);
  add(g.clearcoat_normal_map, kNormal, p.clearcoat_normal);
  add(g.sheen_color_map, kSrgb, p.sheen_color);
  add(g.sheen_roughness_map, kLinear, p.sheen_roughness);  // its alpha
  add(g.transmission_map, kLinear, p.transmission);
  m.params = p;
  scene.materials.push_back(m);
  return int(scene.materials.size()) - 1;
}

MeshSource Loader::mesh_source(XmlAttrs& a, const XMLElement* e) {
  MeshSource m;
  if (e->Attribute("generate") == nullptr) {
    m.src = m.key = resolve_path(a, a.text("src"));
    if (!has_extension(m.src, ".gltf") && !has_extension(m.src, ".glb") && !has_extension(m.src, ".obj") && !has_extension(m.src, ".json"))
      a.fail("'src' must be a .json (the seed's format), .obj, .gltf or .glb mesh");
    return m;
  }
  if (e->Attribute("src")) a.fail("takes 'src' or 'generate', not both");
  if (a.text("generate") != "icosphere") a.fail("'generate' must be \"icosphere\"");
  // Checked as a number before the conversion: a float beyond int's range does not convert.
  const float lf = a.number("level", 5.0f);
  m.displace = a.number("displace", 0.0f);
  if (!(lf >= 0.0f && lf <= 9.0f && lf == std::floor(lf))) a.fail("'level' must be an integer in 0..9 (20 * 4^level triangles)");
  m.level = int(lf);
  if (!(m.displace >= 0.0f && m.displace < 0.5f)) a.fail("'displace' must be in [0, 0.5)");
  m.key = "generate:icosphere:" + std::to_string(m.level) + ":" + std::to_string(m.displace);
  if (generated_triangle_budget >= 0) {
    generated[m.key] = 20ll << (2 * m.level);  // 20 * 4^level; a source used twice is made once
    long long total = 0;
    for (const auto& g : generated) total += g.second;
    if (total > generated_triangle_budget)
      a.fail("the generated meshes make " + std::to_string(total) + " triangles, over this load's budget of " +
             std::to_string(generated_triangle_budget));
  }
  return m;
}

void Loader::mesh(const XMLElement* e) {
  XmlAttrs a(e, file);
  const MeshSource source = mesh_source(a, e);
  const glm::vec3 position = a.vec3("position", glm::vec3(0.0f));
  const glm::vec3 rotation = a.vec3("rotation", glm::vec3(0.0f));
  const float scale = a.number("scale", 1.0f);
  if (!(scale > 0.0f)) a.fail("'scale' must be positive");
  const glm::vec3 velocity = parse_motion(a, position);  // motion blur: the instance's translation
  a.finish();
  const bool gltf = has_extension(source.src, ".gltf") || has_extension(source.src, ".glb");
  const XMLElement* m = e->FirstChildElement();
  if ((!m && !gltf) || (m && m->NextSiblingElement())) a.fail(gltf ? "takes at most one material element inside" : "needs exactly one material element inside");
  MeshEntry& entry = mesh_files[source.key];
  if (!entry.loaded) load_mesh_steps(source, entry).finish();  // else SceneLoad read it ahead
  if (entry.error) a.fail("cannot load the mesh: " + *entry.error);
  if (!entry.used) scene.files.insert(scene.files.end(), entry.files.begin(), entry.files.end());
  if (!entry.used) scene.warnings.insert(scene.warnings.end(), entry.warnings.begin(), entry.warnings.end());
  entry.used = true;
  const std::vector<GltfPart>& parts = entry.parts;
  glm::mat4 place = glm::translate(glm::mat4(1.0f), position);
  place = glm::rotate(place, glm::radians(rotation.z), glm::vec3(0, 0, 1));
  place = glm::rotate(place, glm::radians(rotation.y), glm::vec3(0, 1, 0));
  place = glm::rotate(place, glm::radians(rotation.x), glm::vec3(1, 0, 0));
  place = glm::scale(place, glm::vec3(scale));
  const int shared_material = m ? material(m, glm::vec3(1.0f)) : -1;
  for (const GltfPart& part : parts) {
    const glm::mat4 world = place * part.transform;
    auto within = [&](glm::vec3 v) {  // false for NaN too
      return glm::all(glm::lessThanEqual(glm::abs(glm::vec3(world * glm::vec4(v, 1.0f))), glm::vec3(kMaxMagnitude)));
    };
    // The corners of the mesh's box bound every vertex (an affine map's extremes over a
    // box are at its corners): each vertex is looked at only when a corner is out.
    auto [box, fresh] = mesh_boxes.try_emplace(part.mesh.get(), glm::vec3(INFINITY), glm::vec3(-INFINITY));
    if (fresh)  // once per mesh, not per instance
      for (const glm::vec3& v : part.mesh->positions) box->second.first = glm::min(box->second.first, v), box->second.second = glm::max(box->second.second, v);
    const glm::vec3 lo = box->second.first, hi = box->second.second;
    bool corners_within = true;
    for (int c = 0; c < 8; ++c) corners_within &= within(glm::vec3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z));
    if (!corners_within)
      for (const glm::vec3& v : part.mesh->positions)
        if (!within(v)) a.fail("scaled and moved, the mesh has a vertex beyond 1e9");
    Shape s(Mesh{.mesh = mesh_index(part.mesh), .transform = place * part.transform, .velocity = velocity});
    s.material = shared_material >= 0 ? shared_material : gltf_material(part.material, a);
    s.line = e->GetLineNum();
    scene.shapes.push_back(s);
  }
}

}  // namespace pt
