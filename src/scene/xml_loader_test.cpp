// Loader tests: the three reference scenes load unmodified with their quirks, and
// malformed input fails with a message naming file, line and problem.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/file_io.h"
#include "core/image.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

std::string error_of(const std::string& xml) {
  try {
    load_scene_text(xml, "bad.xml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

const char* kHead = "<?xml version=\"1.0\"?>\n<SceneLevel>\n<Camera position=\"0 0 10\" up=\"0 1 0\" yaw=\"90\" pitch=\"0\"/>\n";

}  // namespace

TEST_CASE("reference scenes in the repo are byte-identical to the originals", "[loader]") {
  for (const char* name : {"scene0.xml", "scene1.xml", "scene2.xml", "cube.json"}) {
    const auto ours = read_file(repo_path("scenes/reference/") + name);
    REQUIRE(ours);
    const auto orig = read_file(repo_path("../shared/reference-scenes/") + name);
    if (orig) CHECK(*ours == *orig);
  }
}

TEST_CASE("scene0 loads: plane, boxes, dielectrics, a metal sphere", "[loader]") {
  const Scene s = load_scene_file(repo_path("scenes/reference/scene0.xml"));
  REQUIRE(s.lights.size() == 1);
  CHECK(s.lights[0].intensity == Approx(167));
  CHECK(s.camera.yaw == Approx(132.5));
  CHECK(s.camera.up == glm::vec3(0, 1, 0));  // written "0, 1, 0"
  CHECK(s.dot_weight);
  // 1 plane + 10 boxes + 1 sphere + the light's sphere
  CHECK(s.shapes.size() == 13);
  int boxes = 0, dielectrics = 0;
  for (const Shape& sh : s.shapes) boxes += sh.kind() == ShapeKind::Box;
  for (const Material& m : s.materials) dielectrics += m.kind() == MaterialKind::SmoothDielectric;
  CHECK(boxes == 10);
  CHECK(dielectrics == 4);
  const Material& plane_mat = s.materials[size_t(s.shapes[1].material)];
  CHECK(plane_mat.kind() == MaterialKind::Diffuse);
  CHECK(plane_mat.tint.x == Approx(0.8f));  // Attenuate folds into the tint
}

TEST_CASE("scene1: the crystal table with min > max is normalised", "[loader]") {
  const Scene s = load_scene_file(repo_path("scenes/reference/scene1.xml"));
  bool found = false;
  for (const Shape& sh : s.shapes) {
    const Box* b = sh.as<Box>();
    if (!b) continue;
    CHECK(b->min.x <= b->max.x);
    CHECK(b->min.y <= b->max.y);
    CHECK(b->min.z <= b->max.z);
    if (b->min.y == Approx(41.49f) && b->max.y == Approx(42.49f)) found = true;
  }
  CHECK(found);
  int transmit = 0;
  for (const Material& m : s.materials) transmit += m.kind() == MaterialKind::Transmit;
  CHECK(transmit == 1);
}

TEST_CASE("scene2: Cornell box with an emissive box", "[loader]") {
  const Scene s = load_scene_file(repo_path("scenes/reference/scene2.xml"));
  int emitters = 0;
  for (const Shape& sh : s.shapes) {
    const Material& m = s.materials[size_t(sh.material)];
    if (m.kind() == MaterialKind::Emit && sh.light < 0) {
      ++emitters;
      CHECK(m.emission == glm::vec3(69.0f));
    }
  }
  CHECK(emitters == 1);
  const Material& metal = s.materials[size_t(s.shapes[s.shapes.size() - 2].material)];
  REQUIRE(metal.kind() == MaterialKind::Metal);
  CHECK(metal.as<Metal>()->iorComplex == glm::vec2(2.1928f, 3.9379f));
  CHECK(metal.as<Metal>()->glossiness == Approx(0.1f));
}

TEST_CASE("malformed scenes give file, line and problem", "[loader]") {
  const std::string h = kHead;
  CHECK(error_of("<SceneLevel><Camera position=\"0 0 0\"></SceneLevel>").rfind("bad.xml:1: malformed XML", 0) == 0);
  CHECK(error_of(h + "<Objects>\n<Sphere center=\"0 0 0\" radius=\"1\" colour=\"1\"><Diffuse/></Sphere></Objects></SceneLevel>") ==
        "bad.xml:5: <Sphere>: unknown attribute 'colour'");
  CHECK(error_of(h + "<Objects>\n<Sphere center=\"0 0 0\"><Diffuse/></Sphere></Objects></SceneLevel>") ==
        "bad.xml:5: <Sphere>: missing attribute 'radius'");
  CHECK(error_of(h + "<Objects>\n<Sphere center=\"0 0\" radius=\"1\"><Diffuse/></Sphere></Objects></SceneLevel>") ==
        "bad.xml:5: <Sphere>: attribute 'center' needs 3 finite numbers: \"0 0\"");
  CHECK(error_of(h + "<Objects>\n<Sphere center=\"0 nan 0\" radius=\"1\"><Diffuse/></Sphere></Objects></SceneLevel>") ==
        "bad.xml:5: <Sphere>: attribute 'center' needs 3 finite numbers: \"0 nan 0\"");
  CHECK(error_of(h + "<Objects>\n<Sphere center=\"0 0 0\" radius=\"-2\"><Diffuse/></Sphere></Objects></SceneLevel>") ==
        "bad.xml:5: <Sphere>: radius must be positive");
  CHECK(error_of(h + "<Objects>\n<Cone/></Objects></SceneLevel>") == "bad.xml:5: unknown object <Cone>");
  CHECK(error_of(h + "<Objects>\n<Sphere center=\"0 0 0\" radius=\"1\">\n<Velvet/></Sphere></Objects></SceneLevel>") ==
        "bad.xml:6: unknown material <Velvet>");
  CHECK(error_of(h + "<Objects>\n<Sphere center=\"0 0 0\" radius=\"1\"></Sphere></Objects></SceneLevel>") ==
        "bad.xml:5: <Sphere>: needs exactly one material element inside");
  CHECK(error_of(h + "<Objects>\n<Box min=\"0 0 0\" max=\"1 1 1\">\n<Attenuate color=\"1 0 0\"/></Box></Objects></SceneLevel>") ==
        "bad.xml:6: <Attenuate>: must wrap exactly one material");
  CHECK(error_of(h + "<Objects>\n<Box min=\"0 0 0\" max=\"1 1 1\">\n<Emit/></Box></Objects></SceneLevel>") ==
        "bad.xml:6: <Emit>: must contain exactly one <Absorb intensity=\"..\" color=\"..\"/>");
  CHECK(error_of(h + "<Objects>\n<Box min=\"0 0 0\" max=\"1 1 1\">\n<Metal glossiness=\"2\"/></Box></Objects></SceneLevel>") ==
        "bad.xml:6: <Metal>: 'glossiness' must be in [0, 1]");
  CHECK(error_of(h + "<Objects>\n<Plane normal=\"0 0 0\" d=\"1\"><Diffuse/></Plane></Objects></SceneLevel>") ==
        "bad.xml:5: <Plane>: plane normal must be non-zero");
  CHECK(error_of(h + "<Objects>\n<Triangle v0=\"0 0 0\" v1=\"1 1 1\" v2=\"2 2 2\"><Diffuse/></Triangle></Objects></SceneLevel>") ==
        "bad.xml:5: <Triangle>: triangle has zero area");
  CHECK(error_of(h + "<Lamp/>\n</SceneLevel>") == "bad.xml:4: unknown element <Lamp> in <SceneLevel>");
  CHECK(error_of("<?xml version=\"1.0\"?>\n<Scene/>") == "bad.xml:2: the root element must be <SceneLevel>");
  CHECK(error_of(h + "</SceneLevel>") == "bad.xml:2: the scene has no objects and no lights");
  CHECK(error_of("<SceneLevel><Objects/></SceneLevel>") == "bad.xml:1: <SceneLevel> needs a <Camera>");
  CHECK(error_of(h + "<Light position=\"0 0 0\" radius=\"0\"/></SceneLevel>") == "bad.xml:4: <Light>: 'radius' must be positive");
}

TEST_CASE("Environment sets the constant background radiance, strictly", "[loader]") {
  const std::string h = kHead;
  const std::string obj = "<Objects><Sphere center=\"0 0 0\" radius=\"1\"><Diffuse/></Sphere></Objects>";
  CHECK(load_scene_text(h + obj + "</SceneLevel>", "x.xml").environment.color == glm::vec3(0.5f));
  CHECK(load_scene_text(h + "<Environment color=\"0 0.1 2\"/>" + obj + "</SceneLevel>", "x.xml").environment.color ==
        glm::vec3(0.0f, 0.1f, 2.0f));
  CHECK(error_of(h + "<Environment color=\"0 -1 0\"/>" + obj + "</SceneLevel>") == "bad.xml:4: <Environment>: 'color' must be >= 0");
  CHECK(error_of(h + "<Environment/>" + obj + "</SceneLevel>") == "bad.xml:4: <Environment>: give either 'color' or 'map'");
  CHECK(error_of(h + "<Environment color=\"1 1 1\" map=\"a.hdr\"/>" + obj + "</SceneLevel>") ==
        "bad.xml:4: <Environment>: give either 'color' or 'map'");
  CHECK(error_of(h + "<Environment map=\"no-such.hdr\"/>" + obj + "</SceneLevel>") ==
        "bad.xml:4: <Environment>: cannot load the environment map: ./no-such.hdr: cannot open the image file");
}

TEST_CASE("a missing scene file is an error naming the file", "[loader]") {
  try {
    load_scene_file("/nonexistent/scene.xml");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "/nonexistent/scene.xml: cannot open the scene file");
  }
}

TEST_CASE("vectors accept commas and spaces, nothing else", "[loader]") {
  const std::string h = kHead;
  const Scene s = load_scene_text(h + "<Objects><Sphere center=\"1,2 , 3\" radius=\"1\"><Diffuse/></Sphere></Objects></SceneLevel>", "x.xml");
  CHECK(position(s.shapes[0].params) == glm::vec3(1, 2, 3));
  CHECK(error_of(h + "<Objects><Sphere center=\"1 2 3 4\" radius=\"1\"><Diffuse/></Sphere></Objects></SceneLevel>").find("needs 3") !=
        std::string::npos);
  CHECK(error_of(h + "<Objects><Sphere center=\"1;2;3\" radius=\"1\"><Diffuse/></Sphere></Objects></SceneLevel>").find("needs 3") !=
        std::string::npos);
}

TEST_CASE("an environment map loads relative to the scene file, top row first", "[loader]") {
  const std::string dir = std::string(PT_BINARY_DIR) + "/loader-test";
  std::filesystem::create_directories(dir + "/maps");
  // 4x2: the top row bright (theta near 0), the bottom row dark. write_hdr takes rows
  // bottom to top, as GL does.
  std::vector<float> rgba = {0.1f, 0.1f, 0.1f, 1, 0.2f, 0.2f, 0.2f, 1, 0.3f, 0.3f, 0.3f, 1, 0.4f, 0.4f, 0.4f, 1,
                             5, 5, 5, 1, 6, 6, 6, 1, 7, 7, 7, 1, 8, 8, 8, 1};
  REQUIRE(write_hdr(dir + "/maps/sky.hdr", 4, 2, rgba));
  const std::string xml = std::string(kHead) +
                          "<Environment map=\"maps/sky.hdr\" rotation=\"90\" intensity=\"2\"/>\n"
                          "<Objects><Sphere center=\"0 0 0\" radius=\"1\"><Diffuse/></Sphere></Objects></SceneLevel>";
  std::ofstream(dir + "/scene.xml") << xml;
  const Scene s = load_scene_file(dir + "/scene.xml");
  REQUIRE(s.environment.map);
  CHECK(s.environment.map->width == 4);
  CHECK(s.environment.map->height == 2);
  CHECK(s.environment.map->rgba[0] == Approx(5.0f).epsilon(0.01));  // top row first
  CHECK(s.environment.map->rgba[4 * 4] == Approx(0.1f).epsilon(0.01));
  CHECK(s.environment.rotation == 90.0f);
  CHECK(s.environment.intensity == 2.0f);
}

TEST_CASE("Reflect and PhongSpecular", "[loader]") {
  const std::string h = kHead;
  const Scene s = load_scene_text(h +
                                      "<Objects><Sphere center=\"0 0 0\" radius=\"1\"><Reflect/></Sphere>"
                                      "<Sphere center=\"3 0 0\" radius=\"1\"><Attenuate color=\"0.5 0.5 0.5\"><PhongSpecular n=\"100\"/></Attenuate></Sphere>"
                                      "</Objects></SceneLevel>",
                                  "x.xml");
  CHECK(s.materials[0].kind() == MaterialKind::Reflect);
  CHECK(s.materials[1].kind() == MaterialKind::PhongSpecular);
  REQUIRE(s.materials[1].as<PhongSpecular>());
  CHECK(s.materials[1].as<PhongSpecular>()->n == 100.0f);
  CHECK(s.materials[1].tint == glm::vec3(0.5f));
  // Attenuate nests: the colours multiply (the furnace test renders a tint as its albedo).
  const Scene n = load_scene_text(h + "<Objects><Sphere center=\"0 0 0\" radius=\"1\"><Attenuate color=\"0.5 0.5 0.5\">"
                                      "<Attenuate color=\"0.5 1 0.2\"><Diffuse/></Attenuate></Attenuate></Sphere></Objects></SceneLevel>",
                                  "x.xml");
  CHECK(n.materials[0].tint == glm::vec3(0.25f, 0.5f, 0.1f));
  CHECK(error_of(h + "<Objects>\n<Sphere center=\"0 0 0\" radius=\"1\"><PhongSpecular/></Sphere></Objects></SceneLevel>") ==
        "bad.xml:5: <PhongSpecular>: missing attribute 'n'");
}

TEST_CASE("FresnelComposite takes exactly two child materials", "[loader]") {
  const std::string h = kHead;
  const Scene s = load_scene_text(h +
                                      "<Objects><Sphere center=\"0 0 0\" radius=\"1\">"
                                      "<Attenuate color=\"1 0.5 0.5\"><FresnelComposite na=\"1\" nb=\"1.85\">"
                                      "<Reflect/><Attenuate color=\"1 0 0\"><Diffuse/></Attenuate>"
                                      "</FresnelComposite></Attenuate></Sphere></Objects></SceneLevel>",
                                  "x.xml");
  const Material& c = s.materials[size_t(s.shapes[0].material)];
  REQUIRE(c.kind() == MaterialKind::FresnelComposite);
  const FresnelComposite& fc = *c.as<FresnelComposite>();
  CHECK(fc.nb == Approx(1.85f));
  CHECK(s.materials[size_t(fc.reflective)].kind() == MaterialKind::Reflect);
  CHECK(s.materials[size_t(fc.reflective)].tint == glm::vec3(1.0f, 0.5f, 0.5f));  // the outer Attenuate reaches the children
  CHECK(s.materials[size_t(fc.transmissive)].kind() == MaterialKind::Diffuse);
  CHECK(s.materials[size_t(fc.transmissive)].tint == glm::vec3(1.0f, 0.0f, 0.0f));
  CHECK(error_of(h + "<Objects>\n<Sphere center=\"0 0 0\" radius=\"1\"><FresnelComposite><Reflect/></FresnelComposite></Sphere></Objects></SceneLevel>") ==
        "bad.xml:5: <FresnelComposite>: must contain exactly two materials: a reflective one, then a transmissive one");
}

TEST_CASE("camera lens and shutter, sphere velocity", "[loader]") {
  const Scene s = load_scene_text(
      "<SceneLevel><Camera position=\"0 0 10\" aperture=\"0.5\" focalDistance=\"12\" shutter=\"0.25\"/>"
      "<Light position=\"0 5 0\" radius=\"1\" velocity=\"0 1 0\"/>"
      "<Objects><Sphere center=\"0 0 0\" radius=\"1\" velocity=\"1 0 0\"><Diffuse/></Sphere></Objects></SceneLevel>",
      "x.xml");
  CHECK(s.camera.aperture == 0.5f);
  CHECK(s.camera.focal_distance == 12.0f);
  CHECK(s.camera.shutter == 0.25f);
  CHECK(velocity(s.shapes[0].params) == glm::vec3(0, 1, 0));  // the light's sphere
  CHECK(velocity(s.shapes[1].params) == glm::vec3(1, 0, 0));
  CHECK(error_of("<SceneLevel><Camera position=\"0 0 10\" focalDistance=\"0\"/></SceneLevel>") ==
        "bad.xml:1: <Camera>: 'aperture' and 'shutter' must be >= 0 and 'focalDistance' > 0");
  // Every kind moves (tests/motion_test.cpp); a misspelt motion is still refused.
  CHECK(error_of(std::string(kHead) + "<Objects>\n<Box min=\"0 0 0\" max=\"1 1 1\" velocty=\"1 0 0\"><Diffuse/></Box></Objects></SceneLevel>") ==
        "bad.xml:5: <Box>: unknown attribute 'velocty'");
  // `end`: the position at time 1, the same motion as velocity = end - start.
  const Scene e = load_scene_text(std::string(kHead) + "<Light position=\"0 5 0\" radius=\"1\" end=\"0 6 0\"/><Objects>"
                                  "<Sphere center=\"1 2 3\" radius=\"1\" end=\"2 2 1\"><Diffuse/></Sphere></Objects></SceneLevel>",
                                  "x.xml");
  CHECK(velocity(e.shapes[0].params) == glm::vec3(0, 1, 0));
  CHECK(velocity(e.shapes[1].params) == glm::vec3(1, 0, -2));
  CHECK(error_of(std::string(kHead) + "<Objects>\n<Sphere center=\"0 0 0\" radius=\"1\" velocity=\"1 0 0\" end=\"1 1 1\"><Diffuse/></Sphere>"
                 "</Objects></SceneLevel>") == "bad.xml:5: <Sphere>: give either 'velocity' or 'end'");
}

TEST_CASE("<Render>: the settings a scene asks for, each optional and checked", "[loader]") {
  const std::string h = kHead;
  const std::string objs = "<Objects><Sphere center=\"0 0 0\" radius=\"1\"><Diffuse/></Sphere></Objects></SceneLevel>";
  const Scene none = load_scene_text(h + objs, "x.xml");
  CHECK(!none.render.bounces);
  CHECK(!none.render.mode);
  CHECK(!none.render.samples);
  const Scene s = load_scene_text(
      h + "<Render bounces=\"12\" mode=\"whitted\" tonemap=\"filmic\" exposure=\"0.5\" samples=\"256\"/>" + objs, "x.xml");
  CHECK(s.render.bounces == 12);
  CHECK(s.render.mode == RenderMode::Whitted);
  CHECK(s.render.tonemap == ToneMap::Filmic);
  CHECK(s.render.exposure == 0.5f);
  CHECK(s.render.samples == 256);
  const Scene part = load_scene_text(h + "<Render samples=\"0\"/>" + objs, "x.xml");
  CHECK(part.render.samples == 0);
  CHECK(!part.render.bounces);
  CHECK(error_of(h + "<Render bounces=\"0\"/>" + objs) == "bad.xml:4: <Render>: 'bounces' must be an integer in 1..64");
  CHECK(error_of(h + "<Render bounces=\"2.5\"/>" + objs) == "bad.xml:4: <Render>: 'bounces' must be an integer in 1..64");
  CHECK(error_of(h + "<Render mode=\"raster\"/>" + objs) == "bad.xml:4: <Render>: 'mode' must be path, whitted or sh");
  CHECK(error_of(h + "<Render exposure=\"0\"/>" + objs) == "bad.xml:4: <Render>: 'exposure' must be positive");
  CHECK(error_of(h + "<Render spp=\"4\"/>" + objs) == "bad.xml:4: <Render>: unknown attribute 'spp'");
  CHECK(error_of(h + "<Render/>\n<Render/>" + objs) == "bad.xml:5: a second <Render>");
}

// The loader audit (issue 15): what is merely unusual loads, as the 2016 program loads it;
// each refused limit has its case in tests/malformed/ (docs/scene-format.md, "Limits").
TEST_CASE("unusual but meaningful values load: extreme IORs, any pitch, exponent 0, exposure and map energy", "[loader]") {
  const std::string h = "<SceneLevel>\n<Camera position=\"0 0 10\" yaw=\"90\"/>\n<Objects>\n";
  auto one = [&](const std::string& obj) { return load_scene_text(h + obj + "\n</Objects></SceneLevel>", "x.xml"); };
  auto sphere = [](const std::string& m) { return "<Sphere center=\"0 0 0\" radius=\"1\">" + m + "</Sphere>"; };
  // ior="120.5": the 2016 program's near-perfect mirror (was refused: "must be in (0, 100]").
  CHECK(one(sphere("<SmoothDielectric ior=\"120.5\"/>")).materials.size() == 1);
  CHECK_NOTHROW(one(sphere("<SmoothDielectric ior=\"1e9\"/>")));
  CHECK_NOTHROW(one(sphere("<SmoothDielectric ior=\"1e-9\"/>")));
  CHECK_NOTHROW(one(sphere("<Transmit outerIor=\"200\" innerIor=\"0.5\"/>")));
  CHECK_NOTHROW(one(sphere("<FresnelComposite na=\"1\" nb=\"150\"><Reflect/><Diffuse/></FresnelComposite>")));
  CHECK_NOTHROW(one(sphere("<Metal ior=\"500\" glossiness=\"1\"/>")));
  CHECK_NOTHROW(one(sphere("<MetallicRoughness ior=\"300\"/>")));
  CHECK_NOTHROW(one(sphere("<PhongSpecular n=\"0\"/>")));
  CHECK_NOTHROW(one(sphere("<PhongSpecular n=\"100000\"/>")));
  CHECK_NOTHROW(one(sphere("<Textured n=\"0\" uvScale=\"0 0\"/>")));  // uvScale 0: one texel everywhere
  CHECK_NOTHROW(one(sphere("<PerlinTexture scale=\"1e-6\"/>")));
  CHECK_NOTHROW(one("<Sphere center=\"0 0 0\" radius=\"1e-6\"><Diffuse/></Sphere>"));
  // The camera: straight up (pitch 90 with up +y is an exact basis), upside down, any yaw.
  for (const char* cam : {"pitch=\"90\"", "pitch=\"-90\"", "pitch=\"120\"", "pitch=\"400\" yaw=\"-1000\"", "up=\"1 0 0\" yaw=\"90\""}) {
    INFO(cam);
    const Scene s = load_scene_text(std::string("<SceneLevel>\n<Camera position=\"0 0 10\" ") + cam + "/>\n<Objects>\n" +
                                        sphere("<Diffuse/>") + "\n</Objects></SceneLevel>",
                                    "x.xml");
    const glm::vec3 r = glm::normalize(glm::cross(camera_forward(s.camera), s.camera.up));
    CHECK(std::isfinite(r.x + r.y + r.z));
    CHECK(std::abs(glm::length(r) - 1.0f) < 1e-5f);
  }
  const std::string objs = "<Objects>\n" + sphere("<Diffuse/>") + "\n</Objects></SceneLevel>";
  CHECK(load_scene_text("<SceneLevel>\n<Camera position=\"0 0 10\"/>\n<Render exposure=\"5000\"/>\n" + objs, "x.xml").render.exposure == 5000.0f);
  CHECK(load_scene_text("<SceneLevel>\n<Camera position=\"0 0 10\"/>\n<Environment map=\"" + repo_path("assets/sky-gradient.hdr") +
                            "\" intensity=\"1e7\"/>\n" + objs,
                        "x.xml")
            .environment.intensity == 1e7f);
}

TEST_CASE("a generated-triangle budget (the fuzzer's) caps <Mesh generate>, counting a source once", "[loader]") {
  const std::string h = kHead;
  auto mesh = [](int level, const char* displace) {
    return "<Mesh generate=\"icosphere\" level=\"" + std::to_string(level) + "\" displace=\"" + displace + "\"><Diffuse/></Mesh>\n";
  };
  // 3 x level 6 = 3 x 81,920 = 245,760 <= 2^18; the same source twice is made once.
  const std::string three = h + "<Objects>\n" + mesh(6, "0") + mesh(6, "0.1") + mesh(6, "0.2") + mesh(6, "0.2") + "</Objects></SceneLevel>";
  CHECK(pt::load_scene_text(three, "ok.xml", false, 1ll << 18).meshes.size() == 3);
  const std::string four = h + "<Objects>\n" + mesh(6, "0") + mesh(6, "0.1") + mesh(6, "0.2") + mesh(6, "0.3") + "</Objects></SceneLevel>";
  try {
    pt::load_scene_text(four, "bad.xml", false, 1ll << 18);
    FAIL("over the budget, yet loaded");
  } catch (const pt::InputError& e) {
    CHECK(std::string(e.what()) == "bad.xml:8: <Mesh>: the generated meshes make 327680 triangles, over this load's budget of 262144");
  }
  CHECK(pt::load_scene_text(four, "nobudget.xml", false).meshes.size() == 4);  // no budget: a legal scene
}
