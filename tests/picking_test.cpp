// Picking: pick() at known pixels of a reference scene (CPU only), the CPU ray cast
// against the production GLSL (camera rays and scene_intersect) for every pixel, the
// dependency list of a scene, and selection edits that re-upload without recompiling.
#include <catch2/catch.hpp>

#include <algorithm>

#include "app/picking.h"
#include "app/selection.h"
#include "core/image.h"
#include "gl_context.h"
#include "glsl_harness.h"
#include "render/camera.h"
#include "render/packing.h"
#include "render/renderer.h"
#include "shapes/box.h"
#include "shapes/sphere.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

// The continuous pixel position where world point p appears (inverse of camera_ray).
glm::vec2 project(const Camera& c, glm::vec3 p, glm::ivec2 size) {
  const CameraBasis b = camera_basis(c, float(size.x) / float(size.y));
  const glm::vec3 d = p - b.position;
  const float s = glm::dot(d, b.forward);
  const glm::vec2 ndc(glm::dot(d, b.right) / (s * glm::dot(b.right, b.right)), glm::dot(d, b.up) / (s * glm::dot(b.up, b.up)));
  return (ndc + 1.0f) * 0.5f * glm::vec2(size);
}

int index_of(const Scene& s, ShapeKind k) {
  for (size_t i = 0; i < s.shapes.size(); ++i)
    if (s.shapes[i].kind() == k) return int(i);
  return -1;
}

}  // namespace

TEST_CASE("pick: known pixels of reference scene0", "[picking]") {
  const Scene s = load_scene_file(repo_path("scenes/reference/scene0.xml"));
  const glm::ivec2 size(160, 120);
  // scene0: the light's sphere, the floor plane, six boxes, spheres.
  const int floor = index_of(s, ShapeKind::Plane);
  REQUIRE(floor >= 0);
  // The camera at height 65 looks level: the bottom row sees the floor, the top row the sky.
  CHECK(pick(s, s.camera, {80.5f, 0.5f}, size) == floor);
  CHECK(pick(s, s.camera, {0.5f, 119.5f}, size) == -1);
  // The ray through a projected point hits that point's shape first (when nothing is in
  // front of it), and the hit lies at that point: the camera math matches project().
  int seen = 0;
  for (int i = 1; i < int(s.shapes.size()); ++i) {
    const Shape& sh = s.shapes[size_t(i)];
    if (sh.kind() != ShapeKind::Box && sh.kind() != ShapeKind::Sphere) continue;
    // The face (or sphere point) nearest the camera, at the shape's middle height.
    const glm::vec3 centre = shape_position(sh);
    const Ray to = {s.camera.position, glm::normalize(centre - s.camera.position)};
    Hit own;
    if (const Sphere* sp = sh.as<Sphere>()) intersect_sphere(*sp, i, to, own);
    else intersect_box(*sh.as<Box>(), i, to, prepare_box(to), own);
    REQUIRE(own.id == i);
    const glm::vec2 px = project(s.camera, centre, size);
    if (px.x < 0 || px.y < 0 || px.x >= size.x || px.y >= size.y) continue;
    const Hit h = intersect_scene(s, camera_ray(s.camera, px, size));
    if (h.t < own.t * 0.999f) continue;  // something in front: not a known pixel
    ++seen;
    CHECK(pick(s, s.camera, px, size) == i);
    CHECK(glm::length(h.p - own.p) < 1e-3f * own.t);
  }
  CHECK(seen >= 4);
}

TEST_CASE("pick: a small scene with exact answers", "[picking]") {
  const Scene s = load_scene_text(
      "<SceneLevel><Camera position=\"0 0 10\" yaw=\"90\" pitch=\"0\"/><Objects>"
      "<Sphere center=\"0 0 0\" radius=\"1\"><Diffuse/></Sphere>"
      "<Box min=\"2 -1 -1\" max=\"3 1 1\"><Diffuse/></Box>"
      "<Triangle v0=\"-3 -1 0\" v1=\"-2 -1 0\" v2=\"-2.5 1 0\"><Diffuse/></Triangle>"
      "</Objects></SceneLevel>",
      "inline.xml");
  const glm::ivec2 size(200, 100);
  CHECK(pick(s, s.camera, glm::vec2(100.0f, 50.0f), size) == 0);                            // the centre: the sphere
  CHECK(pick(s, s.camera, project(s.camera, {2.5f, 0.0f, 1.0f}, size), size) == 1);        // the box's front face
  CHECK(pick(s, s.camera, project(s.camera, {-2.5f, -0.5f, 0.0f}, size), size) == 2);      // inside the triangle
  CHECK(pick(s, s.camera, project(s.camera, {-2.0f, 0.8f, 0.0f}, size), size) == -1);      // beside its slanted edge
  CHECK(pick(s, s.camera, glm::vec2(100.0f, 99.0f), size) == -1);                           // above everything
  CHECK(pick(s, s.camera, glm::vec2(100.0f, 50.0f), glm::ivec2(0, 0)) == -1);
}

// Every pixel's camera ray through the production GLSL (the shader's camera formula and
// scene_intersect) against the CPU cast: the same shape. Where two surfaces are within
// rounding of each other along a ray (silhouettes, touching boxes) GPU and CPU may
// differ: at most 0.2% of the pixels, and only where the two hit distances agree to 1e-3.
TEST_CASE("pick agrees with the shader's scene_intersect on every pixel", "[gpu][picking]") {
  test_gl();
  for (const char* file : {"scenes/reference/scene0.xml", "scenes/reference/scene2.xml", "scenes/mesh-cube.xml"}) {
    const Scene s = load_scene_file(repo_path(file));
    const glm::ivec2 size(96, 72);
    const CameraBasis cb = camera_basis(s.camera, float(size.x) / float(size.y));
    GlslKernel k(
        "uniform vec3 u_cam_pos; uniform vec3 u_cam_fwd; uniform vec3 u_cam_right; uniform vec3 u_cam_up;\n"
        "uniform vec2 u_size;\n"
        "vec4 kernel(vec4 x, int i) {\n"
        "  int w = int(u_size.x);\n"
        "  vec2 ndc = (vec2(float(i % w), float(i / w)) + 0.5) / u_size * 2.0 - 1.0;\n"
        "  Hit h = scene_intersect(Ray(u_cam_pos, normalize(u_cam_fwd + ndc.x * u_cam_right + ndc.y * u_cam_up)));\n"
        "  return vec4(float(h.id), h.t, 0.0, 0.0);\n}\n",
        Features::of(s));
    k.bind_scene(s, pack_scene(s));
    k.program().set("u_cam_pos", cb.position);
    k.program().set("u_cam_fwd", cb.forward);
    k.program().set("u_cam_right", cb.right);
    k.program().set("u_cam_up", cb.up);
    k.program().set("u_size", glm::vec2(size));
    const std::vector<glm::vec4> gpu = k.run(size.x * size.y);
    int differ = 0, hits = 0;
    for (int y = 0; y < size.y; ++y)
      for (int x = 0; x < size.x; ++x) {
        const glm::vec4 g = gpu[size_t(y * size.x + x)];
        const Hit h = intersect_scene(s, camera_ray(s.camera, glm::vec2(x + 0.5f, y + 0.5f), size));
        hits += h.id >= 0;
        if (int(g.x) == h.id) continue;
        ++differ;
        INFO(file << " pixel " << x << "," << y << ": gpu " << g.x << " t " << g.y << ", cpu " << h.id << " t " << h.t);
        CHECK((h.id >= 0 && int(g.x) >= 0 && std::abs(g.y - h.t) < 1e-3f * h.t));
      }
    INFO(file << ": " << differ << " of " << size.x * size.y << " pixels differ");
    CHECK(differ <= size.x * size.y / 500);
    CHECK(hits > size.x * size.y / 4);
  }
}

TEST_CASE("a scene lists the files it references", "[picking][loader]") {
  const std::string path = repo_path("scenes/mesh-cube.xml");
  const Scene s = load_scene_file(path);
  REQUIRE(s.files.size() == 2);
  CHECK(s.files[0] == path);
  CHECK(s.files[1].find("reference/cube.json") != std::string::npos);
  // Image maps are references too (an edited texture must re-render in the watch loop).
  const Scene t = load_scene_file(repo_path("scenes/seed/03-balls-solid-table-wood.xml"));
  for (const char* map : {"wood_diffuse.png", "wood_specular.png", "wood_normal.png"})
    CHECK(std::any_of(t.files.begin(), t.files.end(), [&](const std::string& f) { return f.find(map) != std::string::npos; }));
  // With file references off (the fuzzers), an image path is refused like a mesh path.
  CHECK_THROWS_WITH(load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects><Plane normal=\"0 1 0\" d=\"0\">"
                                    "<Textured diffuse=\"x.png\"/></Plane></Objects></SceneLevel>",
                                    "t.xml", false),
                    Catch::Contains("file references are disabled"));
}

TEST_CASE("selection edits re-upload the scene and never recompile", "[gpu][picking]") {
  test_gl();
  Scene s = load_scene_file(repo_path("scenes/reference/scene0.xml"));
  Renderer r;
  r.resize(32, 24);
  r.set_scene(s);
  const size_t programs = r.programs_compiled();
  RenderSettings st;
  st.sample_limit = 4;
  r.set_settings(st);
  while (!r.converged()) r.step();
  const glm::dvec3 before = image_stats(r.read_radiance()).mean;
  // The floor's colour, a box moved, the light's sphere moved and grown: values only.
  const int light_shape = s.lights[0].shape, floor = index_of(s, ShapeKind::Plane), box = index_of(s, ShapeKind::Box);
  REQUIRE((floor >= 0 && box >= 0));
  s.materials[size_t(s.shapes[size_t(floor)].material)].tint = glm::vec3(0.9f);  // was 0.8 0.2 0 under a yellow light
  move_shape(s, box, shape_position(s.shapes[size_t(box)]) + glm::vec3(0.0f, 10.0f, 0.0f));
  move_shape(s, light_shape, glm::vec3(0.0f, 120.0f, 0.0f));
  set_sphere_radius(s, light_shape, 12.0f);
  CHECK(s.lights[0].position == glm::vec3(0.0f, 120.0f, 0.0f));
  CHECK(s.lights[0].radius == 12.0f);
  CHECK(s.shapes[size_t(light_shape)].as<Sphere>()->center == glm::vec3(0.0f, 120.0f, 0.0f));
  CHECK(s.shapes[size_t(box)].as<Box>()->min.y == 10.0f);
  const Camera cam = r.camera();
  r.set_scene(s);
  r.set_camera(cam);
  CHECK(r.programs_compiled() == programs);
  CHECK(r.samples() == 0);
  while (!r.converged()) r.step();
  const glm::dvec3 after = image_stats(r.read_radiance()).mean;
  INFO("mean before " << before.x << " " << before.y << " " << before.z << ", after " << after.x << " " << after.y << " " << after.z);
  CHECK(after.y / after.x > 1.2 * before.y / before.x);  // the floor is no longer red
}

// The selection panel's fields come from each kind's stem (materials/<kind>.h: edit): a
// recording editor sees what the panel would show, and an edit through it reaches the
// packed record (the panel used to edit an unused IOR slot of a SmoothDielectric).
TEST_CASE("selection panel: each material kind offers its own fields, and they reach the record", "[picking]") {
  struct Recorder {
    std::vector<std::string> labels;
    float set_to = -1.0f;  // sliders write this when >= 0
    bool color(const char* l, glm::vec3&) { return labels.emplace_back(l), false; }
    bool slider(const char* l, float& v, float, float) {
      labels.emplace_back(l);
      if (set_to < 0.0f) return false;
      v = set_to;
      return true;
    }
    bool drag3(const char* l, glm::vec3&, float, float, float) { return labels.emplace_back(l), false; }
  };
  auto fields = [](Material m) {
    Recorder r;
    edit_material(m, r);
    std::string s;
    for (const std::string& l : r.labels) s += (s.empty() ? "" : ", ") + l;
    return s;
  };
  CHECK(fields(Diffuse{}) == "colour");
  CHECK(fields(Metal{}) == "colour, roughness, ior");
  CHECK(fields(SmoothDielectric{}) == "colour, ior");
  CHECK(fields(Transmit{}) == "colour, ior");
  CHECK(fields(Emit{}) == "emission");
  CHECK(fields(FresnelComposite{}) == "");
  CHECK(fields(ChessTexture{}) == "colour, colour 2");
  // Every kind answers (the visit covers the list).
  for (int k = 0; k < kNumMaterialKinds; ++k) {
    const Scene one = load_scene_text(std::string("<SceneLevel><Camera position=\"0 0 5\"/><Objects><Sphere center=\"0 0 0\" radius=\"1\">") +
                                          kMaterialTraits[k].example + "</Sphere></Objects></SceneLevel>",
                                      repo_path("assets/textures") + "/x.xml");
    Material m = one.materials.back();
    REQUIRE(int(m.kind()) == k);
    Recorder r;
    edit_material(m, r);
    INFO(kMaterialKinds[k].xml);
    CHECK((k == int(MaterialKind::FresnelComposite) || !r.labels.empty()));
  }
  // A slider edit lands in the record the shader reads: the dielectric's eta_inner.
  Scene s;
  s.materials.push_back(SmoothDielectric{.ior = 1.5f});
  Recorder set;
  set.set_to = 2.0f;
  CHECK(edit_material(s.materials[0], set));
  const PackedScene p = pack_values(s);
  const int eta_inner_slot = kind_slot(SmoothDielectric::kFields, int(SmoothDielectric::rec::eta_inner));
  CHECK(p.materials.get(0, *material_rec::kPayload[eta_inner_slot]) == 2.0f);
}
