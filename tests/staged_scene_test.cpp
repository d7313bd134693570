// A scene's record textures uploaded in bands of rows (render/staged_scene.h, how the page
// spreads a large scene's upload over frames) hold exactly the records, padding included,
// and the scene renders bit for bit as one uploaded at once.
#include <catch2/catch.hpp>

#include <memory>
#include <vector>

#include "gl_context.h"
#include "render/packing.h"
#include "render/renderer.h"
#include "render/staged_scene.h"
#include "scene_builders.h"
#include "scene/xml_loader.h"

using namespace pt;

namespace {

const std::string kScene = mixed_scene_xml(5);

std::vector<float> read_texture(const Texture& t) {
  Framebuffer f(t);
  REQUIRE(f.complete());
  std::vector<float> out(size_t(t.width()) * size_t(t.height()) * 4);
  glReadPixels(0, 0, t.width(), t.height(), GL_RGBA, GL_FLOAT, out.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return out;
}

std::vector<float> render(Renderer& r, int sweeps) {
  r.resize(48, 32);
  r.restart();
  for (int n = 0; n < sweeps;) n += r.step() > 0 ? 1 : 0;
  return r.read_radiance();
}

}  // namespace

TEST_CASE("a scene uploaded in bands of rows holds its records and renders as one uploaded at once", "[gpu][staging]") {
  test_gl();
  const Scene scene = load_scene_text(kScene, "staged.xml", false);
  const PackedScene p = pack_scene(scene);
  REQUIRE(p.prims.rows() > 3);  // several bands, and a last row partly filled
  Renderer r;
  for (int rows : {1, 3, 1000}) {
    INFO("bands of " << rows << " rows");
    StagedScene staged(r.limits(), p);
    int calls = 1;
    while (!staged.upload(rows)) ++calls;
    CHECK(staged.progress() == 1.0);
    if (rows == 1) CHECK(calls == p.shapes.rows() + p.materials.rows() + p.lights.rows() + p.nodes.rows() + p.prims.rows() + p.vertices.rows());
    CHECK(read_texture(staged.shapes) == p.shapes.texels());
    CHECK(read_texture(staged.materials) == p.materials.texels());
    CHECK(read_texture(staged.lights) == p.lights.texels());
    CHECK(read_texture(staged.nodes) == p.nodes.texels());
    CHECK(read_texture(staged.prims) == p.prims.texels());
    CHECK(read_texture(staged.vertices) == p.vertices.texels());
  }
  r.set_scene(scene);
  const std::vector<float> once = render(r, 2);
  StagedScene staged(r.limits(), p);
  while (!staged.upload(2)) {
  }
  Renderer r2;
  r2.set_scene(scene, p, &staged);
  CHECK(staged.prims.id() == 0u);  // taken by the renderer
  CHECK(render(r2, 2) == once);
}

TEST_CASE("staging a scene beyond the GPU's texture size throws before making anything", "[gpu][staging]") {
  test_gl();
  const Scene scene = load_scene_text(kScene, "staged.xml", false);
  const PackedScene p = pack_scene(scene);
  Renderer r;
  GlLimits small = r.limits();
  small.max_texture_size = kDataWidth / 2;  // every record texture is kDataWidth wide
  CHECK_THROWS_WITH(StagedScene(small, p), Catch::Contains("the scene's objects") && Catch::Contains("GL_MAX_TEXTURE_SIZE"));
}

// update_values(scene) on a renderer showing `before`: accepted, no program built, and
// the image bit for bit that of `scene` set from scratch. Returns the updated image.
static std::vector<float> updated_as_set_anew(Renderer& r, const Scene& scene, const std::vector<float>& before) {
  const size_t programs = r.programs_compiled();
  REQUIRE(r.update_values(scene));
  const std::vector<float> updated = render(r, 2);
  CHECK(updated != before);
  CHECK(r.programs_compiled() == programs);
  Renderer fresh;
  fresh.set_scene(scene);
  CHECK(render(fresh, 2) == updated);
  return updated;
}

// The page's edits of values (a colour, a roughness, a light's colour, the environment's
// colour) re-upload only the shape, material and light records: the image is bit for bit
// that of the edited scene set from scratch. An edit that changes which shapes are lights
// is refused (the caller then sets the scene).
TEST_CASE("an edit of values updates the records in place and renders as the edited scene set anew", "[gpu][staging]") {
  test_gl();
  Scene scene = load_scene_text(kScene, "staged.xml", false);
  Renderer r;
  r.set_scene(scene);
  const std::vector<float> before = render(r, 2);
  for (const Shape& s : scene.shapes)
    if (s.kind() == ShapeKind::Sphere && s.light < 0) scene.materials[size_t(s.material)].tint = glm::vec3(0.2f, 0.9f, 0.3f);
  scene.lights[0].color = glm::vec3(1.0f, 0.5f, 0.25f);
  sync_light(scene, 0);
  scene.environment.color = glm::vec3(0.1f, 0.2f, 0.3f);
  const std::vector<float> edited = updated_as_set_anew(r, scene, before);

  Scene dark = scene;  // the light goes out: its sphere is no longer a sampled light
  for (const Shape& s : dark.shapes)
    if (s.light >= 0) dark.materials[size_t(s.material)].emission = glm::vec3(0.0f);
  CHECK_FALSE(r.update_values(dark));
  CHECK(render(r, 2) == edited);  // refused: nothing changed

  // Another environment map (the page's environment choice): uploaded, not re-packed.
  auto sky = [](float red, float green, float blue) {
    auto m = std::make_shared<EnvImage>();
    m->width = 16;
    m->height = 8;
    for (int y = 0; y < m->height; ++y)
      for (int x = 0; x < m->width; ++x)
        for (float v : {red * float(1 + x), green * float(1 + y), blue, 1.0f}) m->rgba.push_back(v);
    return std::shared_ptr<const EnvImage>(m);
  };
  scene.environment.map = sky(0.05f, 0.1f, 0.4f);
  r.set_scene(scene);
  const std::vector<float> blue = render(r, 2);
  scene.environment.map = sky(0.3f, 0.02f, 0.01f);
  scene.environment.rotation = 90.0f;
  const std::vector<float> red = updated_as_set_anew(r, scene, blue);
  scene.environment.map.reset();  // a map to a colour: another program, refused
  CHECK_FALSE(r.update_values(scene));
  CHECK(render(r, 2) == red);
}

// Moving objects in a scene with a mesh (the page's position and radius edits): the
// BVH is refitted over the same tree and only the changed rows are uploaded; every node
// still bounds what is under it, and the image is the edited scene's as a new build
// renders it (the same nearest hits, another tree).
TEST_CASE("a moved sphere refits the BVH in place and renders as the moved scene built anew", "[gpu][staging]") {
  test_gl();
  Scene scene = load_scene_text(kScene, "staged.xml", false);
  PackedScene p = pack_scene(scene);
  Renderer r;
  r.set_scene(scene, p);
  const std::vector<float> before = render(r, 2);
  int sphere = -1;
  for (size_t i = 0; i < scene.shapes.size(); ++i)
    if (scene.shapes[i].kind() == ShapeKind::Sphere && scene.shapes[i].light < 0) sphere = int(i);
  REQUIRE(sphere >= 0);
  // Far across the mesh, larger; then the light moved too.
  std::vector<int> prims, nodes;
  scene.shapes[size_t(sphere)].as<Sphere>()->center = glm::vec3(-1.2f, 0.3f, 0.5f);
  scene.shapes[size_t(sphere)].as<Sphere>()->radius = 0.6f;
  REQUIRE(refit_shape(scene, p, sphere, prims, nodes));
  scene.lights[0].position = glm::vec3(-1.0f, 2.5f, 1.0f);
  sync_light(scene, 0);
  REQUIRE(refit_shape(scene, p, scene.lights[0].shape, prims, nodes));
  CHECK(nodes.size() >= 2);
  CHECK(nodes.size() < size_t(p.nodes.count()) / 10);  // a path to the root, not the tree
  // Every node bounds its children or its primitives.
  auto inside = [](glm::vec3 lo, glm::vec3 hi, glm::vec3 plo, glm::vec3 phi) {
    return glm::all(glm::lessThanEqual(lo, plo)) && glm::all(glm::greaterThanEqual(hi, phi));
  };
  for (int n = 0; n < p.nodes.count(); ++n) {
    const glm::vec3 lo = p.nodes.get3(n, node_rec::lo), hi = p.nodes.get3(n, node_rec::hi);
    const int first = int(p.nodes.get(n, node_rec::first)), count = int(p.nodes.get(n, node_rec::count));
    if (count == 0) {
      for (int c : {first, first + 1}) REQUIRE(inside(lo, hi, p.nodes.get3(c, node_rec::lo), p.nodes.get3(c, node_rec::hi)));
    } else {
      for (int q = first; q < first + count; ++q) {
        const int tag = int(p.prims.get(q, prim_rec::tag));
        if (tag >= 0) {
          for (const Field* f : {&prim_rec::v0, &prim_rec::v1, &prim_rec::v2}) REQUIRE(inside(lo, hi, p.prims.get3(q, *f), p.prims.get3(q, *f)));
        } else {
          const Sphere& s = *scene.shapes[size_t(-1 - tag)].as<Sphere>();
          REQUIRE(inside(lo, hi, s.center - glm::vec3(s.radius), s.center + glm::vec3(s.radius)));
        }
      }
    }
  }
  REQUIRE(r.update_geometry(scene, p, prims, nodes));
  const std::vector<float> moved = render(r, 2);
  CHECK(moved != before);
  Renderer fresh;
  fresh.set_scene(scene);
  CHECK(render(fresh, 2) == moved);
  // A mesh instance is not refitted: the caller packs again.
  int mesh = -1;
  for (size_t i = 0; i < scene.shapes.size(); ++i)
    if (scene.shapes[i].kind() == ShapeKind::Mesh) mesh = int(i);
  CHECK_FALSE(refit_shape(scene, p, mesh, prims, nodes));
}
