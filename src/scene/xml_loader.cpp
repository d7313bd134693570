// The XML scene loader. Element names dispatch through the kind lists in kinds.h; each
// kind has one parse_<name> function below. Strict: unknown elements and attributes
// are errors with their line.
#include "scene/xml_loader.h"

#include <cmath>
#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>

#include <tinyxml2.h>

#include "core/error.h"
#include "core/file_io.h"
#include "core/image.h"
#include "scene/env_map.h"
#include "scene/mesh_generate.h"
#include "scene/mesh_gltf.h"
#include "scene/mesh_json.h"
#include "scene/mesh_obj.h"
#include "scene/textured_loader.h"
#include "scene/xml_attrs.h"

namespace pt {
namespace {

using tinyxml2::XMLElement;

// ---- shapes ------------------------------------------------------------------------
// Motion blur (extension): `velocity` (per unit time), or `end`, the centre at time 1
// (velocity = end - start); not both.
glm::vec3 parse_motion(XmlAttrs& a, glm::vec3 start) {
  if (a.has("velocity") && a.has("end")) a.fail("give either 'velocity' or 'end'");
  return a.has("end") ? a.vec3("end") - start : a.vec3("velocity", glm::vec3(0.0f));
}

void parse_sphere(XmlAttrs& a, Shape& s) {
  s.a = a.vec3("center");
  s.radius = a.number("radius");
  if (!(s.radius > 0.0f)) a.fail("radius must be positive");
  s.velocity = parse_motion(a, s.a);
}

void parse_box(XmlAttrs& a, Shape& s) {
  const glm::vec3 p = a.vec3("min"), q = a.vec3("max");
  // Files written for the original program give min > max on some axes: normalise.
  s.a = glm::min(p, q);
  s.b = glm::max(p, q);
  if (s.a.x == s.b.x && s.a.y == s.b.y && s.a.z == s.b.z) a.fail("box has no extent");
}

void parse_plane(XmlAttrs& a, Shape& s) {
  const glm::vec3 n = a.vec3("normal");
  const float d = a.number("d");
  const float len = glm::length(n);
  if (!(len > 0.0f) || !std::isfinite(len)) a.fail("plane normal must be non-zero");
  s.a = n / len;  // d = dot(normal, p0) scales with the normal's length
  s.radius = d / len;
}

void parse_triangle(XmlAttrs& a, Shape& s) {
  s.a = a.vec3("v0");
  s.b = a.vec3("v1");
  s.c = a.vec3("v2");
  // Extension: texture coordinates of the three vertices (used by <Textured>).
  const char* uv_names[3] = {"uv0", "uv1", "uv2"};
  for (int i = 0; i < 3; ++i)
    if (a.has(uv_names[i])) s.uv[i] = a.vec2(uv_names[i]);
  if (!(glm::length(glm::cross(s.b - s.a, s.c - s.a)) > 0.0f)) a.fail("triangle has zero area");
}

struct ShapeParser {
  const char* xml;
  ShapeKind kind;
  void (*parse)(XmlAttrs&, Shape&);
};
// Meshes are read from files by Loader::mesh, which shape() calls before this table.
void parse_mesh(XmlAttrs& a, Shape&) { a.fail("internal: <Mesh> is handled by the mesh loader"); }

constexpr ShapeParser kShapeParsers[] = {
#define PT_X(e, g, x, l, r, b) {x, ShapeKind::e, &parse_##g},
    PT_SHAPE_KINDS(PT_X)
#undef PT_X
};

// ---- materials ---------------------------------------------------------------------
struct Loader;
void parse_diffuse(Loader&, XmlAttrs&, const XMLElement*, Material&) {}
void parse_metal(Loader&, XmlAttrs& a, const XMLElement*, Material& m);
void parse_transmit(Loader&, XmlAttrs& a, const XMLElement*, Material& m);
void parse_smooth_dielectric(Loader&, XmlAttrs& a, const XMLElement*, Material& m);
void parse_emit(Loader&, XmlAttrs& a, const XMLElement* e, Material& m);
void parse_fresnel_composite(Loader& l, XmlAttrs& a, const XMLElement* e, Material& m);
void parse_textured(Loader& l, XmlAttrs& a, const XMLElement* e, Material& m);
// Procedural (solid) textures: <ChessTexture color1=".." color2=".." scale=".."/> and the
// same attributes for Worley, Perlin, Formula and FormulaPow; a Lambertian surface whose
// albedo varies in space (3D, so no uv mapping is needed).
void parse_texture(XmlAttrs& a, Material& m, glm::vec3 c1, glm::vec3 c2) {
  m.tint *= a.vec3("color1", c1);
  m.color2 = a.vec3("color2", c2);
  m.scale = a.number("scale", 10.0f);
  if (!(m.scale > 0.0f)) a.fail("'scale' must be positive");
  const glm::vec3 lo = glm::min(m.tint, m.color2), hi = glm::max(m.tint, m.color2);
  if (glm::any(glm::lessThan(lo, glm::vec3(0.0f))) || glm::any(glm::greaterThan(hi, glm::vec3(1.0f))))
    a.fail("colours must be in [0, 1]");
}
void parse_chess_texture(Loader&, XmlAttrs& a, const XMLElement*, Material& m) { parse_texture(a, m, glm::vec3(1.0f), glm::vec3(0.0f)); }
void parse_worley_texture(Loader&, XmlAttrs& a, const XMLElement*, Material& m) {
  parse_texture(a, m, glm::vec3(0.9f), glm::vec3(0.1f));
}
void parse_perlin_texture(Loader&, XmlAttrs& a, const XMLElement*, Material& m) {
  parse_texture(a, m, glm::vec3(0.9f), glm::vec3(0.1f));
}
void parse_formula_texture(Loader&, XmlAttrs& a, const XMLElement*, Material& m) {
  parse_texture(a, m, glm::vec3(1.0f), glm::vec3(0.0f));
}
void parse_formula_pow_texture(Loader&, XmlAttrs& a, const XMLElement*, Material& m) {
  parse_texture(a, m, glm::vec3(1.0f), glm::vec3(0.0f));
}
void parse_reflect(Loader&, XmlAttrs& a, const XMLElement*, Material& m) { m.tint *= a.vec3("color", glm::vec3(1.0f)); }
void parse_phong_specular(Loader&, XmlAttrs& a, const XMLElement*, Material& m) {
  m.exponent = a.number("n");
  if (!(m.exponent >= 0.0f) || m.exponent > 1e5f) a.fail("'n' must be in [0, 100000]");
  m.tint *= a.vec3("color", glm::vec3(1.0f));
}

struct MaterialParser {
  const char* xml;
  MaterialKind kind;
  void (*parse)(Loader&, XmlAttrs&, const XMLElement*, Material&);
  bool has_children;  // whether the element wraps further elements
};
constexpr MaterialParser kMaterialParsers[] = {
#define PT_X(e, g, x) \
  {x, MaterialKind::e, &parse_##g, MaterialKind::e == MaterialKind::Emit || MaterialKind::e == MaterialKind::FresnelComposite},
    PT_MATERIAL_KINDS(PT_X)
#undef PT_X
};

float positive_ior(XmlAttrs& a, const char* name, float fallback) {
  const float v = a.number(name, fallback);
  if (!(v > 0.0f) || v > 100.0f) a.fail(std::string("'") + name + "' must be in (0, 100]");
  return v;
}

void parse_metal(Loader&, XmlAttrs& a, const XMLElement*, Material& m) {
  if (a.has("iorComplex") && a.has("ior")) a.fail("give either 'iorComplex' or 'ior', not both");
  if (a.has("iorComplex")) {
    m.ior = a.vec2("iorComplex");
    if (!(m.ior.x > 0.0f) || m.ior.y < 0.0f) a.fail("'iorComplex' needs n > 0 and k >= 0");
  } else {
    m.ior = glm::vec2(positive_ior(a, "ior", 1.5f), 0.0f);
  }
  m.glossiness = a.number("glossiness", 0.0f);
  if (m.glossiness < 0.0f || m.glossiness > 1.0f) a.fail("'glossiness' must be in [0, 1]");
  m.montecarlo = a.number("montecarlo", 1.0f);
  if (m.montecarlo < 0.0f || m.montecarlo > 1.0f) a.fail("'montecarlo' must be in [0, 1]");
  m.tint *= a.vec3("color", glm::vec3(1.0f));
}

void parse_transmit(Loader&, XmlAttrs& a, const XMLElement*, Material& m) {
  m.outer_ior = positive_ior(a, "outerIor", 1.0f);
  m.inner_ior = positive_ior(a, "innerIor", 1.5f);
}

void parse_smooth_dielectric(Loader&, XmlAttrs& a, const XMLElement*, Material& m) {
  m.outer_ior = 1.0f;
  m.inner_ior = positive_ior(a, "ior", 1.5f);
  m.tint *= a.vec3("color", glm::vec3(1.0f));
}

// <Emit><Absorb intensity=".." color=".."/></Emit>: an emitter that ends the path.
void parse_emit(Loader&, XmlAttrs& a, const XMLElement* e, Material& m) {
  a.finish();
  const XMLElement* absorb = e->FirstChildElement();
  if (!absorb || std::strcmp(absorb->Name(), "Absorb") != 0 || absorb->NextSiblingElement())
    a.fail("must contain exactly one <Absorb intensity=\"..\" color=\"..\"/>");
  XmlAttrs b(absorb, a.file());
  const float intensity = b.number("intensity");
  const glm::vec3 color = b.vec3("color", glm::vec3(1.0f));
  if (intensity < 0.0f || glm::any(glm::lessThan(color, glm::vec3(0.0f)))) b.fail("intensity and color must be >= 0");
  b.finish();
  if (absorb->FirstChildElement()) b.fail("<Absorb> takes no child elements");
  m.emission = color * intensity;
}

bool has_extension(const std::string& path, const char* ext) {
  const size_t n = std::strlen(ext);
  if (path.size() <= n) return false;
  for (size_t i = 0; i < n; ++i)
    if (std::tolower(static_cast<unsigned char>(path[path.size() - n + i])) != ext[i]) return false;
  return true;
}

// What a <Mesh> reads or generates: the key of the scene's mesh cache and how to make it.
struct MeshSource {
  std::string key;
  std::string src;  // the resolved path; empty when generated
  int level = 0;    // generated: subdivisions and displacement
  float displace = 0.0f;
};

// A mesh file (or generated mesh), loaded once per scene however many <Mesh> use it.
struct MeshEntry {
  bool loaded = false;
  bool used = false;  // its files are in the scene's list
  std::vector<GltfPart> parts;
  std::vector<std::string> files;  // the files it read besides src (a glTF's buffers and images)
  std::optional<std::string> error;  // why it could not be loaded
};

// Resumable (a unit: about a triangle, vertex or byte); `e` must outlive it.
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
        }, e.parts);
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

struct Loader {
  std::string file;
  Scene scene;
  std::map<std::string, MeshEntry> mesh_files;  // loaded once per path (or generator and parameters)
  std::map<const MeshData*, std::pair<glm::vec3, glm::vec3>> mesh_boxes;  // each mesh's box, for its instances

  bool allow_files = true;  // false: any file reference is an error (fuzzing, untrusted text)
  int composite_depth = 0;  // FresnelComposites being parsed around the current element

  // A path in a scene file is relative to the scene file's folder. Every referenced file
  // passes through here, so it is also where the dependency list is collected.
  std::string resolve_path(XmlAttrs& a, const std::string& p) {
    if (!allow_files) a.fail("file references are disabled for this scene text");
    std::string r = !p.empty() && p[0] == '/' ? p : directory_of(file) + "/" + p;
    scene.files.push_back(r);
    return r;
  }

  std::shared_ptr<const EnvImage> load_env_image(XmlAttrs& a, const std::string& path) {
    try {
      return load_env_map(path);
    } catch (const std::runtime_error& e) {
      a.fail(e.what());
    }
  }


  [[noreturn]] void fail(const XMLElement* e, const std::string& what) {
    throw InputError(file, e ? e->GetLineNum() : 0, what);
  }

  // Parses one material element (and whatever it wraps); returns its index.
  int material(const XMLElement* e, glm::vec3 tint) {
    if (!std::strcmp(e->Name(), "Attenuate")) {
      XmlAttrs a(e, file);
      const glm::vec3 c = a.vec3("color");
      if (glm::any(glm::lessThan(c, glm::vec3(0.0f))) || glm::any(glm::greaterThan(c, glm::vec3(1.0f))))
        a.fail("'color' components must be in [0, 1]");
      a.finish();
      const XMLElement* inner = e->FirstChildElement();
      if (!inner || inner->NextSiblingElement()) a.fail("must wrap exactly one material");
      return material(inner, tint * c);
    }
    // <Emit intensity=".." color=".."> around a material that is not <Absorb>: a surface that
    // emits and also scatters (an extension of the seed's Emit+Absorb; the closed-form tests
    // use it for walls of albedo rho and emission Le).
    const XMLElement* first = e->FirstChildElement();
    if (!std::strcmp(e->Name(), "Emit") && first && std::strcmp(first->Name(), "Absorb") != 0) {
      XmlAttrs a(e, file);
      const float intensity = a.number("intensity");
      const glm::vec3 color = a.vec3("color", glm::vec3(1.0f));
      if (intensity < 0.0f || glm::any(glm::lessThan(color, glm::vec3(0.0f)))) a.fail("intensity and color must be >= 0");
      a.finish();
      if (first->NextSiblingElement()) a.fail("must wrap exactly one material");
      const int inner = material(first, tint);
      scene.materials[size_t(inner)].emission += color * intensity;
      return inner;
    }
    for (const MaterialParser& p : kMaterialParsers) {
      if (std::strcmp(e->Name(), p.xml) != 0) continue;
      Material m;
      m.kind = p.kind;
      m.tint = tint;
      m.line = e->GetLineNum();
      XmlAttrs a(e, file);
      p.parse(*this, a, e, m);
      a.finish();
      if (!p.has_children && e->FirstChildElement()) a.fail("takes no child elements");
      scene.materials.push_back(m);
      return int(scene.materials.size()) - 1;
    }
    fail(e, "unknown material <" + std::string(e->Name()) + ">");
  }

  // <Mesh src="file.json|.obj|.gltf|.glb" position="x y z" rotation="x y z" scale="s">
  // [material] </Mesh>: an instance of a mesh file (the seed's JSON format, Wavefront OBJ
  // or glTF 2.0), placed by scale, then rotation (degrees about x, then y, then z), then
  // position (extensions). The same file used twice is loaded once and instanced. The
  // material inside applies to every triangle; a glTF file may go without one and then
  // brings its own materials (see gltf_material).
  int mesh_index(const std::shared_ptr<const MeshData>& d) {
    for (size_t i = 0; i < scene.meshes.size(); ++i)
      if (scene.meshes[i] == d) return int(i);
    scene.meshes.push_back(d);
    return int(scene.meshes.size()) - 1;
  }

  // A glTF material as ours (docs/scene-format.md, "glTF materials"): emission, then
  // transmission, then a metal without a metallic-roughness map, then image maps as
  // <Textured>, else <Diffuse> of the base colour.
  int gltf_material(const GltfMaterial& g, XmlAttrs& a) {
    Material m;
    m.line = a.line();
    m.tint = g.base_color;
    const bool maps = g.base_color_map || g.metallic_roughness_map || g.normal_map;
    if (g.emissive != glm::vec3(0.0f)) {
      m.kind = MaterialKind::Emit;
      m.emission = g.emissive;
    } else if (g.transmission >= 0.5f) {
      m.kind = MaterialKind::SmoothDielectric;
      m.ior = glm::vec2(g.ior, 0.0f);
      m.inner_ior = g.ior;
    } else if (g.metallic >= 0.5f && !g.metallic_roughness_map) {
      m.kind = MaterialKind::Metal;  // a bright conductor tinted by the base colour
      m.ior = glm::vec2(0.15f, 3.6f);
      m.glossiness = glm::clamp(g.roughness, 0.0f, 1.0f);  // GGX alpha = roughness^2, as glTF
    } else if (maps) {
      m.kind = MaterialKind::Textured;
      auto add = [&](const GltfImage& img, const std::string& name, const LoadedImage& pixels, bool normal) {
        return add_image_map(scene, name, pixels, normal, a.line(), [&](const std::string& what) { a.fail("'" + img.name + "' " + what); });
      };
      if (g.base_color_map) m.diffuse_map = add(*g.base_color_map, g.base_color_map->name, g.base_color_map->image, false);
      if (g.normal_map) m.normal_map = add(*g.normal_map, g.normal_map->name, g.normal_map->image, true);
      if (g.metallic_roughness_map) {
        // The Phong lobe's weight s is the metalness (blue, linear) times metallicFactor, grey;
        // the lobe's exponent comes from roughnessFactor (n = 2 / alpha^2 - 2, alpha = roughness^2).
        LoadedImage s = g.metallic_roughness_map->image;
        for (size_t i = 0; i < s.rgba.size(); i += 4) s.rgba[i] = s.rgba[i + 1] = s.rgba[i + 2] = s.rgba[i + 2] * g.metallic;
        s.bits = 0;
        m.specular_map = add(*g.metallic_roughness_map, g.metallic_roughness_map->name + "#metalness*" + std::to_string(g.metallic), s, false);
      }
      const float alpha = g.roughness * g.roughness;
      m.exponent = alpha > 0.0f ? glm::clamp(2.0f / (alpha * alpha) - 2.0f, 1.0f, 1e5f) : 1e5f;
    }
    scene.materials.push_back(m);
    return int(scene.materials.size()) - 1;
  }

  // The source of a <Mesh> (also read ahead by SceneLoad, which loads it before the scene
  // is built); throws InputError for a malformed one.
  MeshSource mesh_source(XmlAttrs& a, const XMLElement* e) {
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
    return m;
  }

  void mesh(const XMLElement* e) {
    XmlAttrs a(e, file);
    const MeshSource source = mesh_source(a, e);
    const glm::vec3 position = a.vec3("position", glm::vec3(0.0f));
    const glm::vec3 rotation = a.vec3("rotation", glm::vec3(0.0f));
    const float scale = a.number("scale", 1.0f);
    if (!(scale > 0.0f)) a.fail("'scale' must be positive");
    a.finish();
    const bool gltf = has_extension(source.src, ".gltf") || has_extension(source.src, ".glb");
    const XMLElement* m = e->FirstChildElement();
    if ((!m && !gltf) || (m && m->NextSiblingElement())) a.fail(gltf ? "takes at most one material element inside" : "needs exactly one material element inside");
    MeshEntry& entry = mesh_files[source.key];
    if (!entry.loaded) load_mesh_steps(source, entry).finish();  // else SceneLoad read it ahead
    if (entry.error) a.fail("cannot load the mesh: " + *entry.error);
    if (!entry.used) scene.files.insert(scene.files.end(), entry.files.begin(), entry.files.end());
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
      Shape s;
      s.kind = ShapeKind::Mesh;
      s.mesh = mesh_index(part.mesh);
      s.transform = place * part.transform;
      s.material = shared_material >= 0 ? shared_material : gltf_material(part.material, a);
      s.line = e->GetLineNum();
      scene.shapes.push_back(s);
    }
  }

  void shape(const XMLElement* e) {
    if (!std::strcmp(e->Name(), "Mesh")) return mesh(e);
    for (const ShapeParser& p : kShapeParsers) {
      if (std::strcmp(e->Name(), p.xml) != 0) continue;
      Shape s;
      s.kind = p.kind;
      s.line = e->GetLineNum();
      XmlAttrs a(e, file);
      p.parse(a, s);
      s.dynamic = a.boolean("isDynamic", false);
      a.finish();
      const XMLElement* m = e->FirstChildElement();
      if (!m || m->NextSiblingElement()) a.fail("needs exactly one material element inside");
      s.material = material(m, glm::vec3(1.0f));
      scene.shapes.push_back(s);
      return;
    }
    fail(e, "unknown object <" + std::string(e->Name()) + ">");
  }

  void camera(const XMLElement* e) {
    XmlAttrs a(e, file);
    Camera& c = scene.camera;
    c.position = a.vec3("position");
    c.up = a.vec3("up", glm::vec3(0.0f, 1.0f, 0.0f));
    if (!(glm::length(c.up) > 0.0f)) a.fail("'up' must be non-zero");
    c.up = glm::normalize(c.up);
    c.yaw = a.number("yaw", 0.0f);
    c.pitch = a.number("pitch", 0.0f);
    if (std::abs(c.pitch) >= 90.0f) a.fail("'pitch' must be within (-90, 90) degrees");
    // Extensions: a thin lens and a shutter interval.
    c.aperture = a.number("aperture", 0.0f);
    c.focal_distance = a.number("focalDistance", 1.0f);
    c.shutter = a.number("shutter", 0.0f);
    if (c.aperture < 0.0f || !(c.focal_distance > 0.0f) || c.shutter < 0.0f)
      a.fail("'aperture' and 'shutter' must be >= 0 and 'focalDistance' > 0");
    a.finish();
    if (e->FirstChildElement()) a.fail("takes no child elements");
  }

  void light(const XMLElement* e) {
    XmlAttrs a(e, file);
    Light l;
    l.position = a.vec3("position");
    l.radius = a.number("radius", 1.0f);
    l.color = a.vec3("color", glm::vec3(1.0f));
    l.intensity = a.number("intensity", 1.0f);
    const glm::vec3 velocity = parse_motion(a, l.position);
    if (!(l.radius > 0.0f)) a.fail("'radius' must be positive");
    if (l.intensity < 0.0f || glm::any(glm::lessThan(l.color, glm::vec3(0.0f)))) a.fail("intensity and color must be >= 0");
    a.finish();
    if (e->FirstChildElement()) a.fail("takes no child elements");
    // A light is an emissive sphere that next-event estimation also samples.
    Material m;
    m.kind = MaterialKind::Emit;
    m.emission = l.radiance();
    m.line = e->GetLineNum();
    scene.materials.push_back(m);
    Shape s;
    s.kind = ShapeKind::Sphere;
    s.a = l.position;
    s.radius = l.radius;
    s.material = int(scene.materials.size()) - 1;
    s.light = int(scene.lights.size());
    s.velocity = velocity;
    s.dynamic = true;
    s.line = e->GetLineNum();
    l.shape = int(scene.shapes.size());
    scene.shapes.push_back(s);
    scene.lights.push_back(l);
  }

  // <Render bounces mode tonemap exposure samples/>: every attribute optional.
  void render_settings(const XMLElement* e) {
    XmlAttrs a(e, file);
    SceneRender& r = scene.render;
    auto integer = [&](const char* name, float lo, float hi) {
      const float v = a.number(name);
      if (!(v >= lo && v <= hi && v == std::floor(v)))
        a.fail("'" + std::string(name) + "' must be an integer in " + std::to_string(int(lo)) + ".." + std::to_string(int(hi)));
      return int(v);
    };
    if (a.has("bounces")) r.bounces = integer("bounces", 1.0f, 64.0f);
    if (a.has("samples")) r.samples = integer("samples", 0.0f, 16777216.0f);
    if (a.has("mode")) {
      RenderMode m;
      if (!render_mode_from_name(a.text("mode").c_str(), &m)) a.fail("'mode' must be path, whitted or sh");
      r.mode = m;
    }
    if (a.has("tonemap")) {
      ToneMap t;
      if (!tonemap_from_name(a.text("tonemap").c_str(), &t))
        a.fail("'tonemap' must be one of none, linear, reinhard, filmic, srgb, uncharted2, aces");
      r.tonemap = t;
    }
    if (a.has("exposure")) {
      r.exposure = a.number("exposure");
      if (!(*r.exposure > 0.0f && *r.exposure <= 1000.0f)) a.fail("'exposure' must be in (0, 1000]");
    }
    a.finish();
    if (e->FirstChildElement()) a.fail("takes no child elements");
  }

  void root(const XMLElement* r) {
    if (!r || std::strcmp(r->Name(), "SceneLevel") != 0) fail(r, "the root element must be <SceneLevel>");
    XmlAttrs a(r, file);
    scene.dot_weight = a.boolean("dotWeight", true);
    a.finish();
    bool have_camera = false, have_objects = false, have_env = false, have_render = false;
    for (const XMLElement* e = r->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const char* n = e->Name();
      if (!std::strcmp(n, "Camera")) {
        if (have_camera) fail(e, "a second <Camera>");
        have_camera = true;
        camera(e);
      } else if (!std::strcmp(n, "Light")) {
        light(e);
      } else if (!std::strcmp(n, "Environment")) {
        // Extension: <Environment color="r g b"/>, the constant radiance of rays that leave
        // the scene (default 0.5 grey, the seed's constant environment).
        if (have_env) fail(e, "a second <Environment>");
        have_env = true;
        XmlAttrs env(e, file);
        Environment& en = scene.environment;
        if (env.has("map") == env.has("color")) env.fail("give either 'color' or 'map'");
        if (env.has("color")) {
          en.color = env.vec3("color");
          if (glm::any(glm::lessThan(en.color, glm::vec3(0.0f)))) env.fail("'color' must be >= 0");
        } else {
          en.map_path = resolve_path(env, env.text("map"));
          en.map = load_env_image(env, en.map_path);
          en.rotation = env.number("rotation", 0.0f);
          en.intensity = env.number("intensity", 1.0f);
          if (en.intensity < 0.0f || en.intensity > 1e6f) env.fail("'intensity' must be in [0, 1e6]");
        }
        env.finish();
        if (e->FirstChildElement()) env.fail("takes no child elements");
      } else if (!std::strcmp(n, "Render")) {
        if (have_render) fail(e, "a second <Render>");
        have_render = true;
        render_settings(e);
      } else if (!std::strcmp(n, "Objects")) {
        if (have_objects) fail(e, "a second <Objects>");
        have_objects = true;
        XmlAttrs(e, file).finish();
        for (const XMLElement* o = e->FirstChildElement(); o; o = o->NextSiblingElement()) shape(o);
      } else {
        fail(e, "unknown element <" + std::string(n) + "> in <SceneLevel>");
      }
    }
    if (!have_camera) fail(r, "<SceneLevel> needs a <Camera>");
    if (scene.shapes.empty()) fail(r, "the scene has no objects and no lights");
  }
};

// <FresnelComposite na="1" nb="1.5"> reflective material, transmissive material
// </FresnelComposite>: the first child is taken with the dielectric Fresnel reflectance
// of the na|nb interface, the second otherwise.
void parse_fresnel_composite(Loader& l, XmlAttrs& a, const XMLElement* e, Material& m) {
  // The shader resolves nested composites in a loop of kMaxCompositeDepth levels (GLSL has
  // no recursion); a deeper one would never scatter and silently lose energy.
  constexpr int kMaxCompositeDepth = 4;
  if (l.composite_depth >= kMaxCompositeDepth) a.fail("nested more than 4 deep (the shader resolves 4 levels)");
  struct Depth {
    int& d;
    explicit Depth(int& x) : d(++x) {}
    ~Depth() { --d; }
  } depth(l.composite_depth);
  m.outer_ior = positive_ior(a, "na", 1.0f);
  m.inner_ior = positive_ior(a, "nb", 1.5f);
  const XMLElement* first = e->FirstChildElement();
  const XMLElement* second = first ? first->NextSiblingElement() : nullptr;
  if (!first || !second || second->NextSiblingElement())
    a.fail("must contain exactly two materials: a reflective one, then a transmissive one");
  m.child_a = l.material(first, m.tint);  // an Attenuate around the composite tints both
  m.child_b = l.material(second, m.tint);
}

// <Textured diffuse="wood.png" specular=".." normal=".." n="50" uvScale="su sv"
// uvOffset="ou ov"/>: see scene/textured_loader.h.
void parse_textured(Loader& l, XmlAttrs& a, const XMLElement*, Material& m) {
  parse_textured_attrs(a, l.scene, m, [&l](XmlAttrs& at, const std::string& p) { return l.resolve_path(at, p); });
}

}  // namespace

// Text between elements is never meaningful in the format: it is an error, not ignored.
static void reject_text(const tinyxml2::XMLNode* n, const std::string& path) {
  for (const tinyxml2::XMLNode* c = n->FirstChild(); c; c = c->NextSibling()) {
    if (const tinyxml2::XMLText* t = c->ToText()) {
      const char* v = t->Value();
      if (v && v[std::strspn(v, " \t\r\n")] != '\0')
        throw InputError(path, c->GetLineNum(), "unexpected text \"" + std::string(v).substr(0, 40) + "\"" +
                                                    (n->ToElement() ? " in <" + std::string(n->Value()) + ">" : ""));
    } else if (c->ToUnknown()) {
      throw InputError(path, c->GetLineNum(), "unexpected markup <" + std::string(c->Value()).substr(0, 40) + ">");
    }
    reject_text(c, path);  // depth is bounded by tinyxml2 (TINYXML2_MAX_ELEMENT_DEPTH)
  }
}

struct SceneLoad::State {
  tinyxml2::XMLDocument doc;
  Loader loader;
  std::vector<MeshSource> sources;  // in the order of the document, each key once
  std::vector<double> estimate;     // units each is expected to take
  size_t current = 0;               // the source being loaded
  size_t last_current = 0;
  double spent = 0.0;               // units given to the current source so far
  double progress = 0.0;            // never goes back
  std::string stage;
  Scene scene;
};

SceneLoad::SceneLoad(const std::string& text, const std::string& path, bool allow_files) : s_(std::make_unique<State>()) {
  // tinyxml2 stops at a NUL byte and accepts what came before: a NUL is an error here.
  const size_t nul = text.find('\0');
  if (nul != std::string::npos)
    throw InputError(path, 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(nul), '\n')),
                     "NUL byte at byte " + std::to_string(nul) + " (not a text file?)");
  tinyxml2::XMLDocument& doc = s_->doc;
  if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    // ErrorStr() is "Error=NAME ErrorID=.. Line number=N[: detail]": keep NAME and detail.
    const std::string full = doc.ErrorStr() ? doc.ErrorStr() : "";
    const size_t detail = full.find(": ", full.find("Line number="));
    const std::string why = std::string(doc.ErrorName()) + (detail == std::string::npos ? "" : full.substr(detail));
    throw InputError(path, std::max(1, doc.ErrorLineNum()), "malformed XML: " + why);
  }
  reject_text(&doc, path);
  Loader& l = s_->loader;
  l.allow_files = allow_files;
  l.file = path;
  l.scene.path = path;
  l.scene.files = {path};
  // Read ahead: every <Mesh> with a well-formed source, wherever it is. One that is not
  // (or is somewhere a mesh is not allowed) is left to the scene's own pass, which says why.
  Loader ahead;
  ahead.allow_files = allow_files;
  ahead.file = path;
  std::vector<const XMLElement*> todo{doc.RootElement()};
  while (!todo.empty()) {
    const XMLElement* e = todo.back();
    todo.pop_back();
    for (const XMLElement* c = e ? e->LastChildElement() : nullptr; c; c = c->PreviousSiblingElement()) todo.push_back(c);
    if (!e || std::strcmp(e->Name(), "Mesh") != 0) continue;
    try {
      XmlAttrs a(e, path);
      MeshSource m = ahead.mesh_source(a, e);
      if (std::none_of(s_->sources.begin(), s_->sources.end(), [&](const MeshSource& o) { return o.key == m.key; })) {
        double units = 1.0;
        if (m.src.empty()) {
          const double tris = 20.0 * std::pow(4.0, m.level);
          units = tris * (4.0 / 3.0 + 1.0) + 2.0 * (tris / 2.0);  // subdivisions, normals; displacement and uv per vertex
        } else {
          std::error_code ec;
          const auto bytes = std::filesystem::file_size(m.src, ec);
          if (!ec) units = double(bytes) * (has_extension(m.src, ".obj") ? 1.5 : 0.4);
        }
        s_->sources.push_back(std::move(m));
        s_->estimate.push_back(std::max(1.0, units));
      }
    } catch (const InputError&) {
    }
  }
  s_->stage = s_->sources.empty() ? "building the scene" : "reading the meshes";
  job_ = steps();
}

SceneLoad::~SceneLoad() = default;

Resumable SceneLoad::steps() {
  State& s = *s_;
  for (s.current = 0; s.current < s.sources.size(); ++s.current) {
    const MeshSource& m = s.sources[s.current];
    s.stage = m.src.empty() ? "generating the mesh" : "reading " + m.src.substr(m.src.find_last_of('/') + 1);
    Resumable load = load_mesh_steps(m, s.loader.mesh_files[m.key]);
    while (!co_await load) {
    }
  }
  s.stage = "building the scene";
  // After meshes, the scene's build (one step: 10-40 ms in the page for a million
  // triangles) gets a slice of its own.
  if (!s.sources.empty()) co_await EndSlice{};
  s.loader.root(s.doc.RootElement());
  s.scene = std::move(s.loader.scene);
}

bool SceneLoad::run(long work) {
  State& s = *s_;
  s.spent += double(work);
  const bool done = job_.run(work);
  if (s.current != s.last_current) s.spent = 0.0, s.last_current = s.current;  // the units went mostly to the next source
  if (!done && s.current < s.sources.size())
    s.progress = std::max(s.progress, (double(s.current) + std::min(0.99, s.spent / s.estimate[s.current])) / double(s.sources.size()));
  return done;
}

bool SceneLoad::done() const { return job_.done(); }

double SceneLoad::progress() const { return job_.done() ? 1.0 : std::min(0.99, s_->progress); }

const std::string& SceneLoad::stage() const { return s_->stage; }

Scene SceneLoad::take() { return std::move(s_->scene); }

Scene load_scene_text(const std::string& text, const std::string& path, bool allow_files) {
  SceneLoad l(text, path, allow_files);
  l.finish();
  return l.take();
}

std::string read_scene_file(const std::string& path) {
  auto text = read_file(path);
  if (!text) throw InputError(path, 0, "cannot open the scene file");
  // Meshes and images are separate files: a scene this large is not a scene.
  if (text->size() > kMaxSceneBytes)
    throw InputError(path, 0, "the scene file has " + std::to_string(text->size()) + " bytes (at most " +
                                  std::to_string(kMaxSceneBytes) + ")");
  return std::move(*text);
}

Scene load_scene_file(const std::string& path) { return load_scene_text(read_scene_file(path), path); }

}  // namespace pt
