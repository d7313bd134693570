// The XML loader's document walk, shared by its files: the Loader builds a Scene from a
// parsed document (xml_walk.cpp: the scene's elements, its shapes and its materials, whose
// kinds parse themselves: shapes/<kind>.h, materials/<kind>.h; xml_meshes.cpp: <Mesh> files and glTF
// materials); SceneLoad (xml_loader.cpp) drives it. Internal to scene/.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <tinyxml2.h>

#include "core/resumable.h"
#include "core/xml_attrs.h"
#include "scene/mesh_gltf.h"
#include "scene/scene.h"

namespace pt {

bool has_extension(const std::string& path, const char* ext);

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
  std::vector<std::string> warnings;  // a glTF's unsupported extensions (parse_gltf)
  GltfCamera camera;                  // a glTF's first camera node (for a scene of the file alone)
  std::optional<std::string> error;  // why it could not be loaded
};

// Reads or generates one mesh source into `e` (which must outlive it). Resumable (a unit:
// about a triangle, vertex or byte).
Resumable load_mesh_steps(MeshSource m, MeshEntry& e);

struct Loader final : MaterialLoader {
  std::string file;
  Scene scene;
  std::map<std::string, MeshEntry> mesh_files;  // loaded once per path (or generator and parameters)
  std::map<const MeshData*, std::pair<glm::vec3, glm::vec3>> mesh_boxes;  // each mesh's box, for its instances

  bool allow_files = true;  // false: any file reference is an error (fuzzing, untrusted text)
  long long generated_triangle_budget = -1;  // >= 0: a cap on generated triangles (the fuzzer's)
  std::map<std::string, long long> generated;  // generated sources so far, by key: their triangles
  int composite_depth_ = 0;  // composites being parsed around the current element (child())

  // A path in a scene file is relative to the scene file's folder. Every referenced file
  // passes through here, so it is also where the dependency list is collected.
  std::string resolve_path(XmlAttrs& a, const std::string& p);
  std::shared_ptr<const EnvImage> load_env_image(XmlAttrs& a, const std::string& path);
  [[noreturn]] void fail(const tinyxml2::XMLElement* e, const std::string& what);
  // Parses one material element (and whatever it wraps); returns its index.
  int material(const tinyxml2::XMLElement* e, glm::vec3 tint);
  // The index of mesh data d in the scene's list (added once).
  int mesh_index(const std::shared_ptr<const MeshData>& d);
  // A glTF material as ours (docs/gltf.md): GltfPbr (the glTF BSDF with its maps), or a
  // stand-in SmoothDielectric for transmission >= 0.5.
  int gltf_material(const GltfMaterial& g, XmlAttrs& a);
  // The source of a <Mesh> (also read ahead by SceneLoad, which loads it before the scene
  // is built); throws InputError for a malformed one.
  MeshSource mesh_source(XmlAttrs& a, const tinyxml2::XMLElement* e);
  // <Mesh src="file.json|.obj|.gltf|.glb" position="x y z" rotation="x y z" scale="s">
  // [material] </Mesh>: an instance of a mesh file (the seed's JSON format, Wavefront OBJ
  // or glTF 2.0), placed by scale, then rotation (degrees about x, then y, then z), then
  // position (extensions). The same file used twice is loaded once and instanced. The
  // material inside applies to every triangle; a glTF file may go without one and then
  // brings its own materials (see gltf_material).
  void mesh(const tinyxml2::XMLElement* e);
  void shape(const tinyxml2::XMLElement* e);
  void camera(const tinyxml2::XMLElement* e);
  void light(const tinyxml2::XMLElement* e);
  // <Render bounces mode tonemap exposure samples/>: every attribute optional.
  void render_settings(const tinyxml2::XMLElement* e);
  void root(const tinyxml2::XMLElement* r);
  void environment(const tinyxml2::XMLElement* e);

  // MaterialLoader: what a material kind's parse asks of the scene (materials/material.h).
  int child(const tinyxml2::XMLElement* e, glm::vec3 tint) override;
  int image_map(XmlAttrs& a, const char* attr, bool normal) override;
  int image_map_linear(XmlAttrs& a, const char* attr) override;
  int composite_depth() const override { return composite_depth_; }
};

}  // namespace pt
