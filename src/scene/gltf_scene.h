// A scene made from a glTF file alone (`pathtracer render model.glb`, the page's
// ?scene=model.glb or a dropped file; docs/gltf.md): the file as one <Mesh src> brings
// its meshes and materials exactly as in an XML scene, with the default environment
// (kDefaultEnvMap), path mode, the camera: the glTF's first camera node, else one
// that frames the scene's bounds, and its KHR_lights_punctual lights. SceneLoad (scene/xml_loader.h) reads it in slices like
// any scene: it loads the generated scene text, then set_gltf_camera.
#pragma once
#include <string>
#include <utility>

#include <glm/glm.hpp>

#include "core/error.h"
#include "scene/mesh_gltf.h"
#include "scene/scene.h"

namespace pt {

// .gltf or .glb (any case): a scene of the file alone, not an XML scene.
bool is_gltf_file(const std::string& path);

// The shipped HDR map a glTF scene is lit by (assets/env/afternoon.hdr; the page's
// /assets/env): a daylight sky with a sun, the map the glTF test scenes use. Where the
// file is missing, the scene has the constant environment instead, with a warning.
std::string default_env_map();

// The XML scene SceneLoad reads for the glTF file `path`; its camera is a placeholder
// that set_gltf_camera replaces.
std::string gltf_scene_text(const std::string& path, const std::string& env_map);

// The camera of a glTF camera node: at the node's origin, looking down its -z with its +y
// up, vertical field of view yfov (its aspectRatio is not used: the image's own aspect
// is; znear and zfar are not used: a path tracer has no clip planes). A pitch beyond
// +-89.9 degrees (the free camera's range) is clamped there.
Camera camera_from_gltf(const GltfCamera& g);

// A camera that frames the box [lo, hi]: it looks along -z at the centre of the box's
// bounding sphere from the distance where that sphere just fits the vertical field of
// view (fov_y degrees), so the whole box is in the image whenever its aspect is >= 1.
Camera framing_camera(glm::vec3 lo, glm::vec3 hi, float fov_y = 45.0f);

// The world-space box of every mesh vertex of the scene (lo > hi when it has none).
std::pair<glm::vec3, glm::vec3> mesh_bounds(const Scene& scene);

// The scene's camera: `g` when it is a perspective camera node, else the framing camera
// (an orthographic camera is warned about and replaced by it); and the glTF's punctual
// lights (g.lights, KHR_lights_punctual) join the scene's.
void set_gltf_camera(Scene& scene, const GltfCamera& g);

// An error met while loading the generated scene, as the glTF file's own: the generated
// text's line and element dropped ("model.glb: /accessors/3: ...").
InputError gltf_scene_error(const InputError& e, const std::string& path);

}  // namespace pt
