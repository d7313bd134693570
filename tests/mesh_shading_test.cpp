// Meshes through the production integrator: vertex normals are shading normals. Normals
// equal to the geometric one render exactly as no normals; normals tilted by tau under a
// uniform sky give the closed form (1 + cos tau) / 2 (the cosine lobe reaching below the
// surface collects nothing, and nothing leaks through), also when the normals come from an
// OBJ file's "vn", and interpolated across triangles; a glTF file renders without NaN; a glTF base-colour texture shows its
// colours where its uv put them.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include <glm/gtc/type_ptr.hpp>

#include "gl_context.h"
#include "render/camera.h"
#include "scene/mesh_obj.h"
#include "glsl_harness.h"
#include "scene/xml_loader.h"
#include "scene_builders.h"
#include "test_paths.h"

using namespace pt;

namespace {

// A white Lambertian 20 x 20 quad at y = 0 made of a 4 x 4 grid of triangles, with every
// vertex normal `n` (none when n is zero), under sky radiance 1, seen from above.
Scene quad(glm::vec3 n, const std::string& obj_normal = "") {
  Scene s;
  s.camera.position = glm::vec3(0.3f, 10.0f, 0.2f);
  s.camera.pitch = -89.9f;
  s.environment.color = glm::vec3(1.0f);
  const int m = add_material(s, Material{});
  auto mesh = std::make_shared<MeshData>();
  const int N = 4;
  for (int z = 0; z <= N; ++z)
    for (int x = 0; x <= N; ++x) {
      mesh->positions.emplace_back(-10.0f + 20.0f * float(x) / N, 0.0f, -10.0f + 20.0f * float(z) / N);
      if (n != glm::vec3(0.0f)) mesh->normals.push_back(glm::normalize(n));
    }
  for (int z = 0; z < N; ++z)
    for (int x = 0; x < N; ++x) {
      const unsigned a = unsigned(z * (N + 1) + x), b = a + 1, c = a + unsigned(N + 1), d = c + 1;
      mesh->triangles.emplace_back(a, c, d);
      mesh->triangles.emplace_back(a, d, b);
    }
  if (!obj_normal.empty()) {
    // The same grid as OBJ text, every corner naming the one normal (v//n), read by the
    // production OBJ loader.
    std::string text = "vn " + obj_normal + "\n";
    for (const glm::vec3& p : mesh->positions) text += "v " + std::to_string(p.x) + " 0 " + std::to_string(p.z) + "\n";
    for (const glm::uvec3& t : mesh->triangles)
      text += "f " + std::to_string(t.x + 1) + "//1 " + std::to_string(t.y + 1) + "//1 " + std::to_string(t.z + 1) + "//1\n";
    mesh = std::make_shared<MeshData>(parse_mesh_obj(text, "grid.obj"));
  }
  s.meshes.push_back(mesh);
  s.shapes.push_back(Shape(Mesh{.mesh = 0}, m));
  return s;
}

}  // namespace

TEST_CASE("mesh vertex normals: equal to the geometric normal renders exactly as none", "[gpu][mesh]") {
  test_gl();
  const RenderResult a = render_scene(quad(glm::vec3(0.0f)), 32, 32, 16);
  const RenderResult b = render_scene(quad(glm::vec3(0.0f, 1.0f, 0.0f)), 32, 32, 16);
  double d = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) d = std::max(d, double(std::abs(a.rgba[i] - b.rgba[i])));
  CHECK(a.counters.bad_samples == 0);
  CHECK(d == 0.0);
}

TEST_CASE("mesh vertex normals tilted by tau under a uniform sky give (1 + cos tau) / 2", "[gpu][mesh]") {
  test_gl();
  for (float tau_deg : {0.0f, 30.0f, 60.0f}) {
    const float tau = glm::radians(tau_deg);
    const RenderResult r = render_scene(quad(glm::vec3(std::sin(tau), std::cos(tau), 0.0f)), 32, 32, 64);
    CHECK(r.counters.bad_samples == 0);
    const Estimate e = region_mean(r, 0, 0, 32, 32);
    const double exact = (1.0 + std::cos(double(tau))) / 2.0;
    std::printf("sky on a mesh with normals tilted by %2.0f deg: %.5f, exact %.5f (%+.2f se)\n", tau_deg, e.mean, exact,
                (e.mean - exact) / e.se);
    CHECK(std::abs(e.mean - exact) < 4.0 * e.se + 1e-6);
  }
}

TEST_CASE("OBJ vertex normals (vn) are the shading normals: tilted by 60 deg, (1 + cos 60) / 2", "[gpu][mesh][obj]") {
  test_gl();
  const RenderResult r = render_scene(quad(glm::vec3(0.0f), "0.866025 0.5 0"), 32, 32, 64);
  REQUIRE(r.counters.bad_samples == 0);
  const Estimate e = region_mean(r, 0, 0, 32, 32);
  std::printf("sky on an OBJ grid with vn tilted by 60 deg: %.5f, exact 0.75000 (%+.2f se)\n", e.mean, (e.mean - 0.75) / e.se);
  CHECK(std::abs(e.mean - 0.75) < 4.0 * e.se + 1e-6);
  // The geometric normal as "vn" renders exactly as no normals (1 under the sky).
  const RenderResult flat = render_scene(quad(glm::vec3(0.0f), "0 1 0"), 32, 32, 16);
  const RenderResult none = render_scene(quad(glm::vec3(0.0f)), 32, 32, 16);
  CHECK(flat.rgba == none.rgba);
}

// Interpolation: one OBJ quad (two triangles, x and z in [-10, 10]) whose vertices at
// x = -10 have normal (-sin 60, cos 60, 0) and those at x = +10 (sin 60, cos 60, 0).
// Barycentric interpolation of these unit normals is (x / 10 sin 60, cos 60, 0) on either
// triangle, tilted by theta(x) = atan(tan 60 x / 10), so under the uniform sky the
// radiance is (1 + cos theta(x)) / 2: 1 in the middle, 0.75 at the edges. Flat shading (a
// normal per face) or the geometric normal (1 everywhere) would not give this ramp. Each
// band of rows is compared with the closed form averaged over its pixels' footprints on
// the ground (the production camera basis, box pixel filter).
TEST_CASE("OBJ vertex normals are interpolated across triangles: a ramp of tilts gives its closed form", "[gpu][mesh][obj]") {
  test_gl();
  Scene s = quad(glm::vec3(0.0f));
  s.meshes[0] = std::make_shared<MeshData>(parse_mesh_obj(
      "v -10 0 -10\nv 10 0 -10\nv 10 0 10\nv -10 0 10\nvn -0.8660254 0.5 0\nvn 0.8660254 0.5 0\n"
      "f 1//1 4//1 3//2\nf 1//1 3//2 2//2\n",
      "ramp.obj"));
  const int n = 32, spp = 64;
  const RenderResult r = render_scene(s, n, n, spp);
  REQUIRE(r.counters.bad_samples == 0);
  const CameraBasis cam = camera_basis(s.camera, 1.0f);
  auto exact_at = [&](double ndc_x, double ndc_y) {
    const glm::dvec3 d = glm::dvec3(cam.forward) + ndc_x * glm::dvec3(cam.right) + ndc_y * glm::dvec3(cam.up);
    const double x = double(cam.position.x) + d.x * (-double(cam.position.y) / d.y);  // where the ray meets y = 0
    const double theta = std::atan(std::tan(glm::radians(60.0)) * x / 10.0);
    return (1.0 + std::cos(theta)) / 2.0;
  };
  for (int band = 0; band < 4; ++band) {
    const int y0 = band * 8;
    const Estimate e = region_mean(r, 0, y0, n, y0 + 8);
    double exact = 0.0;
    const int k = 8;  // k x k points per pixel
    for (int y = y0; y < y0 + 8; ++y)
      for (int x = 0; x < n; ++x)
        for (int j = 0; j < k; ++j)
          for (int i = 0; i < k; ++i) exact += exact_at((x + (i + 0.5) / k) / n * 2.0 - 1.0, (y + (j + 0.5) / k) / n * 2.0 - 1.0);
    exact /= double(8 * n * k * k);
    std::printf("OBJ normal ramp, rows %2d..%2d: %.5f, exact %.5f (%+.2f se)\n", y0, y0 + 7, e.mean, exact, (e.mean - exact) / e.se);
    CHECK(std::abs(e.mean - exact) < 4.0 * e.se + 1e-6);
  }
}

TEST_CASE("the glTF sample scene loads (instances share one mesh) and renders without NaN", "[gpu][mesh][gltf]") {
  test_gl();
  const Scene s = load_scene_file(repo_path("scenes/gltf-instances.xml"));
  int instances = 0;
  for (const Shape& sh : s.shapes) instances += sh.kind() == ShapeKind::Mesh;
  CHECK(instances == 9);        // three nodes in each of three placements
  CHECK(s.meshes.size() == 2);  // one torus per file (.gltf, .glb), shared by its two glTF meshes and three nodes
  const RenderResult r = render_scene(s, 48, 32, 4);
  CHECK(r.counters.bad_samples == 0);
  CHECK(region_mean(r, 0, 0, 48, 32).mean > 0.05);
}

// assets/models/textured-quad.*: the quad z = 0, -1..1, facing +z, its base colour a 4x4 PNG
// of four quadrants, red, green (top) / blue, white (bottom). Seen from +z under a uniform
// sky of radiance 1, a Lambertian surface returns its albedo: each quadrant's middle
// (texels of one colour on every side, so bilinear filtering does not blend) must show the
// texture's linear colour, upright (the v flip), in the .gltf (image by file URI, a scene
// dependency) and the .glb (image in the BIN chunk).
TEST_CASE("a glTF base-colour texture renders with its colours where its uv put them", "[gpu][mesh][gltf]") {
  test_gl();
  for (const char* file : {"textured-quad.gltf", "textured-quad.glb"}) {
    INFO(file);
    const Scene s = load_scene_text(
        "<SceneLevel><Camera position=\"0 0 3\" yaw=\"90\" pitch=\"0\"/><Environment color=\"1 1 1\"/><Objects>"
        "<Mesh src=\"../assets/models/" + std::string(file) + "\"/></Objects></SceneLevel>",
        repo_path("scenes/textured-quad-test.xml"));
    REQUIRE(s.materials.size() == 1);
    CHECK(s.materials[0].kind() == MaterialKind::GltfPbr);
    if (std::string(file) == "textured-quad.gltf") CHECK(s.files.back() == repo_path("scenes/../assets/models/textured-quad.png"));
    const int n = 32;
    const RenderResult r = render_scene(s, n, n, 16);
    CHECK(r.counters.bad_samples == 0);
    // Pixels 8..11 and 20..23 see x (and y) in [-0.75, -0.25] and [0.25, 0.75] of the quad
    // (half-extent 3 tan 22.5 deg = 1.243 at the quad): the middle of each quadrant.
    // Rows of the result run bottom to top.
    auto mean = [&](int x0, int y0) {
      glm::dvec3 m(0.0);
      for (int y = y0; y < y0 + 4; ++y)
        for (int x = x0; x < x0 + 4; ++x) m += glm::dvec3(glm::make_vec3(&r.rgba[(size_t(y) * n + size_t(x)) * 4]));
      return m / 16.0;
    };
    const struct {
      const char* name;
      int x, y;
      glm::dvec3 rgb;
    } quadrants[] = {{"top left", 8, 20, {1, 0, 0}}, {"top right", 20, 20, {0, 1, 0}}, {"bottom left", 8, 8, {0, 0, 1}}, {"bottom right", 20, 8, {1, 1, 1}}};
    for (const auto& q : quadrants) {
      const glm::dvec3 m = mean(q.x, q.y);
      std::printf("%s, %-12s: %.4f %.4f %.4f (texture %.0f %.0f %.0f)\n", file, q.name, m.x, m.y, m.z, q.rgb.x, q.rgb.y, q.rgb.z);
      INFO(q.name);
      // The glTF BSDF (a rough dielectric, ior 1.5, of the map's base colour: GltfPbr) is
      // not a pure Lambert: its coat adds a few per cent of white and takes some of the
      // base. Each quadrant still shows its texture's colour where its uv put it.
      for (int c = 0; c < 3; ++c) CHECK((q.rgb[c] > 0.5 ? m[c] > 0.6 : m[c] < 0.15));
    }
  }
}
