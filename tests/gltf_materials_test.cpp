// glTF materials as glTF defines them (materials/gltf_pbr.h, docs/gltf.md), on the assets
// of tools/gen_gltf_assets.py (assets/gltf/test-*.gltf: quads z = 0 over [-1, 1]^2 facing
// +z), each seen head-on from z = 3 with closed-form expectations; and the BSDF's
// reciprocity and furnace sweep (MetallicRoughness, what a GltfPbr becomes at the hit).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "gl_context.h"
#include "glsl_harness.h"
#include "scene/textured_loader.h"
#include "scene/xml_loader.h"
#include "media_scenes.h"
#include "test_paths.h"
#include "stats.h"

using namespace pt;

namespace {

constexpr int kN = 32;  // pixels; the quad's half-extent 1 is 16 / 1.243 pixels (fov 45 at distance 3)

// `file` (assets/gltf/) seen from z = +3 (or -3: from behind) under a sky of `sky`.
RenderResult view(const std::string& file, double sky, bool behind = false, int spp = 64) {
  const std::string cam = behind ? "<Camera position=\"0 0 -3\" yaw=\"-90\" pitch=\"0\"/>" : "<Camera position=\"0 0 3\" yaw=\"90\" pitch=\"0\"/>";
  const Scene s = load_scene_text("<SceneLevel>" + cam + "<Environment color=\"" + std::to_string(sky) + " " + std::to_string(sky) + " " +
                                      std::to_string(sky) + "\"/><Objects><Mesh src=\"../assets/gltf/" + file + "\"/></Objects></SceneLevel>",
                                  repo_path("scenes/gltf-test.xml"));
  const RenderResult r = render_scene(s, kN, kN, spp);
  CHECK(r.counters.bad_samples == 0);
  return r;
}

// The mean over a 2 x 2 pixel block around quad point (x, y) (seen from the front).
double at(const RenderResult& r, double x, double y) {
  const int px = int(std::floor(16.0 + x * 16.0 / 1.2426)), py = int(std::floor(16.0 + y * 16.0 / 1.2426));
  return region_mean(r, px - 1, py - 1, px + 1, py + 1).mean;
}

}  // namespace

TEST_CASE("glTF: a metallic-roughness checker gives the metal/dielectric split per texel", "[gpu][gltf]") {
  test_gl();
  // White smooth metal (a mirror of the sky: 1) beside a black smooth dielectric (only its
  // coat: Schlick's F of f0 = 0.04, ~0.04 head-on); TEXCOORD_0, then the same maps on
  // TEXCOORD_1 with a constant TEXCOORD_0.
  for (const char* file : {"test-checker.gltf", "test-uv1.gltf"}) {
    INFO(file);
    const RenderResult r = view(file, 1.0);
    for (double s : {-1.0, 1.0}) {
      CHECK(at(r, -0.5 * s, 0.5 * s) == Approx(1.0).margin(0.01));          // metal
      CHECK(at(r, 0.5 * s, 0.5 * s) == Approx(schlick(0.04, 0.99)).margin(0.005));  // dielectric
    }
  }
}

TEST_CASE("glTF: maps decode as glTF says (colour sRGB with linear alpha, metallic-roughness linear)", "[loader][gltf]") {
  const Scene s = load_scene_text("<SceneLevel><Camera position=\"0 0 3\"/><Objects><Mesh src=\"../assets/gltf/test-mask.gltf\"/>"
                                  "<Mesh src=\"../assets/gltf/test-checker.gltf\"/></Objects></SceneLevel>",
                                  repo_path("scenes/gltf-test.xml"));
  REQUIRE(s.materials.size() == 2);
  const GltfPbr& mask = *s.materials[0].as<GltfPbr>();
  const GltfPbr& checker = *s.materials[1].as<GltfPbr>();
  CHECK(mask.alphaMode == GltfPbr::kMask);
  CHECK(s.images[size_t(mask.base.image)]->rgba[3] == Approx(102.0 / 255.0));  // alpha: linear
  const ImageMap& mr = *s.images[size_t(checker.metal_rough.image)];
  CHECK(mr.rgba[2] == 0.0f);  // rows from the bottom: (0, 0) is the image's bottom-left, a dielectric texel
  CHECK(mr.rgba[4 + 2] == 1.0f);
  // A code of 128 would read 0.502 linear and 0.216 as sRGB: the base map holds 0 and 255
  // only, so check the decoder directly on the mid code.
  LoadedImage img;
  img.width = img.height = 1;
  img.bits = 8;
  img.rgba = {128 / 255.0f, 128 / 255.0f, 128 / 255.0f, 128 / 255.0f};
  Scene t;
  const int srgb = add_image_map(t, "x", img, false, 0, [](const std::string&) {});
  const int lin = add_linear_image_map(t, "x", img, 0, [](const std::string&) {});
  CHECK(t.images[size_t(srgb)]->rgba[0] == Approx(0.2158).margin(1e-3));
  CHECK(t.images[size_t(lin)]->rgba[0] == Approx(0.502).margin(1e-3));
  CHECK(t.images[size_t(srgb)]->rgba[3] == Approx(0.502).margin(1e-3));
}

TEST_CASE("glTF: sampler wrap modes and KHR_texture_transform", "[gpu][gltf]") {
  test_gl();
  // Emission of a two-texel map (black | white, NEAREST) under a black sky: u runs over
  // [-1, 2] across the quad, so each sixth of it is half a period.
  struct C {
    const char* file;
    int bands[6];
  };
  for (const C& c : {C{"test-wrap-repeat.gltf", {0, 1, 0, 1, 0, 1}}, C{"test-wrap-clamp.gltf", {0, 0, 0, 1, 1, 1}},
                     C{"test-wrap-mirror.gltf", {1, 0, 0, 1, 1, 0}}}) {
    INFO(c.file);
    const RenderResult r = view(c.file, 0.0, false, 16);
    for (int b = 0; b < 6; ++b) {
      INFO("band " << b);
      CHECK(at(r, -1.0 + (b + 0.5) / 3.0, 0.0) == Approx(c.bands[b]).margin(0.02));
    }
  }
  // offset (0.5, 0) and scale (2, 1): u' = 2u + 0.5 over u in [0, 1]: white, black, white, black.
  const RenderResult r = view("test-transform.gltf", 0.0, false, 16);
  for (int b = 0; b < 4; ++b) CHECK(at(r, -1.0 + (b + 0.5) / 2.0, 0.0) == Approx(b % 2 == 0 ? 1.0 : 0.0).margin(0.02));
}

TEST_CASE("glTF: alpha MASK and BLEND, and single-sided back faces", "[gpu][gltf]") {
  test_gl();
  // MASK at 0.5: the left half (alpha 0.4) lets the sky (1) through, the right (0.6) is a
  // black mirror (~0).
  const RenderResult mask = view("test-mask.gltf", 1.0);
  CHECK(at(mask, -0.5, 0.0) == Approx(1.0).margin(0.01));
  CHECK(at(mask, 0.5, 0.0) < 0.01);
  // BLEND at alpha 0.5: half the camera rays pass.
  const RenderResult blend = view("test-blend.gltf", 1.0, false, 256);
  const Estimate e = region_mean(blend, 10, 10, 22, 22);
  INFO("blend " << e.mean << " se " << e.se);
  CHECK(std::abs(e.mean - 0.5) < 4 * e.se + 2e-3);
  // Single-sided: a black mirror from the front, culled (the sky) from behind.
  CHECK(at(view("test-single-sided.gltf", 1.0), 0.0, 0.0) < 0.01);
  CHECK(at(view("test-single-sided.gltf", 1.0, true), 0.0, 0.0) == Approx(1.0).margin(0.01));
}

TEST_CASE("glTF: a BLEND quad of alpha 0.5 passes half the light, shadow rays included", "[gpu][gltf]") {
  test_gl();
  // A diffuse floor lit by a sphere light through a horizontal half-alpha quad, seen from
  // below the quad: the floor under it gets half the light of the floor without it.
  auto floor = [](bool quad) {
    const Scene s = load_scene_text(
        std::string("<SceneLevel><Camera position=\"0 0.7 4\" yaw=\"90\" pitch=\"-10\"/><Environment color=\"0 0 0\"/>"
                    "<Light position=\"0 3 0\" radius=\"0.3\" color=\"1 1 1\" intensity=\"20\"/><Objects>"
                    "<Plane normal=\"0 1 0\" d=\"0\"><Diffuse/></Plane>") +
            (quad ? "<Mesh src=\"../assets/gltf/test-blend.gltf\" position=\"0 1.5 0\" rotation=\"-90 0 0\" scale=\"1.5\"/>" : "") +
            "</Objects></SceneLevel>",
        repo_path("scenes/gltf-test.xml"));
    const RenderResult r = render_scene(s, kN, kN, 512);
    CHECK(r.counters.bad_samples == 0);
    return region_mean(r, 12, 4, 20, 10);
  };
  const Estimate with = floor(true), without = floor(false);
  const double ratio = with.mean / without.mean, se = ratio * std::hypot(with.se / with.mean, without.se / without.mean);
  std::printf("blend shadow: floor %.5f (se %.5f) vs %.5f (se %.5f): ratio %.4f (se %.4f)\n", with.mean, with.se, without.mean,
              without.se, ratio, se);
  CHECK(std::abs(ratio - 0.5) < 4 * se + 0.01);
}

TEST_CASE("MetallicRoughness: reciprocity f(wo, wi) = f(wi, wo)", "[gpu][sampling]") {
  test_gl();
  for (float metallic : {0.0f, 0.5f, 1.0f})
    for (float roughness : {0.1f, 0.5f, 1.0f}) {
      const Material m = MetallicRoughness{.baseColor = glm::vec3(0.9f, 0.5f, 0.2f), .metallic = metallic, .roughness = roughness};
      GlslKernel k(glsl_material(m) +
                   "vec3 dir(float a, float b) { float z = max(a, 1e-3); float r = sqrt(1.0 - z * z); return vec3(r * cos(6.2831853 * b), r * sin(6.2831853 * b), z); }\n"
                   "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 7u), 0u);\n"
                   "  vec3 a = dir(rand01(), rand01()), b = dir(rand01(), rand01());\n  float p;\n"
                   "  vec3 fab = material_eval(make_material(), a, b, true, p) / b.z;\n"
                   "  vec3 fba = material_eval(make_material(), b, a, true, p) / a.z;\n"
                   "  return vec4(fab.r, fba.r, fab.b, fba.b);\n}\n");
      float worst = 0.0f;
      for (const glm::vec4& v : k.run(20000))
        for (int c : {0, 2}) worst = std::max(worst, std::abs(v[c] - v[c + 1]) / std::max(1e-3f, std::max(v[c], v[c + 1])));
      INFO("metallic " << metallic << " roughness " << roughness);
      CHECK(worst < 1e-3f);
    }
}

TEST_CASE("MetallicRoughness: furnace sweep metallic x roughness returns 1 (multiple-scattering compensation)", "[gpu][transport]") {
  test_gl();
  // A white sphere under a sky of 1: what it returns is its directional albedo averaged
  // over the visible disc. With the multiple-scattering compensation (the default:
  // materials/gltf_ms.glsl) a white material absorbs nothing: 1 within 1%, and never above
  // 1. Without it (--gltf-ms off, the spec's single scattering) the white rough metal
  // returns 0.32, the energy single-scattering GGX loses (docs/gltf.md has both tables).
  RenderSettings st;
  st.max_bounces = 32;
  {
    RenderSettings off = st;
    off.gltf_ms = false;
    Scene s;
    s.camera = camera_looking_down_z(glm::vec3(0.0f, 0.0f, 4.0f));
    s.environment.color = glm::vec3(1.0f);
    add_sphere(s, glm::vec3(0.0f), 1.0f, add_material(s, MetallicRoughness{.metallic = 1.0f, .roughness = 1.0f}));
    const Estimate e = region_mean(render_scene(s, 48, 48, 64, off), 18, 18, 30, 30);
    std::printf("furnace, --gltf-ms off: metallic 1 roughness 1: %.4f (%.4f)\n", e.mean, e.se);
    CHECK(std::abs(e.mean - 0.3194) < 4 * e.se + 0.005);  // docs/gltf.md, "the spec's model"
  }
  std::printf("furnace (white MetallicRoughness sphere, sky 1): rows metallic, columns roughness 0, .25, .5, .75, 1\n");
  for (int i = 0; i <= 4; ++i) {
    std::printf("  metallic %.2f:", i / 4.0);
    for (int j = 0; j <= 4; ++j) {
      Scene s;
      s.camera = camera_looking_down_z(glm::vec3(0.0f, 0.0f, 4.0f));
      s.environment.color = glm::vec3(1.0f);
      add_sphere(s, glm::vec3(0.0f), 1.0f, add_material(s, MetallicRoughness{.metallic = i / 4.0f, .roughness = j / 4.0f}));
      const RenderResult r = render_scene(s, 48, 48, 64, st);
      const Estimate e = region_mean(r, 18, 18, 30, 30);
      std::printf(" %.4f (%.4f)", e.mean, e.se);
      INFO("metallic " << i / 4.0 << " roughness " << j / 4.0 << ": " << e.mean << " se " << e.se);
      CHECK(r.counters.bad_samples == 0);
      CHECK(e.mean <= 1.0 + 3 * e.se + 1e-6);
      CHECK(std::abs(e.mean - 1.0) < 0.01 + 3 * e.se);  // (se up to 0.008 at roughness 1; the lobe sweep checks 1% at se 0.002)
    }
    std::printf("\n");
  }
}

TEST_CASE("glTF: the extensions' maps (clearcoat R, specular A, sheen colour RGB) read per texel", "[gpu][gltf]") {
  test_gl();
  // Black quads without dielectric specular, seen head-on (cos ~0.99) under a sky of 1:
  // the map's white left half shows only its lobe, the black right half nothing.
  // A smooth clearcoat of 1 and a smooth specular layer reflect Schlick's F(f0 = 0.04) =
  // 0.04 there; the sheen returns its albedo E(mu, 0.5) (the build-time table).
  for (const char* file : {"test-clearcoat-map.gltf", "test-specular-map.gltf"}) {
    const RenderResult r = view(file, 1.0);
    INFO(file << ": left " << at(r, -0.5, 0.0) << " right " << at(r, 0.5, 0.0));
    CHECK(at(r, -0.5, 0.0) == Approx(0.04).margin(0.002));
    CHECK(at(r, 0.5, 0.0) < 1e-4);
  }
  Features f = all_features();
  f.material_features |= feature_bit(MaterialFeature::GltfSheen);
  GlslKernel k("vec4 kernel(vec4 x, int i) { return vec4(gltf_sheen_albedo(3.0 / sqrt(9.25), gltf_sheen_roughness(0.5))); }\n", f);
  const double e = k.run(1)[0].x;
  const RenderResult r = view("test-sheen-map.gltf", 1.0, false, 256);
  INFO("sheen: left " << at(r, -0.5, 0.0) << " (table " << e << ") right " << at(r, 0.5, 0.0));
  CHECK(e > 0.01);
  CHECK(at(r, -0.5, 0.0) == Approx(e).epsilon(0.05));
  CHECK(at(r, 0.5, 0.0) < 1e-4);
}

// KHR_materials_volume's absorption (assets/gltf/test-volume.gltf, tools/gen_gltf_assets.py):
// a closed slab 1 thick of smooth glass (ior 1.5) keeping (0.5, 0.8, 0.2) per unit length,
// seen head-on under a sky of 1: its reflectance plus transmittance with every internal
// reflection (tests/media_test.cpp has the formula), at the centre (2 x 2 pixels, rays
// within 1.5 degrees of the normal: 1e-4 of path length).
TEST_CASE("glTF: KHR_materials_volume absorbs inside (Beer-Lambert) as its attenuationColor and distance say", "[gpu][gltf][media]") {
  test_gl();
  const Scene s = load_scene_text("<SceneLevel><Camera position=\"0 0 3\" yaw=\"90\" pitch=\"0\"/><Environment color=\"1 1 1\"/>"
                                  "<Objects><Mesh src=\"../assets/gltf/test-volume.gltf\"/></Objects></SceneLevel>",
                                  repo_path("scenes/gltf-test.xml"));
  REQUIRE(s.materials.size() == 1);
  const GltfPbr* d = std::get_if<GltfPbr>(&s.materials[0].params);  // the glTF BSDF with its volume
  REQUIRE(d);
  CHECK(d->volume_ior() == 1.5f);
  CHECK(d->sigma.x == Approx(std::log(2.0)));
  RenderSettings st;
  st.max_bounces = 16;
  const RenderResult r = render_scene(s, kN, kN, 1024, st);
  CHECK(r.counters.bad_samples == 0);
  const double lum[3] = {0.2126, 0.7152, 0.0722};
  double expect_lum = 0.0;
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (int y = 15; y < 17; ++y)
      for (int x = 15; x < 17; ++x) sum += r.rgba[(size_t(y) * kN + x) * 4 + c];
    const double expect = slab_returned(kAttenuation[c]);  // the asset's attenuation (tools/gen_gltf_assets.py)
    std::printf("glTF volume, channel %d: %.5f, closed form %.5f\n", c, sum / 4.0, expect);
    CHECK(sum / 4.0 == Approx(expect).epsilon(0.01));  // each channel roughly; the luminance within its error:
    expect_lum += lum[c] * expect;
  }
  const Estimate e = region_mean(r, 15, 15, 17, 17);
  std::printf("glTF volume, luminance: %.5f +- %.5f, closed form %.5f\n", e.mean, e.se, expect_lum);
  CHECK(std::abs(e.mean - expect_lum) <= 4.0 * e.se + 3e-4 * expect_lum);
}
