// Procedural textures: exact chess cells, the range and variety of the noises, and a
// texture of one colour rendering exactly as the Diffuse material it resolves to.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/error.h"
#include "gl_context.h"
#include "glsl_harness.h"
#include "scene/xml_loader.h"
#include "scene_builders.h"

using namespace pt;

TEST_CASE("chess cells alternate across the origin", "[gpu][texture]") {
  GlslKernel k("vec4 kernel(vec4 x, int i) { return vec4(chess_pattern(x.xyz, 2.0)); }\n");
  const std::vector<glm::vec4> out = k.run({{1, 1, 1, 0}, {3, 1, 1, 0}, {-1, 1, 1, 0}, {-1, -1, 1, 0}, {-1, -1, -1, 0}, {4.5f, 2.5f, 0.5f, 0}});
  CHECK(out[0].x == 0.0f);
  CHECK(out[1].x == 1.0f);
  CHECK(out[2].x == 1.0f);
  CHECK(out[3].x == 0.0f);
  CHECK(out[4].x == 1.0f);
  CHECK(out[5].x == 1.0f);  // cells (2, 1, 0)
}

TEST_CASE("noise textures stay in [0, 1] and vary", "[gpu][texture]") {
  for (const char* pattern : {"perlin_pattern", "worley_pattern", "formula_pattern", "formula_pow_pattern"}) {
    GlslKernel k(std::string("vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 9u), 0u);\n"
                             "  vec3 p = (vec3(rand01(), rand01(), rand01()) - 0.5) * 200.0;\n  return vec4(") +
                 pattern + "(p, 7.0));\n}\n");
    double lo = 1e9, hi = -1e9, sum = 0, sq = 0;
    const std::vector<glm::vec4> out = k.run(20000);
    for (const glm::vec4& v : out) {
      lo = std::min(lo, double(v.x));
      hi = std::max(hi, double(v.x));
      sum += v.x;
      sq += double(v.x) * v.x;
    }
    const double mean = sum / double(out.size()), sd = std::sqrt(sq / double(out.size()) - mean * mean);
    INFO(pattern << ": range [" << lo << ", " << hi << "], mean " << mean << ", sd " << sd);
    CHECK(lo >= 0.0);
    CHECK(hi <= 1.0);
    CHECK(sd > 0.05);
  }
}

TEST_CASE("a one-colour texture renders exactly as Diffuse of that colour", "[gpu][texture]") {
  test_gl();
  auto scene = [](const std::string& material) {
    return load_scene_text("<SceneLevel><Camera position=\"0 4 6\" yaw=\"90\" pitch=\"-30\"/>"
                           "<Light position=\"1 5 0\" radius=\"0.5\" intensity=\"30\"/><Objects>"
                           "<Plane normal=\"0 1 0\" d=\"0\">" + material + "</Plane>"
                           "<Sphere center=\"0 1 0\" radius=\"1\">" + material + "</Sphere></Objects></SceneLevel>",
                           "t.xml");
  };
  const RenderResult a = render_scene(scene("<ChessTexture color1=\"0.3 0.5 0.7\" color2=\"0.3 0.5 0.7\" scale=\"0.5\"/>"), 32, 32, 16);
  const RenderResult b = render_scene(scene("<Attenuate color=\"0.3 0.5 0.7\"><Diffuse/></Attenuate>"), 32, 32, 16);
  double worst = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) worst = std::max(worst, double(std::abs(a.rgba[i] - b.rgba[i])));
  CHECK(worst < 1e-5);
  // Two colours: the image changes.
  const RenderResult c = render_scene(scene("<ChessTexture color1=\"0.9 0.9 0.9\" color2=\"0.1 0.1 0.1\" scale=\"0.5\"/>"), 32, 32, 16);
  double diff = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) diff = std::max(diff, double(std::abs(c.rgba[i] - b.rgba[i])));
  CHECK(diff > 0.05);
}

TEST_CASE("texture elements are strict", "[loader][texture]") {
  const std::string h = "<SceneLevel><Camera position=\"0 0 5\"/><Objects>\n<Sphere center=\"0 0 0\" radius=\"1\">";
  const Scene s = load_scene_text(h + "<WorleyTexture color1=\"1 0 0\" color2=\"0 0 1\" scale=\"3\"/></Sphere></Objects></SceneLevel>", "x.xml");
  REQUIRE(s.materials[0].kind() == MaterialKind::WorleyTexture);
  const WorleyTexture& w = *s.materials[0].as<WorleyTexture>();
  CHECK(w.color1 == glm::vec3(1, 0, 0));
  CHECK(w.color2 == glm::vec3(0, 0, 1));
  CHECK(w.scale == 3.0f);
  try {
    load_scene_text(h + "<PerlinTexture scale=\"0\"/></Sphere></Objects></SceneLevel>", "x.xml");
    FAIL("loaded");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "x.xml:2: <PerlinTexture>: 'scale' must be positive");
  }
}
