// A scene made from a glTF file alone (scene/gltf_scene.h).
#include "scene/gltf_scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/file_io.h"
#include "scene/xml_walk.h"

#ifndef PT_DEFAULT_ENV_MAP
#define PT_DEFAULT_ENV_MAP "assets/env/afternoon.hdr"
#endif

namespace pt {
namespace {

std::string xml_escaped(const std::string& s) {
  std::string r;
  for (char c : s) {
    switch (c) {
      case '&': r += "&amp;"; break;
      case '<': r += "&lt;"; break;
      case '>': r += "&gt;"; break;
      case '"': r += "&quot;"; break;
      case '\'': r += "&apos;"; break;
      default: r += c;
    }
  }
  return r;
}

constexpr float kMaxPitch = 89.9f;  // the free camera's range is (-90, 90)

// Yaw and pitch (render/camera.h: forward = (-cos y cos p, sin p, -sin y cos p)) of a direction.
void aim(Camera& c, glm::vec3 f) {
  f = glm::normalize(f);
  c.pitch = std::clamp(glm::degrees(std::asin(std::clamp(f.y, -1.0f, 1.0f))), -kMaxPitch, kMaxPitch);
  c.yaw = glm::degrees(std::atan2(-f.z, -f.x));
}

}  // namespace

bool is_gltf_file(const std::string& path) { return has_extension(path, ".gltf") || has_extension(path, ".glb"); }

std::string default_env_map() { return PT_DEFAULT_ENV_MAP; }

std::string gltf_scene_text(const std::string& path, const std::string& env_map) {
  const std::string name = path.substr(path.find_last_of('/') + 1);  // beside the scene "file": the file itself
  std::string t = "<SceneLevel dotWeight=\"true\"><Camera position=\"0 0 0\"/>";
  if (!env_map.empty()) t += "<Environment map=\"" + xml_escaped(env_map) + "\"/>";
  return t + "<Render mode=\"path\"/><Objects><Mesh src=\"" + xml_escaped(name) + "\"/></Objects></SceneLevel>";
}

Camera camera_from_gltf(const GltfCamera& g) {
  Camera c;
  c.position = glm::vec3(g.transform[3]);
  aim(c, -glm::vec3(g.transform[2]));
  const glm::vec3 up = glm::vec3(g.transform[1]);
  c.up = glm::length(up) > 0.0f ? glm::normalize(up) : glm::vec3(0.0f, 1.0f, 0.0f);
  c.fov_y = glm::degrees(g.yfov);
  return c;
}

Camera framing_camera(glm::vec3 lo, glm::vec3 hi, float fov_y) {
  Camera c;
  c.fov_y = fov_y;
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
  const float distance = radius / std::sin(glm::radians(fov_y) * 0.5f);
  c.position = centre + glm::vec3(0.0f, 0.0f, distance);
  aim(c, glm::vec3(0.0f, 0.0f, -1.0f));
  c.focal_distance = distance;
  return c;
}

std::pair<glm::vec3, glm::vec3> mesh_bounds(const Scene& scene) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const Shape& s : scene.shapes) {
    const Mesh* m = s.as<Mesh>();
    if (!m) continue;
    for (const glm::vec3& v : scene.meshes[size_t(m->mesh)]->positions) {
      const glm::vec3 w = glm::vec3(m->transform * glm::vec4(v, 1.0f));
      lo = glm::min(lo, w), hi = glm::max(hi, w);
    }
  }
  return {lo, hi};
}

void set_gltf_camera(Scene& scene, const GltfCamera& g) {
  scene.punctual.insert(scene.punctual.end(), g.lights.begin(), g.lights.end());
  if (g.node >= 0 && g.perspective) {
    scene.camera = camera_from_gltf(g);
    return;
  }
  if (g.node >= 0)
    scene.warnings.push_back(scene.path + ": /nodes/" + std::to_string(g.node) +
                             ": an orthographic camera is not supported: the scene is framed instead");
  const auto [lo, hi] = mesh_bounds(scene);
  scene.camera = framing_camera(lo, hi);
}

InputError gltf_scene_error(const InputError& e, const std::string& path) {
  // "path:LINE: <Mesh>: cannot load the mesh: SRC: what" or "path:LINE: <Mesh>: what".
  std::string what = e.what();
  if (e.line() > 0) {
    const std::string lead = path + ":" + std::to_string(e.line()) + ": ";
    if (what.rfind(lead, 0) == 0) what = what.substr(lead.size());
    if (what.rfind("<Mesh>: ", 0) == 0) what = what.substr(8);
  }
  const std::string cannot = "cannot load the mesh: " + directory_of(path) + "/" + path.substr(path.find_last_of('/') + 1);
  if (what.rfind(cannot, 0) == 0) {
    // The inner error names the file as resolved, then ":LINE: " (JSON syntax) or ": ".
    what = what.substr(cannot.size());
    size_t digits = 1;
    while (digits < what.size() && std::isdigit(static_cast<unsigned char>(what[digits]))) ++digits;
    if (digits > 1 && what.compare(digits, 2, ": ") == 0) return InputError(path, std::stoi(what.substr(1, digits - 1)), what.substr(digits + 2));
    if (what.rfind(": ", 0) == 0) what = what.substr(2);
  }
  return InputError(path, 0, what);
}

}  // namespace pt
