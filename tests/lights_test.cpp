// Lights on the CPU side: the punctual kinds' XML elements (each kind's example loads,
// bad values are errors naming file and line), KHR_lights_punctual read from a glTF
// (positions and directions through node transforms, the spot's cone, range), and the
// light selection's alias table (render/light_select.h): the table selects each light
// with exactly its pmf, and the pmf is proportional to power.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "render/light_select.h"
#include "render/packing.h"
#include "scene/xml_loader.h"
#include "scene_builders.h"

using namespace pt;

namespace {

std::string scene_with(const std::string& lights) {
  return R"(<SceneLevel><Camera position="0 1 3" yaw="90" pitch="0"/>)" + lights +
         R"(<Objects><Plane normal="0 1 0" d="0"><Diffuse/></Plane></Objects></SceneLevel>)";
}

// The probability that the alias table selects each slot: 1/n per slot, split between
// the slot (keep) and its alias (1 - keep): what select_light in lights.glsl does.
std::vector<double> selection_probabilities(const AliasTable& t) {
  const size_t n = t.pmf.size();
  std::vector<double> p(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    p[i] += double(t.keep[i]) / double(n);
    p[size_t(t.alias[i])] += (1.0 - double(t.keep[i])) / double(n);
  }
  return p;
}

}  // namespace

TEST_CASE("punctual lights: each kind's example element loads", "[loader][lights]") {
#define PT_X(e, g, x) \
  {                                                                                  \
    const Scene s = load_scene_text(scene_with(e::kExample), "lights.xml");          \
    REQUIRE(s.punctual.size() == 1);                                                 \
    CHECK(s.punctual[0].kind() == LightKind::e);                                     \
    CHECK(s.punctual[0].line == 1);                                                  \
  }
  PT_LIGHT_KINDS(PT_X)
#undef PT_X
}

TEST_CASE("punctual lights: XML attributes", "[loader][lights]") {
  const Scene s = load_scene_text(scene_with(R"(<PointLight position="1 2 3" color="0.5 1 1" intensity="4" range="7"/>
    <SpotLight position="0 3 0" direction="0 -2 0" intensity="10" innerCone="20" outerCone="40"/>
    <DirectionalLight direction="0 -1 1" color="1 1 0.5" intensity="2"/>)"),
                                  "lights.xml");
  REQUIRE(s.punctual.size() == 3);
  const PointLight& p = *s.punctual[0].as<PointLight>();
  CHECK(p.position == glm::vec3(1, 2, 3));
  CHECK(p.intensity == glm::vec3(2, 4, 4));
  CHECK(p.range == 7.0f);
  const SpotLight& sp = *s.punctual[1].as<SpotLight>();
  CHECK(sp.direction == glm::vec3(0, -1, 0));
  CHECK(sp.inner == Approx(glm::radians(20.0f)));
  CHECK(sp.outer == Approx(glm::radians(40.0f)));
  CHECK(sp.range == 0.0f);
  const DirectionalLight& d = *s.punctual[2].as<DirectionalLight>();
  CHECK(d.direction.y == Approx(-std::sqrt(0.5f)));
  CHECK(d.intensity == glm::vec3(2, 2, 1));
  // Packed as light records after the emitting shapes (none here): shape = -1 - kind.
  const PackedScene packed = pack_scene(s);
  REQUIRE(packed.lights.count() == 3);
  CHECK(packed.lights.get(0, light_rec::shape) == -1.0f);
  CHECK(packed.lights.get(1, light_rec::shape) == -2.0f);
  CHECK(packed.lights.get(2, light_rec::shape) == -3.0f);
  CHECK(packed.lights.get(1, light_rec::cos_outer) == Approx(std::cos(glm::radians(40.0f))));
  CHECK(light_shapes(s) == std::vector<int>{-1, -2, -3});
}

TEST_CASE("punctual lights: bad elements are errors with file and line", "[loader][lights]") {
  for (const char* bad : {R"(<PointLight/>)", R"(<PointLight position="0 1 0" intensity="-1"/>)",
                          R"(<PointLight position="0 1 0" range="0"/>)", R"(<PointLight position="0 1 0" radius="1"/>)",
                          R"(<SpotLight position="0 1 0" direction="0 -1 0" innerCone="30" outerCone="30"/>)",
                          R"(<SpotLight position="0 1 0" direction="0 -1 0" outerCone="100"/>)",
                          R"(<SpotLight position="0 1 0" direction="0 0 0"/>)", R"(<DirectionalLight/>)",
                          R"(<DirectionalLight direction="0 -1 0"><Diffuse/></DirectionalLight>)"}) {
    INFO(bad);
    try {
      load_scene_text(scene_with(bad), "bad.xml");
      FAIL("loaded");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).rfind("bad.xml:1:", 0) == 0);
    }
  }
}

TEST_CASE("light selection: the alias table selects each light with its pmf", "[lights][selection]") {
  for (const std::vector<double>& w : {std::vector<double>{1.0}, std::vector<double>{1.0, 1.0, 1.0},
                                       std::vector<double>{1000.0, 1.0}, std::vector<double>{0.0, 3.0, 1.0, 0.5, 7.0, 0.0, 2.0},
                                       std::vector<double>{1e-6, 1.0, 1e6}}) {
    const AliasTable t = alias_table(w);
    double sum = 0.0;
    for (double x : w) sum += x;
    const std::vector<double> p = selection_probabilities(t);
    for (size_t i = 0; i < w.size(); ++i) {
      CHECK(t.pmf[i] == Approx(w[i] / sum).epsilon(1e-6).margin(1e-12));
      CHECK(p[i] == Approx(w[i] / sum).epsilon(1e-5).margin(1e-7));
      CHECK(t.alias[i] >= 0);
      CHECK(size_t(t.alias[i]) < w.size());
    }
  }
  // One light: kept always, pmf exactly 1 (the shader's arithmetic is then that of a lone light).
  const AliasTable one = alias_table({5.0});
  CHECK(one.pmf[0] == 1.0f);
  CHECK(one.keep[0] == 1.0f);
}

TEST_CASE("light selection: proportional to power, area and punctual lights alike", "[lights][selection]") {
  // A light sphere (r 10, L 100) beside an emitting box (40x30x40, L 69): powers
  // L * area * pi, so the sphere gets 125664 / (125664 + 552000) of the samples, not half.
  Scene s;
  Material box = Emit{}, ball = Emit{};
  box.emission = glm::vec3(69.0f);
  ball.emission = glm::vec3(100.0f);
  add_box(s, {-10, 115, -11}, {30, 145, 29}, add_material(s, box));
  add_sphere(s, {10, 95, 9}, 10.0f, add_material(s, ball));
  PackedScene p = pack_scene(s);
  REQUIRE(p.lights.count() == 2);
  const double sphere = 100.0 * 4.0 * M_PI * 100.0;
  CHECK(p.lights.get(0, light_rec::pmf) == Approx(552000.0 / (552000.0 + sphere)));
  CHECK(p.lights.get(1, light_rec::pmf) == Approx(sphere / (552000.0 + sphere)));
  CHECK(p.seal_lo.empty());
  // A point light of intensity I: 4 pi I; a spot of full cone 90 degrees (inner 0):
  // 2 pi I / 3 at outer 90 (the squared ramp over cos in [0, 1] integrates to 1/3).
  s.punctual.push_back({PointLight{.position = glm::vec3(0, 2, 0), .intensity = glm::vec3(1000.0f)}, 0});
  s.punctual.push_back({SpotLight{.position = glm::vec3(0), .intensity = glm::vec3(3000.0f), .inner = 0.0f, .outer = 1.5707963f}, 0});
  const std::vector<double> w = light_powers(s, {0, 1});
  REQUIRE(w.size() == 4);
  CHECK(w[2] == Approx(4.0 * M_PI * 1000.0));
  CHECK(w[3] == Approx(2.0 * M_PI * 3000.0 / 3.0).epsilon(1e-5));
  p = pack_scene(s);
  double total = 0.0;
  for (int i = 0; i < p.lights.count(); ++i) total += p.lights.get(i, light_rec::pmf);
  CHECK(total == Approx(1.0).epsilon(1e-6));
}

TEST_CASE("glTF: KHR_lights_punctual lights placed and aimed by their nodes", "[loader][gltf][lights]") {
  // Node 1 (translation 1 0 0) is the parent of node 2, a point light at (0 2 3): at
  // (1 2 3). Node 3: a spot turned -90 degrees about +x, so its -z points down -y.
  // Node 4: a directional light, unrotated: it points down -z. Node 5 (not in the scene).
  const std::string text = R"({"asset":{"version":"2.0"},"extensionsUsed":["KHR_lights_punctual"],
 "extensions":{"KHR_lights_punctual":{"lights":[
   {"type":"point","color":[1,0.5,0.25],"intensity":8,"range":12},
   {"type":"spot","intensity":20,"spot":{"innerConeAngle":0.2,"outerConeAngle":0.5}},
   {"type":"directional","intensity":3}]}},
 "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
 "bufferViews":[{"buffer":0,"byteLength":36}],
 "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
 "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
 "nodes":[{"mesh":0},{"translation":[1,0,0],"children":[2]},
   {"translation":[0,2,3],"extensions":{"KHR_lights_punctual":{"light":0}}},
   {"translation":[0,5,0],"rotation":[-0.70710678,0,0,0.70710678],"scale":[2,2,2],"extensions":{"KHR_lights_punctual":{"light":1}}},
   {"extensions":{"KHR_lights_punctual":{"light":2}}},
   {"translation":[9,9,9],"extensions":{"KHR_lights_punctual":{"light":0}}}],
 "scenes":[{"nodes":[0,1,3,4]}],"scene":0})";
  const std::string dir = (std::filesystem::temp_directory_path() / "pt-lights-test").string();
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/lights.gltf";
  std::ofstream(path, std::ios::binary) << text;
  const Scene s = load_scene_file(path);
  CHECK(s.warnings.empty());
  REQUIRE(s.punctual.size() == 3);
  int seen = 0;
  for (const PunctualLight& l : s.punctual) {
    if (const PointLight* p = l.as<PointLight>()) {
      ++seen;
      CHECK(p->position.x == Approx(1.0f));
      CHECK(p->position.y == Approx(2.0f));
      CHECK(p->position.z == Approx(3.0f));
      CHECK(p->intensity == glm::vec3(8.0f, 4.0f, 2.0f));  // candela -> our units 1:1 (docs/gltf.md)
      CHECK(p->range == 12.0f);
    } else if (const SpotLight* sp = l.as<SpotLight>()) {
      ++seen;
      CHECK(sp->position.y == Approx(5.0f));
      CHECK(sp->direction.x == Approx(0.0f).margin(1e-6));
      CHECK(sp->direction.y == Approx(-1.0f));
      CHECK(sp->direction.z == Approx(0.0f).margin(1e-6));
      CHECK(sp->inner == Approx(0.2f));
      CHECK(sp->outer == Approx(0.5f));
      CHECK(sp->intensity == glm::vec3(20.0f));  // the node's scale changes nothing of the light
    } else if (const DirectionalLight* d = l.as<DirectionalLight>()) {
      ++seen;
      CHECK(d->direction == glm::vec3(0.0f, 0.0f, -1.0f));
      CHECK(d->intensity == glm::vec3(3.0f));
    }
  }
  CHECK(seen == 3);
  // A bad light is an error with its JSON pointer.
  std::string bad = text;
  bad.replace(bad.find("\"innerConeAngle\":0.2"), 20, "\"innerConeAngle\":0.7");
  std::ofstream(path, std::ios::binary) << bad;
  try {
    load_scene_file(path);
    FAIL("loaded");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("/extensions/KHR_lights_punctual/lights/1/spot") != std::string::npos);
  }
}

TEST_CASE("light selection: a light sealed inside an absorbing box is never selected while the camera is outside", "[lights][selection]") {
  // scene2: the <Light> sphere (centre 10 125 9, radius 10) touches the emitting box's
  // bottom face from inside (y = 115) and is otherwise strictly inside: sealed.
  const Scene s2 = load_scene_file(PT_SOURCE_DIR "/scenes/reference/scene2.xml");
  PackedScene p = pack_scene(s2);
  REQUIRE(p.lights.count() == 2);
  int box = -1, sphere = -1;
  for (int i = 0; i < 2; ++i) (s2.shapes[size_t(p.lights.get(i, light_rec::shape))].as<Sphere>() ? sphere : box) = i;
  REQUIRE(box >= 0);
  REQUIRE(sphere >= 0);
  CHECK(p.lights.get(sphere, light_rec::pmf) == 0.0f);
  CHECK(p.lights.get(box, light_rec::pmf) == 1.0f);
  REQUIRE(p.seal_lo.size() == 1);
  CHECK(p.seal_lo[0] == glm::vec3(-10, 115, -11));
  CHECK(p.seal_hi[0] == glm::vec3(30, 145, 29));
  CHECK_FALSE(camera_sealed_off(p.seal_lo, p.seal_hi, s2.camera.position, s2.camera.aperture));
  CHECK(camera_sealed_off(p.seal_lo, p.seal_hi, glm::vec3(10, 120, 0), 0.0f));
  CHECK(camera_sealed_off(p.seal_lo, p.seal_hi, glm::vec3(10, 113, 0), 3.0f));  // the lens reaches inside
  CHECK_FALSE(camera_sealed_off(p.seal_lo, p.seal_hi, glm::vec3(10, 113, 0), 1.0f));

  // Not sealed: a box that scatters (Diffuse) instead of absorbing; a light that pokes
  // out; a light inside an emitting sphere (not a solid box); a moving light that leaves.
  auto sealed = [](const Scene& s) { return sealed_lights(s, sampled_light_shapes(s)); };
  Scene a;
  Material emit = Emit{}, diffuse;
  emit.emission = glm::vec3(1.0f);
  const int e = add_material(a, emit), d = add_material(a, diffuse);
  add_box(a, {-2, -2, -2}, {2, 2, 2}, d);
  add_sphere(a, {0, 0, 0}, 1.0f, e);
  CHECK(sealed(a).sealed == std::vector<char>{0});
  a.shapes[0].material = e;
  CHECK(sealed(a).sealed == std::vector<char>{0, 1});  // the box is a light too, sealing the sphere
  a.shapes[1].as<Sphere>()->radius = 2.5f;
  CHECK(sealed(a).sealed == std::vector<char>{0, 0});
  a.shapes[1].as<Sphere>()->radius = 1.0f;
  a.shapes[1].as<Sphere>()->velocity = glm::vec3(1.5f, 0, 0);  // at time 1 it pokes out
  CHECK(sealed(a).sealed == std::vector<char>{0, 0});
  a.shapes[1].as<Sphere>()->velocity = glm::vec3(0.0f);
  a.shapes[0] = Shape(Sphere{.center = glm::vec3(0), .radius = 3.0f}, e);
  CHECK(sealed(a).sealed == std::vector<char>{0, 0});
  // A triangle lying on the box's face (bounds touching it) is not sealed; one inside is.
  Scene t;
  const int te = add_material(t, emit);
  add_box(t, {-2, -2, -2}, {2, 2, 2}, te);
  t.shapes.push_back(Shape(Triangle{.v0 = {-1, -2, -1}, .v1 = {1, -2, -1}, .v2 = {0, -2, 1}}, te));
  t.shapes.push_back(Shape(Triangle{.v0 = {-1, -1, -1}, .v1 = {1, -1, -1}, .v2 = {0, -1, 1}}, te));
  CHECK(sealed(t).sealed == std::vector<char>{0, 0, 1});
}
