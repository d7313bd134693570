// Small scenes built in code for the transport tests.
#pragma once
#include <string>
#include <vector>

#include "render/renderer.h"
#include "scene/scene.h"

namespace pt {

inline int add_material(Scene& s, Material m) {
  s.materials.push_back(m);
  return int(s.materials.size()) - 1;
}

inline void add_box(Scene& s, glm::vec3 lo, glm::vec3 hi, int material) {
  s.shapes.push_back(Shape(Box{.min = lo, .max = hi}, material));
}

inline void add_sphere(Scene& s, glm::vec3 c, float r, int material) {
  s.shapes.push_back(Shape(Sphere{.center = c, .radius = r}, material));
}

// Camera at `pos` looking down -z (yaw 90 in the seed's convention).
inline Camera camera_looking_down_z(glm::vec3 pos) {
  Camera c;
  c.position = pos;
  c.yaw = 90.0f;
  return c;
}

// A closed room [-1,1]^3 made of six wall boxes whose inner faces all carry `wall`.
inline Scene closed_room(const Material& wall) {
  Scene s;
  s.camera = camera_looking_down_z(glm::vec3(0.0f, 0.0f, 0.5f));
  s.environment.color = glm::vec3(0.0f);
  const int m = add_material(s, wall);
  const float t = 1.1f;
  add_box(s, {-t, -t, -t}, {t, -1, t}, m);
  add_box(s, {-t, 1, -t}, {t, t, t}, m);
  add_box(s, {-t, -t, -t}, {-1, t, t}, m);
  add_box(s, {1, -t, -t}, {t, t, t}, m);
  add_box(s, {-t, -t, -t}, {t, t, -1}, m);
  add_box(s, {-t, -t, 1}, {t, t, t}, m);
  return s;
}

// A white (albedo 1) infinite plane y = 0 under a sphere light of radiance L, seen from
// above at an angle, in a black environment: the plane's radiance has a closed form.
inline Scene sphere_light_over_plane(glm::vec3 center, float radius, float L) {
  Scene s;
  s.camera.position = glm::vec3(0.0f, 6.0f, 3.0f);
  s.camera.yaw = 90.0f;
  s.camera.pitch = -60.0f;
  s.environment.color = glm::vec3(0.0f);
  Material white, emit = Emit{};
  emit.emission = glm::vec3(L);
  s.shapes.push_back(Shape(Plane{.normal = glm::vec3(0, 1, 0), .d = 0.0f}, add_material(s, white)));
  add_sphere(s, center, radius, add_material(s, emit));
  return s;
}

// A light, a sphere, a plane and a generated icosphere mesh of 20 * 4^level triangles
// (every BVH role and a mesh to read in slices), as XML: the loading tests' scene.
inline std::string mixed_scene_xml(int level) {
  return R"(<SceneLevel><Camera position="0 0 3" yaw="90" pitch="0"/>
  <Light position="1 2 2" radius="0.3" color="1 1 1" intensity="40"/><Objects>
  <Sphere center="1.5 0 0" radius="0.4"><Diffuse/></Sphere>
  <Plane normal="0 1 0" d="-1"><Attenuate color="0.7 0.7 0.7"><Diffuse/></Attenuate></Plane>
  <Mesh generate="icosphere" level=")" + std::to_string(level) + R"(" displace="0.05"><Attenuate color="0.8 0.5 0.3"><Diffuse/></Attenuate></Mesh>
</Objects></SceneLevel>)";
}

struct RenderResult {
  std::vector<float> rgba;  // mean radiance rgb, mean squared luminance a
  int spp;
  int w, h;
  Renderer::Counters counters;
};

inline RenderResult render_scene(const Scene& scene, int w, int h, int spp, RenderSettings st = {}) {
  Renderer r;
  r.resize(w, h);
  st.sample_limit = spp;
  if (st.spp_per_pass <= 1) st.spp_per_pass = 16;
  r.set_settings(st);
  r.set_scene(scene);
  while (!r.converged()) r.step();
  return {r.read_radiance(), spp, w, h, r.counters()};
}

// Mean luminance over pixels [x0,x1)x[y0,y1) and its standard error from the per-pixel
// luminance variance read_radiance gives in alpha ((sum of w_c sd_c)^2: the samples'
// luminance variance when the channels are proportional, else a bound on it).
struct Estimate {
  double mean, se;
};
inline Estimate region_mean(const RenderResult& r, int x0, int y0, int x1, int y1) {
  double sum = 0, var = 0;
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x, ++n) {
      const float* p = &r.rgba[(size_t(y) * r.w + x) * 4];
      const double l = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
      sum += l;
      var += double(p[3]) / r.spp;
    }
  return {sum / n, std::sqrt(var) / n};
}

}  // namespace pt
