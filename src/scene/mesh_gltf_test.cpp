// glTF from memory (the fuzzer's entry point): .glb and .gltf told apart by the magic and
// giving the same mesh; files named by URI go through the resolver only (refused without
// one, recorded as the scene's dependencies with one).
#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/file_io.h"
#include "core/resumable.h"
#include "scene/mesh_gltf.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

std::string bytes_of(const std::string& rel) {
  const auto b = read_file(repo_path(rel));
  REQUIRE(b);
  return *b;
}

// quad.glb's BIN chunk: the quad's geometry, as the .gltf tests' buffer files hold it.
std::string quad_bin() {
  const std::string glb = bytes_of("tests/fuzz/corpus/mesh_gltf/quad.glb");
  uint32_t json = 0, bin = 0;
  std::memcpy(&json, glb.data() + 12, 4);
  std::memcpy(&bin, glb.data() + 20 + json, 4);
  return glb.substr(20 + json + 8, bin);
}

std::string error_of(const std::string& bytes, const GltfResolver& resolve) {
  try {
    parse_gltf(bytes, "m.gltf", resolve);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("glTF from memory: binary and JSON by their magic, the same quad", "[loader][mesh][gltf]") {
  for (const char* f : {"quad.glb", "quad-textured.gltf", "quad-textured.glb"}) {
    INFO(f);
    // The names say nothing: the .glb is read as "m.gltf" and the other way round.
    const std::vector<GltfPart> parts = parse_gltf(bytes_of(std::string("tests/fuzz/corpus/mesh_gltf/") + f), "m.gltf", {});
    REQUIRE(parts.size() == 1);
    const MeshData& m = *parts[0].mesh;
    REQUIRE(m.positions.size() == 4);
    REQUIRE(m.normals.size() == 4);
    REQUIRE(m.uvs.size() == 4);
    REQUIRE(m.triangles.size() == 2);
    CHECK(m.positions[2] == glm::vec3(1, 1, 0));
    CHECK(m.normals[3] == glm::vec3(0, 0, 1));
    CHECK(m.triangles[1] == glm::uvec3(0, 2, 3));
    // The file's uv (0, 1) (1, 1) (1, 0) (0, 0): glTF's v runs down the image, ours up.
    CHECK(m.uvs[0] == glm::vec2(0, 0));
    CHECK(m.uvs[2] == glm::vec2(1, 1));
    CHECK(m.uvs[3] == glm::vec2(0, 1));
    CHECK(bool(parts[0].material.base_color_map) == (std::string(f) != "quad.glb"));
  }
  CHECK(error_of("", {}) == "m.gltf: JSON string too short.");
  CHECK(error_of("glTF\x02", {}) == "m.gltf: byte 5: the file ends inside the GLB header (truncated)");
}

TEST_CASE("glTF buffer files go through the resolver: refused without one, dependencies with one", "[loader][mesh][gltf]") {
  // missing-buffer.gltf names "no-such.bin" (the quad's geometry, as quad.glb's BIN chunk).
  const std::string dir = std::string(PT_BINARY_DIR) + "/gltf-test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/no-such.bin", std::ios::binary) << quad_bin();
  const std::string text = bytes_of("tests/malformed/gltf/missing-buffer.gltf");
  std::ofstream(dir + "/quad.gltf", std::ios::binary) << text;

  CHECK(error_of(text, {}) == "m.gltf: /buffers/0: file references are disabled for this glTF");
  CHECK(error_of(bytes_of("tests/malformed/gltf/missing-image.gltf"), {}) == "m.gltf: /images/0: file references are disabled for this glTF");
  std::vector<std::string> asked;
  const std::vector<GltfPart> parts = parse_gltf(text, dir + "/quad.gltf", [&](const std::string& p) {
    asked.push_back(p);
    return p;
  });
  CHECK(asked == std::vector<std::string>{dir + "/no-such.bin"});
  REQUIRE(parts.size() == 1);
  CHECK(parts[0].mesh->triangles.size() == 2);
  CHECK(error_of(text, [](const std::string&) -> std::string { throw InputError("x.xml", 3, "no"); }) ==
        "m.gltf: /buffers/0: x.xml:3: no");
  // Buffers that are neither a data: URI nor a file, or have no whole byte count.
  auto edited = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    REQUIRE(t.find(from) != std::string::npos);
    return t.replace(t.find(from), from.size(), to);
  };
  CHECK(error_of(edited("\"byteLength\": 140,\n   \"uri\": \"no-such.bin\"", "\"byteLength\": 140"), {}) ==
        "m.gltf: /buffers/0: no uri (only a binary glTF's buffers may have none)");
  CHECK(error_of(edited("\"uri\": \"no-such.bin\"", "\"uri\": 7"), {}) == "m.gltf: /buffers/0: uri is not a string");
  CHECK(error_of(edited("\"byteLength\": 140,", "\"byteLength\": 140.5,"), {}) ==
        "m.gltf: /buffers/0: byteLength must be a whole number of bytes");

  const std::string scene = "<SceneLevel><Camera position=\"0 0 5\"/><Objects><Mesh src=\"quad.gltf\"/></Objects></SceneLevel>";
  const Scene s = load_scene_text(scene, dir + "/s.xml");
  CHECK(s.files == std::vector<std::string>{dir + "/s.xml", dir + "/quad.gltf", dir + "/no-such.bin"});
  try {
    load_scene_text(scene, dir + "/s.xml", false);
    FAIL("loaded");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("file references are disabled") != std::string::npos);
  }
}

TEST_CASE("glTF buffers are ours: a buffer file read 256 KB a slice, the GLB's BIN chunk used where it lies", "[loader][mesh][gltf]") {
  // The quad as a .gltf naming big.bin (its geometry, then 1 MB that byteLength leaves
  // out), and as quad.glb. tinygltf read a buffer file, and copied a BIN chunk, in one step.
  const std::string dir = std::string(PT_BINARY_DIR) + "/gltf-test";
  std::filesystem::create_directories(dir);
  const std::string glb = bytes_of("tests/fuzz/corpus/mesh_gltf/quad.glb");
  std::ofstream(dir + "/big.bin", std::ios::binary) << quad_bin() << std::string(size_t(1) << 20, '\0');
  std::string text = bytes_of("tests/malformed/gltf/missing-buffer.gltf");
  REQUIRE(text.find("no-such.bin") != std::string::npos);
  text.replace(text.find("no-such.bin"), 11, "big.bin");
  auto slices = [&](const std::string& bytes, const std::string& path) {
    std::vector<GltfPart> parts;
    Resumable r = parse_gltf_steps(bytes, path, [](const std::string& p) { return p; }, parts);
    int n = 1;
    while (!r.run(1)) ++n;  // one unit: every yield ends a slice
    REQUIRE(parts.size() == 1);
    CHECK(parts[0].mesh->triangles.size() == 2);
    CHECK(parts[0].mesh->positions[2] == glm::vec3(1, 1, 0));
    return n;
  };
  // The same conversion; the file's 1 MB + 140 bytes are 5 more slices of 256 KB.
  CHECK(slices(text, dir + "/big.gltf") - slices(glb, dir + "/quad.glb") == 5);
}

TEST_CASE("glTF maps become GltfPbr's: base colour (sRGB), metallic-roughness (linear), normal", "[loader][mesh][gltf]") {
  // The textured quad (its 4x4 image: red, green / blue, white quadrants) with that image
  // also as metallicRoughnessTexture and normalTexture.
  std::string text = bytes_of("tests/fuzz/corpus/mesh_gltf/quad-textured.gltf");
  const std::string from = "\"metallicFactor\": 0.0, \"roughnessFactor\": 1.0, \"baseColorTexture\": {\"index\": 0}}";
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(),
               "\"metallicFactor\": 0.5, \"roughnessFactor\": 0.5, \"baseColorTexture\": {\"index\": 0}, "
               "\"metallicRoughnessTexture\": {\"index\": 0}}, \"normalTexture\": {\"index\": 0}");
  const std::string factor = "\"baseColorFactor\": [1, 1, 1, 1]";
  REQUIRE(text.find(factor) != std::string::npos);
  text.replace(text.find(factor), factor.size(), "\"baseColorFactor\": [0.5, 1, 1, 1]");
  const std::string dir = std::string(PT_BINARY_DIR) + "/gltf-test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/maps.gltf", std::ios::binary) << text;
  const Scene s = load_scene_text("<SceneLevel><Camera position=\"0 0 5\"/><Objects><Mesh src=\"maps.gltf\"/></Objects></SceneLevel>",
                                  dir + "/s.xml");
  REQUIRE(s.materials.size() == 1);
  const Material& m = s.materials[0];
  REQUIRE(m.kind() == MaterialKind::GltfPbr);
  const GltfPbr& t = *m.as<GltfPbr>();
  CHECK(t.baseColor == glm::vec3(0.5f, 1.0f, 1.0f));
  CHECK(t.metallic == 0.5f);
  CHECK(t.roughness == 0.5f);
  REQUIRE(s.images.size() == 3);  // one image, three decodings
  REQUIRE(t.base.image >= 0);
  REQUIRE(t.metal_rough.image >= 0);
  REQUIRE(t.normal.image >= 0);
  // Texel (0, 0) of a map is the image's bottom-left: the blue quadrant.
  const ImageMap& d = *s.images[size_t(t.base.image)];
  const ImageMap& mr = *s.images[size_t(t.metal_rough.image)];
  CHECK(d.rgba[0] == 0.0f);
  CHECK(d.rgba[2] == 1.0f);
  CHECK(mr.rgba[2] == 1.0f);  // blue, linear
  CHECK(s.images[size_t(t.normal.image)]->normal);
}
