// The scene model: plain data, filled by the XML loader, read by the packer and the UI.
// Units are the scene file's own. Radiance of emitters: see docs/scene-format.md
// ("intensity" is radiance per unit colour, the same map for lights and Emit).
#pragma once
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "lights/all.h"
#include "materials/all.h"
#include "scene/kinds.h"
#include "shapes/all.h"
#include "core/render_mode.h"
#include "core/tonemap.h"

namespace pt {

// A material: its kind's parameters (materials/<kind>.h, the variant's index is its
// MaterialKind) and what every kind has (MaterialCommon: the Attenuate tint, emission).
struct Material : MaterialCommon {
  MaterialParams params{Diffuse{}};
  int line = 0;  // scene-file line, for messages
  Material() = default;
  template <class K, class = std::enable_if_t<!std::is_same_v<std::decay_t<K>, Material> && !std::is_same_v<std::decay_t<K>, MaterialParams>>>
  Material(K kind, glm::vec3 tint_ = glm::vec3(1.0f)) : params(std::move(kind)) {  // Material m = Metal{...};
    tint = tint_;
  }
  MaterialKind kind() const { return MaterialKind(params.index()); }
  template <class K>
  K* as() { return std::get_if<K>(&params); }
  template <class K>
  const K* as() const { return std::get_if<K>(&params); }
};

// A shape: its kind's parameters (shapes/<kind>.h; the variant's index is its ShapeKind)
// and what every shape has: its material, its light, whether the UI may move it.
struct Shape {
  ShapeParams params{Sphere{}};
  int material = 0;
  int light = -1;  // index into Scene::lights when this shape is a light
  bool dynamic = false;
  int line = 0;    // scene-file line, for messages
  Shape() = default;
  template <class K, class = std::enable_if_t<!std::is_same_v<std::decay_t<K>, Shape> && !std::is_same_v<std::decay_t<K>, ShapeParams>>>
  Shape(K k, int material_ = 0) : material(material_) {  // Shape s = Box{...};
    set(std::move(k));
  }
  template <class K>
  void set(K k) {
    params = std::move(k);
  }
  ShapeKind kind() const { return ShapeKind(params.index()); }
  template <class K>
  K* as() { return std::get_if<K>(&params); }
  template <class K>
  const K* as() const { return std::get_if<K>(&params); }
};

// A <Light>: an emissive sphere. lights[0] is the one the UI controls.
struct Light {
  glm::vec3 position{0.0f};
  float radius = 1.0f;
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  int shape = -1;  // its sphere in Scene::shapes
  glm::vec3 radiance() const { return color * intensity; }
};

struct Camera {
  glm::vec3 position{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float yaw = 0.0f;    // degrees
  float pitch = 0.0f;  // degrees
  float fov_y = 45.0f;
  float aperture = 0.0f;         // lens radius (scene units); 0 = pinhole
  float focal_distance = 1.0f;   // distance of the plane in focus along the view direction
  float shutter = 0.0f;          // the shutter is open over [0, shutter] (motion blur)
};

// The view direction (unit): yaw 180 looks down +x, 90 down -z (render/camera.h's basis).
inline glm::vec3 camera_forward(const Camera& c) {
  const float y = glm::radians(c.yaw), p = glm::radians(c.pitch);
  return glm::vec3(-std::cos(y) * std::cos(p), std::sin(p), -std::sin(y) * std::cos(p));
}

// An equirectangular HDR image, rows top (theta = 0, +y) to bottom, RGBA float.
struct EnvImage {
  int width = 0, height = 0;
  std::vector<float> rgba;
};

// An image map of a <Textured> material, decoded on load: RGBA float, rows from v = 0
// (the image's bottom row) up. Colour maps (diffuse, specular) hold linear values (8/16-bit
// files are sRGB-decoded); normal maps hold tangent-space vector components in [-1, 1].
struct ImageMap {
  std::string path;     // as resolved from the scene file
  bool normal = false;  // decoded as a normal map
  int width = 0, height = 0;
  std::vector<float> rgba;
  int line = 0;         // the scene line that first referenced it, for messages
};

struct Environment {
  glm::vec3 color{0.5f};   // constant radiance seen by rays that leave the scene
  std::string map_path;    // or an equirectangular HDR map (then `color` is unused)
  std::shared_ptr<const EnvImage> map;
  float rotation = 0.0f;   // degrees about +y (the seed's slider: 0..720)
  float intensity = 1.0f;  // multiplies the map (the seed's "energy": 0..5)
};

// <Render> (extension): the render settings a scene asks for, each optional. What a
// user sets explicitly (a command-line flag, a page URL parameter) wins over it.
struct SceneRender {
  std::optional<int> bounces;       // 1..64
  std::optional<RenderMode> mode;
  std::optional<ToneMap> tonemap;
  std::optional<float> exposure;    // > 0
  std::optional<int> samples;       // the sample limit; 0: unlimited
};

struct Scene {
  std::string path;
  // The scene file and every file it references (meshes, images), as the loader opened
  // them: what `pathtracer watch` and the page's reload loop watch for changes.
  std::vector<std::string> files;
  Camera camera;
  Environment environment;
  SceneRender render;
  bool dot_weight = true;  // SceneLevel dotWeight: cosine-weighted (true) or uniform diffuse sampling
  std::vector<Light> lights;
  std::vector<PunctualLight> punctual;  // point, spot and directional lights (lights/kinds.h)
  std::vector<Shape> shapes;
  std::vector<Material> materials;
  // Mesh geometry, shared by instances (a scene copy shares it too: it is never edited).
  std::vector<std::shared_ptr<const MeshData>> meshes;
  std::vector<std::shared_ptr<const ImageMap>> images;  // Textured maps, each file once per decoding
  std::vector<std::string> warnings;  // what was read but not understood (a glTF's unsupported extensions)
};

// After editing lights[i], writes it into its sphere and emission (the data the
// renderer packs).
inline void sync_light(Scene& scene, int i) {
  const Light& l = scene.lights[size_t(i)];
  Shape& s = scene.shapes[size_t(l.shape)];
  Sphere& sphere = *s.as<Sphere>();
  sphere.center = l.position;
  sphere.radius = l.radius;
  scene.materials[size_t(s.material)].emission = l.radiance();
}

// An emitter of a samplable kind: next-event estimation samples it as a light.
inline bool is_sampled_light(const Scene& scene, const Shape& s) {
  const Material& m = scene.materials[size_t(s.material)];
  return info(s.kind()).samplable && (m.emission.x > 0.0f || m.emission.y > 0.0f || m.emission.z > 0.0f);
}

// The shapes next-event estimation samples as lights, in shape order: each
// is_sampled_light shape (the shader generator and the packer both use this list).
inline std::vector<int> sampled_light_shapes(const Scene& scene) {
  std::vector<int> out;
  for (size_t i = 0; i < scene.shapes.size(); ++i)
    if (is_sampled_light(scene, scene.shapes[i])) out.push_back(int(i));
  return out;
}

}  // namespace pt
