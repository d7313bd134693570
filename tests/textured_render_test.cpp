// Textured through the production integrator: a flat normal map renders exactly as no
// normal map; a tilted one under a uniform sky gives the closed form (1 + cos tau) / 2;
// white furnaces; the Lambert + Phong mixture's albedo against its closed form; the
// procedural textures on every shape kind; a JPEG read by the loader.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/image.h"
#include "gl_context.h"
#include "glsl_harness.h"
#include "scene/xml_loader.h"
#include "scene_builders.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

using namespace pt;

namespace {

std::string dir() {
  const std::string d = std::string(PT_BINARY_DIR) + "/textured-test";
  std::filesystem::create_directories(d);
  return d;
}

// A PNG whose every texel is `rgb` (8-bit codes); with `noise`, texels vary around it.
std::string png(const std::string& name, glm::ivec3 rgb, bool noise = false) {
  const int n = 8;
  std::vector<uint8_t> px;
  for (int i = 0; i < n * n; ++i)
    for (int c = 0; c < 4; ++c) px.push_back(c == 3 ? 255 : uint8_t(noise ? (rgb[c] + 37 * i * (c + 1)) % 256 : rgb[c]));
  const std::string path = dir() + "/" + name;
  REQUIRE(write_png(path, n, n, px));
  return path;
}

double max_abs_diff(const RenderResult& a, const RenderResult& b) {
  double d = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) d = std::max(d, double(std::abs(a.rgba[i] - b.rgba[i])));
  return d;
}

void check_close(const char* what, Estimate e, double exact) {
  std::printf("%-58s %.5f  exact %.5f  (%+.2f se, se %.5f)\n", what, e.mean, exact, (e.mean - exact) / e.se, e.se);
  INFO(what << ": " << e.mean << " vs " << exact << " (se " << e.se << ")");
  CHECK(std::abs(e.mean - exact) < 4.0 * e.se + 1e-6 * exact);
}

// Directional albedo of the normalised modified Phong lobe (n + 2) / (2 pi) cos^n(alpha)
// clipped to the upper hemisphere, at incidence cos_o (midpoint rule in (theta, phi)).
double phong_albedo(double n, double cos_o) {
  const double pi = 3.14159265358979323846, so = std::sqrt(1 - cos_o * cos_o);
  const int nt = 2000, np = 2000;
  double sum = 0;
  for (int i = 0; i < nt; ++i) {
    const double th = (i + 0.5) * (pi / 2) / nt, st = std::sin(th), ct = std::cos(th);
    for (int j = 0; j < np; ++j) {
      const double ph = (j + 0.5) * 2 * pi / np;
      const double c = -so * st * std::cos(ph) + cos_o * ct;  // dot(wi, mirror of wo = (-so, 0, cos_o))
      if (c > 0) sum += (n + 2) / (2 * pi) * std::pow(c, n) * ct * st;
    }
  }
  return sum * (pi / 2 / nt) * (2 * pi / np);
}

}  // namespace

TEST_CASE("normal maps: a flat map renders exactly as no map", "[gpu][textured]") {
  test_gl();
  const std::string diffuse = png("noisy.png", {200, 120, 40}, true), flat = png("flat.png", {128, 128, 255});
  auto scene = [&](const std::string& extra) {
    const std::string m = "<Textured diffuse=\"" + diffuse + "\" specular=\"" + png("spec.png", {90, 90, 90}) + "\" n=\"20\" uvScale=\"0.7 0.7\"" + extra + "/>";
    return load_scene_text("<SceneLevel><Camera position=\"0 4 6\" yaw=\"90\" pitch=\"-30\"/>"
                           "<Light position=\"1 5 0\" radius=\"0.5\" intensity=\"30\"/><Objects>"
                           "<Plane normal=\"0 1 0\" d=\"0\">" + m + "</Plane><Sphere center=\"-1 1 0\" radius=\"1\">" + m + "</Sphere>"
                           "<Box min=\"1 0 -1\" max=\"2 1.5 0\">" + m + "</Box>"
                           "<Triangle v0=\"-2 0 -2\" v1=\"2 0 -2\" v2=\"0 3 -2\" uv1=\"2 0\" uv2=\"1 2\">" + m + "</Triangle></Objects></SceneLevel>",
                           dir() + "/flat.xml");
  };
  const RenderResult a = render_scene(scene(""), 48, 48, 16);
  const RenderResult b = render_scene(scene(" normal=\"" + flat + "\""), 48, 48, 16);
  CHECK(a.counters.bad_samples == 0);
  CHECK(max_abs_diff(a, b) == 0.0);
  // A bumpy map changes the image (the test can tell).
  const RenderResult c = render_scene(scene(" normal=\"" + png("bumpy.png", {128, 128, 255}, true) + "\""), 48, 48, 16);
  CHECK(c.counters.bad_samples == 0);
  CHECK(max_abs_diff(a, c) > 0.05);
}

TEST_CASE("normal maps: a tilted normal under a uniform sky sees (1 + cos tau) / 2 of it", "[gpu][textured]") {
  // A white Lambertian plane under sky radiance 1: with the shading normal tilted by tau
  // the BSDF's cosine lobe reaches below the geometric surface, where no light comes from
  // (and none may leak through): radiance = integral over the upper hemisphere of
  // max(0, cos(n_s, w)) / pi = (1 + cos tau) / 2.
  test_gl();
  for (int tilt_code : {128, 209, 245}) {  // x component of the map: 0, ~0.64, ~0.92
    const int z_code = int(std::lround(128 + 127 * std::sqrt(std::max(0.0, 1 - std::pow((tilt_code - 128) / 127.0, 2)))));
    const std::string map = png("tilt" + std::to_string(tilt_code) + ".png", {tilt_code, 128, z_code});
    const double x = (tilt_code - 128) / 127.0, z = (z_code - 128) / 127.0, cos_tau = z / std::sqrt(x * x + z * z);
    const Scene s = load_scene_text("<SceneLevel><Camera position=\"0.3 10 0.2\" pitch=\"-89.9\"/><Environment color=\"1 1 1\"/><Objects>"
                                    "<Plane normal=\"0 1 0\" d=\"0\"><Textured normal=\"" + map + "\"/></Plane></Objects></SceneLevel>",
                                    dir() + "/tilt.xml");
    const RenderResult r = render_scene(s, 32, 32, 64);
    CHECK(r.counters.bad_samples == 0);
    const std::string what = "sky on a plane tilted by normal map, cos tau = " + std::to_string(cos_tau);
    check_close(what.c_str(), region_mean(r, 0, 0, 32, 32), (1 + cos_tau) / 2);
  }
}

TEST_CASE("white furnace: Textured with a white diffuse map returns 1, with specular <= 1", "[gpu][textured][transport]") {
  test_gl();
  RenderSettings st;
  st.max_bounces = 64;
  auto furnace = [&](const std::string& attrs) {
    return load_scene_text("<SceneLevel><Camera position=\"0 0 4\" yaw=\"90\"/><Environment color=\"1 1 1\"/><Objects>"
                           "<Sphere center=\"0 0 0\" radius=\"1\"><Textured " + attrs + "/></Sphere></Objects></SceneLevel>",
                           dir() + "/furnace.xml");
  };
  const std::string white = png("white.png", {255, 255, 255});
  const RenderResult r = render_scene(furnace("diffuse=\"" + white + "\""), 64, 64, 64, st);
  CHECK(r.counters.bad_samples == 0);
  check_close("furnace: Textured, white diffuse map -> 1", region_mean(r, 24, 24, 40, 40), 1.0);
  // With a bumpy normal map too: shading normals may lose energy, never make it.
  const RenderResult b = render_scene(furnace("diffuse=\"" + white + "\" normal=\"" + png("bumpy2.png", {128, 128, 255}, true) + "\""), 64, 64, 64, st);
  const Estimate eb = region_mean(b, 24, 24, 40, 40);
  std::printf("furnace: Textured, white diffuse, bumpy normal map: %.5f (se %.5f)\n", eb.mean, eb.se);
  CHECK(eb.mean <= 1.0 + 4 * eb.se);
  // Specular 0.5 (code 188 is linear 0.5029), n = 20: the sphere's pixels see albedos
  // (1 - s) + s A_20(theta_o) <= 1, equal to 1 at the centre, where A_20(0) = 1.
  const RenderResult sp = render_scene(furnace("diffuse=\"" + white + "\" specular=\"" + png("half.png", {188, 188, 188}) + "\" n=\"20\""), 64, 64, 64, st);
  const Estimate all = region_mean(sp, 24, 24, 40, 40), centre = region_mean(sp, 31, 31, 33, 33);
  std::printf("furnace: Textured with specular 0.5: sphere %.5f (se %.5f), centre %.5f (se %.5f)\n", all.mean, all.se, centre.mean, centre.se);
  CHECK(all.mean <= 1.0 + 4 * all.se);
  CHECK(all.mean < 0.99);  // the specular lobe's energy lost below the horizon at grazing angles
  check_close("furnace: Textured with specular, centre pixels -> ~1", centre, 1.0 - 0.5029 * (1.0 - phong_albedo(20, std::cos(0.03))));
}

TEST_CASE("Textured mixture albedo: (1 - s) rho + s A_n(theta_o), sampled weights", "[gpu][textured]") {
  // The record as resolve_textured leaves it: tint = (1 - s) rho, the hit field spec = s.
  const double s = 0.4, n = 30;
  for (double cos_o : {1.0, 0.5, 0.1}) {
    char setup[512];
    std::snprintf(setup, sizeof setup,
                  "const vec3 WO = vec3(%.9f, 0.0, %.9f);\nvec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 77u), 0u);\n"
                  "  MaterialRec m = packed_textured();\n  TexturedRec q = textured_rec(m);\n  q.spec = vec3(%.6f);\n  m = with_textured_rec(m, q);\n"
                  "  BsdfSample b;\n  if (!material_sample(m, WO, true, vec3(rand01(), rand01(), rand01()), b)) return vec4(0.0);\n"
                  "  return vec4(b.weight, 1.0);\n}\n",
                  std::sqrt(1 - cos_o * cos_o), cos_o, s);
    GlslKernel k(glsl_material(Material(Textured{.n = float(n)}, glm::vec3(float(1 - s))), "packed_textured") + setup);
    k.program().use();
    k.program().set("u_dot_weight", 1);
    const int N = 1000000;
    double sum = 0, sq = 0;
    for (const glm::vec4& v : k.run(N)) {
      sum += v.x;
      sq += double(v.x) * v.x;
    }
    const double mean = sum / N, se = std::sqrt((sq / N - mean * mean) / N);
    const double exact = (1 - s) + s * phong_albedo(n, cos_o);
    const std::string what = "Textured albedo, s = 0.4, n = 30, cos_o = " + std::to_string(cos_o);
    check_close(what.c_str(), {mean, se}, exact);
    if (cos_o == 1.0) CHECK(exact == Approx(1.0).epsilon(1e-4));
  }
}

TEST_CASE("procedural textures render on every shape kind without NaN", "[gpu][textured][texture]") {
  test_gl();
  for (const char* tex : {"ChessTexture", "WorleyTexture", "PerlinTexture", "FormulaTexture", "FormulaPowTexture"}) {
    const std::string m = std::string("<") + tex + " color1=\"0.9 0.8 0.7\" color2=\"0.1 0.2 0.3\" scale=\"0.4\"/>";
    const Scene s = load_scene_text("<SceneLevel><Camera position=\"0 3 6\" yaw=\"90\" pitch=\"-20\"/><Light position=\"1 5 2\" radius=\"0.5\" intensity=\"30\"/><Objects>"
                                    "<Plane normal=\"0 1 0\" d=\"0\">" + m + "</Plane><Sphere center=\"-1.5 1 0\" radius=\"1\">" + m + "</Sphere>"
                                    "<Box min=\"0.5 0 -1\" max=\"2 1.5 0.5\">" + m + "</Box>"
                                    "<Triangle v0=\"-3 0 -2\" v1=\"3 0 -2\" v2=\"0 3 -2\">" + m + "</Triangle></Objects></SceneLevel>",
                                    "proc.xml");
    const RenderResult r = render_scene(s, 32, 32, 8);
    INFO(tex);
    CHECK(r.counters.bad_samples == 0);
    const ImageStats st = image_stats(r.rgba);
    CHECK(st.bad == 0);
    CHECK(st.max_lum > 0.05);
  }
}

TEST_CASE("a JPEG diffuse map loads and decodes from sRGB", "[loader][textured]") {
  std::vector<uint8_t> rgb(16 * 16 * 3);
  for (size_t i = 0; i < rgb.size(); i += 3) rgb[i] = 188, rgb[i + 1] = 128, rgb[i + 2] = 40;
  const std::string path = dir() + "/tile.jpg";
  REQUIRE(stbi_write_jpg(path.c_str(), 16, 16, 3, rgb.data(), 95));
  const Scene s = load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects><Sphere center=\"0 0 0\" radius=\"1\"><Textured diffuse=\"tile.jpg\"/></Sphere></Objects></SceneLevel>",
                                  dir() + "/j.xml");
  REQUIRE(s.images.size() == 1);
  const ImageMap& m = *s.images[0];
  CHECK(m.width == 16);
  CHECK(m.rgba[0] == Approx(0.5029).margin(0.01));  // JPEG is lossy: a few codes off
  CHECK(m.rgba[1] == Approx(0.2159).margin(0.01));
  CHECK(m.rgba[2] == Approx(0.0213).margin(0.005));
}
