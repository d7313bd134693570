// Image textures (<Textured>): uv mappings of every shape against closed forms, the
// texture-array lookup (texel centres, bilinear mixes, wrap-around), decoding, normal
// mapping (a flat map changes nothing, a tilted one changes the cosine as the closed
// form says), white furnaces and the mixture's albedo, loader errors, GL limits.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "core/file_io.h"
#include "core/image.h"
#include "gl_context.h"
#include "glsl_harness.h"
#include "gpu/texture_array.h"
#include "render/image_maps.h"
#include "scene/textured_loader.h"
#include "scene/xml_loader.h"
#include "scene_builders.h"
#include "stats.h"

using namespace pt;

namespace {

std::string tmp_dir() {
  const std::string d = std::string(PT_BINARY_DIR) + "/textured-test";
  std::filesystem::create_directories(d);
  return d;
}

// A w x h PNG of one 8-bit RGB colour; returns its path.
std::string solid_png(const std::string& name, int r, int g, int b, int w = 4, int h = 4) {
  std::vector<uint8_t> px;
  for (int i = 0; i < w * h; ++i) px.insert(px.end(), {uint8_t(r), uint8_t(g), uint8_t(b), uint8_t(255)});
  const std::string path = tmp_dir() + "/" + name;
  REQUIRE(write_png(path, w, h, px));
  return path;
}

glm::vec4 run_one(const std::string& body) { return GlslKernel("vec4 kernel(vec4 x, int i) {\n" + body + "\n}\n").run(1)[0]; }

void check_vec(glm::vec4 got, glm::vec4 want, float tol, const char* what) {
  INFO(what << ": got (" << got.x << ", " << got.y << ", " << got.z << ", " << got.w << ") want (" << want.x << ", " << want.y
            << ", " << want.z << ", " << want.w << ")");
  CHECK(glm::all(glm::lessThanEqual(glm::abs(got - want), glm::vec4(tol))));
}

}  // namespace

TEST_CASE("uv mappings: closed forms at known points", "[gpu][textured]") {
  const char* sphere = "vec3 c = vec3(1.0, 2.0, 3.0); ShapeRec s; s.kind = SHAPE_SPHERE; s = with_sphere_rec(s, SphereRec(c, 2.0, vec3(0.0)));\n";
  struct C {
    std::string body;
    glm::vec4 want;
  };
  for (const C& c : std::vector<C>{
           // sphere: u = atan(-n.z, n.x) / 2pi (mod 1), v = 1 - acos(n.y) / pi; tangent in zw (x, z)
           {std::string(sphere) + "vec3 n = vec3(1, 0, 0); vec4 t = tangent_sphere(s, c + 2.0 * n, n); return vec4(uv_sphere(s, c + 2.0 * n, n), t.x, t.z);", {0, 0.5f, 0, -1}},
           {std::string(sphere) + "vec3 n = vec3(0, 0, -1); vec4 t = tangent_sphere(s, c + 2.0 * n, n); return vec4(uv_sphere(s, c + 2.0 * n, n), t.x, t.z);", {0.25f, 0.5f, -1, 0}},
           {std::string(sphere) + "vec3 n = vec3(-1, 0, 0); return vec4(uv_sphere(s, c + 2.0 * n, n), 0, 0);", {0.5f, 0.5f, 0, 0}},
           {std::string(sphere) + "vec3 n = vec3(0, 0, 1); return vec4(uv_sphere(s, c + 2.0 * n, n), 0, 0);", {0.75f, 0.5f, 0, 0}},
           {std::string(sphere) + "vec3 n = vec3(0, 1, 0); vec4 t = tangent_sphere(s, c + 2.0 * n, n); return vec4(uv_sphere(s, c + 2.0 * n, n), t.x, t.z);", {0, 1, 0, -1}},
           {std::string(sphere) + "vec3 n = vec3(0, -1, 0); return vec4(uv_sphere(s, c + 2.0 * n, n), 0, 0);", {0, 0, 0, 0}},
           {std::string(sphere) + "vec3 n = normalize(vec3(1, 1, 0)); return vec4(uv_sphere(s, c + 2.0 * n, n), 0, 0);", {0, 0.75f, 0, 0}},
           // box [0,2]x[0,4]x[0,8]: every face spans [0, 1]^2
           {"ShapeRec s; s.kind = SHAPE_BOX; s = with_box_rec(s, BoxRec(vec3(0.0), vec3(2.0, 4.0, 8.0), vec3(0.0)));\n return vec4(uv_box(s, vec3(2, 1, 2), vec3(1, 0, 0)), uv_box(s, vec3(0, 1, 2), vec3(-1, 0, 0)));", {0.75f, 0.25f, 0.25f, 0.25f}},
           {"ShapeRec s; s.kind = SHAPE_BOX; s = with_box_rec(s, BoxRec(vec3(0.0), vec3(2.0, 4.0, 8.0), vec3(0.0)));\n return vec4(uv_box(s, vec3(1, 4, 6), vec3(0, 1, 0)), uv_box(s, vec3(1, 0, 6), vec3(0, -1, 0)));", {0.5f, 0.25f, 0.5f, 0.75f}},
           {"ShapeRec s; s.kind = SHAPE_BOX; s = with_box_rec(s, BoxRec(vec3(0.0), vec3(2.0, 4.0, 8.0), vec3(0.0)));\n return vec4(uv_box(s, vec3(0.5, 3, 8), vec3(0, 0, 1)), uv_box(s, vec3(0.5, 3, 0), vec3(0, 0, -1)));", {0.25f, 0.75f, 0.75f, 0.75f}},
           // plane: scene units in frame_from(normal): the floor has u = x, v = -z
           {"vec3 nn = vec3(0, 1, 0); ShapeRec s; s.kind = SHAPE_PLANE; s = with_plane_rec(s, PlaneRec(nn, 0.0, vec3(0.0)));\n vec4 t = tangent_plane(s, vec3(3, 0, -5), nn); return vec4(uv_plane(s, vec3(3, 0, -5), nn), t.x, t.z);", {3, 5, 1, 0}},
           {"vec3 nn = vec3(0, 0, 1); ShapeRec s; s.kind = SHAPE_PLANE; s = with_plane_rec(s, PlaneRec(nn, 2.0, vec3(0.0)));\n return vec4(uv_plane(s, vec3(3, 4, 2), nn), 0, 0);", {3, 4, 0, 0}},
           // triangle: barycentric interpolation of the vertex uv
           {"ShapeRec s; s.kind = SHAPE_TRIANGLE; s = with_triangle_rec(s, TriangleRec(vec3(0), vec3(2, 0, 0), vec3(0, 2, 0), vec3(0.0)));\n UvRec t; t.uv0 = vec2(0, 0); t.uv1 = vec2(1, 0); t.uv2 = vec2(0, 1);\n"
            " UvRec q; q.uv0 = vec2(0.1, 0.2); q.uv1 = vec2(0.9, 0.2); q.uv2 = vec2(0.1, 1.0);\n vec3 p = vec3(1, 0.5, 0), n = vec3(0, 0, 1);\n"
            " return vec4(uv_triangle(s, t, p, n), uv_triangle(s, q, p, n));", {0.5f, 0.25f, 0.5f, 0.4f}},
           {"ShapeRec s; s.kind = SHAPE_TRIANGLE; s = with_triangle_rec(s, TriangleRec(vec3(0), vec3(2, 0, 0), vec3(0, 2, 0), vec3(0.0)));\n UvRec t; t.uv0 = vec2(0, 0); t.uv1 = vec2(-1, 0); t.uv2 = vec2(0, 1);\n"
            " vec4 a = tangent_triangle(s, t, vec3(0.5), vec3(0, 0, 1)); return vec4(a.x, a.y, a.z, a.w);", {-1, 0, 0, -1}},
       }) {
    // Sphere uv go through atan (GPU transcendentals: about 1e-6 here, less exact elsewhere).
    check_vec(run_one(c.body), c.want, 1e-5f, c.body.c_str());
  }
}

TEST_CASE("uv mappings: the tangent frame follows the uv gradient on every shape", "[gpu][textured]") {
  // At random surface points: moving by eps along t raises u (by eps |du/dp|) and keeps v;
  // moving along b = w cross(n, t) raises v and keeps u.
  GlslKernel k(
      "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 5u), 0u);\n  int kind = i % 4;\n  ShapeRec s;\n  vec3 sa = vec3(0.0), sb = vec3(0.0), sc = vec3(0.0); float sr = 2.0;\n"
      "  vec3 n, p; UvRec t; t.uv0 = vec2(0.3, 0.1); t.uv1 = vec2(0.9, 0.4); t.uv2 = vec2(0.2, 0.8);\n"
      "  float a = TWO_PI * (0.05 + 0.4 * rand01()), c = 0.8 * rand01() - 0.4;\n"
      "  if (kind == 0) { s.kind = SHAPE_SPHERE; sa = vec3(1.0); n = vec3(sqrt(1.0 - c * c) * cos(a), c, sqrt(1.0 - c * c) * sin(a)); p = sa + 2.0 * n; }\n"
      "  if (kind == 1) { s.kind = SHAPE_BOX; sa = vec3(-1.0); sb = vec3(2.0, 3.0, 1.0); int f = int(6.0 * rand01()) % 6; vec3 ax = f % 3 == 0 ? vec3(1, 0, 0) : (f % 3 == 1 ? vec3(0, 1, 0) : vec3(0, 0, 1));\n"
      "    n = f < 3 ? ax : -ax; p = mix(sa, sb, vec3(0.2 + 0.6 * rand01(), 0.2 + 0.6 * rand01(), 0.2 + 0.6 * rand01())); p = mix(p, f < 3 ? sb : sa, ax); }\n"
      "  if (kind == 2) { s.kind = SHAPE_PLANE; sa = normalize(vec3(rand01() - 0.5, rand01() - 0.5, rand01() - 0.5)); sr = 0.7; n = sa; p = frame_from(n).t * 3.0 * rand01() + n * 0.7; }\n"
      "  if (kind == 3) { s.kind = SHAPE_TRIANGLE; sa = vec3(0.0); sb = vec3(2.0, 0.5, 0.0); sc = vec3(0.3, 1.5, 1.0); n = normalize(cross(sb - sa, sc - sa));\n"
      "    float r = 0.2 + 0.5 * rand01(); p = sa + r * (sb - sa) * 0.5 + r * (sc - sa) * 0.5; }\n"
      "  if (kind == 0) s = with_sphere_rec(s, SphereRec(sa, sr, vec3(0.0)));\n"
      "  if (kind == 1) s = with_box_rec(s, BoxRec(sa, sb, vec3(0.0)));\n"
      "  if (kind == 2) s = with_plane_rec(s, PlaneRec(sa, sr, vec3(0.0)));\n"
      "  if (kind == 3) s = with_triangle_rec(s, TriangleRec(sa, sb, sc, vec3(0.0)));\n"
      "  SurfaceUv su = surface_uv(s, Hit(1.0, 0, n, p, -1));\n"
      "  if (kind == 3) { su.uv = uv_triangle(s, t, p, n); su.tangent = tangent_triangle(s, t, p, n); }\n"
      "  vec3 b = su.tangent.w * cross(n, su.tangent.xyz);\n  float e = 1e-3;\n"
      "  vec3 pt = p + e * su.tangent.xyz, pb = p + e * b;\n  if (kind == 0) { pt = sa + 2.0 * normalize(pt - sa); pb = sa + 2.0 * normalize(pb - sa); }\n"
      "  vec3 nt = kind == 0 ? normalize(pt - sa) : n, nb = kind == 0 ? normalize(pb - sa) : n;\n"
      "  vec2 ut = kind == 3 ? uv_triangle(s, t, pt, n) : surface_uv(s, Hit(1.0, 0, nt, pt, -1)).uv;\n"
      "  vec2 ub = kind == 3 ? uv_triangle(s, t, pb, n) : surface_uv(s, Hit(1.0, 0, nb, pb, -1)).uv;\n"
      "  vec2 dt = ut - su.uv, db = ub - su.uv;\n"
      // An affine uv map need not be orthogonal (the triangle's is not): there b only has to
      // point to the side of dp/dv, and moving along it may change u.
      "  return vec4(dt.x, abs(dt.y) / max(abs(dt.x), 1e-12), db.y, kind == 3 ? 0.0 : abs(db.x) / max(abs(db.y), 1e-12));\n}\n");
  int bad = 0;
  const std::vector<glm::vec4> out = k.run(4000);
  for (size_t i = 0; i < out.size(); ++i) {
    const glm::vec4 v = out[i];
    // du > 0 along t with v nearly unchanged; dv > 0 along b with u nearly unchanged.
    if (!(v.x > 0.0f && v.y < 0.02f && v.z > 0.0f && v.w < 0.02f)) {
      if (++bad <= 5) std::printf("kind %zu: du %g (dv/du %g) dv %g (du/dv %g)\n", i % 4, v.x, v.y, v.z, v.w);
    }
  }
  CHECK(bad == 0);
}

TEST_CASE("texture array lookup: exact texel centres, bilinear mixes, wrap-around", "[gpu][textured]") {
  test_gl();
  // Layer 0: 4x4 texels (i, j) = (i / 4, j / 4, (i + 4 j) / 16); layer 1: one constant.
  Scene scene;
  auto grid = std::make_shared<ImageMap>(), flat = std::make_shared<ImageMap>();
  grid->width = grid->height = flat->width = flat->height = 4;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      grid->rgba.insert(grid->rgba.end(), {i / 4.0f, j / 4.0f, (i + 4 * j) / 16.0f, 1.0f});
      flat->rgba.insert(flat->rgba.end(), {0.5f, 0.25f, 0.125f, 1.0f});
    }
  scene.images = {grid, flat};
  const MapArray a = build_map_array(scene, TextureArray::max_size(), TextureArray::max_layers());
  REQUIRE(a.layers == 2);
  const TextureArray maps(a.width, a.height, a.layers, a.texels.data());
  GlslKernel k("vec4 kernel(vec4 x, int i) { return vec4(map_lookup(int(x.z), x.xy), 0.0); }\n");
  maps.bind(15);
  glActiveTexture(GL_TEXTURE0);
  k.program().use();
  k.program().set("u_maps", 15);
  struct C {
    glm::vec2 uv;
    int layer;
    glm::vec3 want;
    bool exact;
  };
  std::vector<C> cases;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) cases.push_back({{(i + 0.5f) / 4, (j + 0.5f) / 4}, 0, {i / 4.0f, j / 4.0f, (i + 4 * j) / 16.0f}, true});
  cases.push_back({{0.3f, 0.9f}, 1, {0.5f, 0.25f, 0.125f}, true});
  cases.push_back({{5.125f, -0.875f}, 0, {0, 0, 0}, true});                    // repeats: (0.125, 0.125)
  cases.push_back({{0.25f, 0.125f}, 0, {0.125f, 0, 0.5f / 16}, false});        // halfway between texels 0 and 1
  cases.push_back({{0.1875f, 0.125f}, 0, {0.0625f, 0, 0.25f / 16}, false});    // a quarter of the way
  cases.push_back({{0.0f, 0.125f}, 0, {0.375f, 0, 1.5f / 16}, false});         // u wraps: texels 3 and 0
  cases.push_back({{0.125f, 0.0f}, 0, {0, 0.375f, 6.0f / 16}, false});         // v wraps: rows 3 and 0
  cases.push_back({{1.0f, 1.0f}, 0, {0.375f, 0.375f, 7.5f / 16}, false});      // the corner: four texels
  cases.push_back({{0.875f, 0.625f}, 0, {0.75f, 0.5f, 11.0f / 16}, true});     // an edge texel's centre
  std::vector<glm::vec4> in;
  for (const C& c : cases) in.emplace_back(c.uv.x, c.uv.y, float(c.layer), 0.0f);
  const std::vector<glm::vec4> out = k.run(in);
  for (size_t i = 0; i < cases.size(); ++i) {
    // Centres are exact; mixes carry the hardware's fixed-point filter weights (8 bits of
    // fraction on many GPUs): 1/256 of the largest difference of the values mixed.
    const float tol = cases[i].exact ? 1e-6f : 0.75f / 256.0f;
    INFO("uv (" << cases[i].uv.x << ", " << cases[i].uv.y << ") layer " << cases[i].layer);
    check_vec(out[i], glm::vec4(cases[i].want, 0.0f), tol, "lookup");
  }
}

TEST_CASE("image maps: resampling, decoding and GL limits", "[textured]") {
  ImageMap small;
  small.width = small.height = 2;
  small.rgba = {0, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 1, 1, 1, 0, 1};  // r = column, g = row
  const std::vector<float> up = resample_repeat(small, 4, 4);
  // Target texel (0, 0) lies at source (-0.25, -0.25): 3/4 of texel 0 and 1/4 of texel 1 (wrapped).
  CHECK(up[0] == Approx(0.25));
  CHECK(up[1] == Approx(0.25));
  CHECK(up[(1 * 4 + 1) * 4] == Approx(0.25));  // (1, 1) at source (0.25, 0.25): 3/4 texel 0
  CHECK(up[(0 * 4 + 2) * 4] == Approx(0.75));   // (2, 0) at source (0.75, -0.25)
  // sRGB codes decode to linear colour; normal-map codes map 128 to 0 and 255 to 1.
  LoadedImage img;
  img.width = 3;
  img.height = 1;
  img.rgba = {0, 128 / 255.0f, 1, 1, 10 / 255.0f, 64 / 255.0f, 200 / 255.0f, 1, 1, 1, 1, 1};
  const ImageMap colour = decode_image_map(img, false), normal = decode_image_map(img, true);
  CHECK(colour.rgba[0] == 0.0f);
  CHECK(colour.rgba[1] == Approx(0.2158605).epsilon(1e-5));
  CHECK(colour.rgba[2] == 1.0f);
  CHECK(colour.rgba[4] == Approx(10 / 255.0 / 12.92).epsilon(1e-5));
  CHECK(normal.rgba[0] == -1.0f);
  CHECK(normal.rgba[1] == 0.0f);
  CHECK(normal.rgba[2] == 1.0f);
  CHECK(normal.rgba[5] == Approx((64 - 128) / 127.0).epsilon(1e-6));
  // Limits: too large an image, too many layers; the message names the scene line.
  Scene s;
  s.path = "big.xml";
  auto m = std::make_shared<ImageMap>(small);
  m->path = "a.png";
  m->line = 7;
  s.images = {m, m};
  try {
    build_map_array(s, 1, 16);
    FAIL("accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "big.xml:7: <Textured>: image 'a.png' is 2x2, larger than this GPU's GL_MAX_TEXTURE_SIZE (1)");
  }
  try {
    build_map_array(s, 16, 1);
    FAIL("accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "big.xml:7: <Textured>: the scene has 2 image maps, more than this GPU's GL_MAX_ARRAY_TEXTURE_LAYERS (1)");
  }
}

TEST_CASE("Textured: a file that cannot be read is an error naming it and the line", "[loader][textured]") {
  const std::string dir = tmp_dir();
  const std::string head = "<SceneLevel><Camera position=\"0 0 5\"/><Objects>\n<Sphere center=\"0 0 0\" radius=\"1\">\n";
  try {
    load_scene_text(head + "<Textured diffuse=\"nope.png\"/></Sphere></Objects></SceneLevel>", dir + "/x.xml");
    FAIL("loaded");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == dir + "/x.xml:3: <Textured>: cannot read 'nope.png': no such file, or it cannot be opened");
  }
  const std::string text = "not an image";
  REQUIRE(write_file_atomic(dir + "/bad.png", text.data(), text.size()));
  try {
    load_scene_text(head + "<Textured normal=\"bad.png\"/></Sphere></Objects></SceneLevel>", dir + "/x.xml");
    FAIL("loaded");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).rfind(dir + "/x.xml:3: <Textured>: cannot read 'bad.png': not a PNG, JPEG or HDR image", 0) == 0);
  }
  solid_png("white.png", 255, 255, 255);
  for (const char* bad : {"<Textured diffuse=\"white.png\" color=\"1 1 1\"/>", "<Textured n=\"-1\"/>", "<Textured n=\"1e6\"/>"}) {
    INFO(bad);
    CHECK_THROWS_AS(load_scene_text(head + bad + "</Sphere></Objects></SceneLevel>", dir + "/x.xml"), InputError);
  }
  const Scene s = load_scene_text(head + "<Textured diffuse=\"white.png\" specular=\"white.png\" normal=\"white.png\" n=\"30\" uvScale=\"2 3\" uvOffset=\"0.5 0.25\"/></Sphere>"
                                  "<Triangle v0=\"0 0 0\" v1=\"1 0 0\" v2=\"0 1 0\" uv0=\"0.5 0.5\" uv2=\"1, 2\"><Diffuse/></Triangle></Objects></SceneLevel>",
                                  dir + "/x.xml");
  REQUIRE(s.images.size() == 2);  // white.png once as colour (diffuse, specular), once as a normal map
  REQUIRE(s.materials[0].as<Textured>());
  CHECK(s.materials[0].as<Textured>()->diffuse == s.materials[0].as<Textured>()->specular);
  CHECK(s.materials[0].as<Textured>()->uvScale == glm::vec2(2, 3));
  CHECK(s.materials[0].as<Textured>()->uvOffset == glm::vec2(0.5f, 0.25f));
  CHECK(s.shapes[1].as<Triangle>()->uv0 == glm::vec2(0.5f, 0.5f));
  CHECK(s.shapes[1].as<Triangle>()->uv1 == glm::vec2(1.0f, 0.0f));
  CHECK(s.shapes[1].as<Triangle>()->uv2 == glm::vec2(1.0f, 2.0f));
}
