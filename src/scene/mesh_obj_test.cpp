// Wavefront OBJ normals and texture coordinates: each distinct (v, vt, vn) triple of the
// faces is one vertex of the loaded mesh, carrying the numbers of the file.
#include <catch2/catch.hpp>

#include "core/error.h"
#include "scene/mesh_obj.h"

using namespace pt;

TEST_CASE("OBJ vn and vt are loaded per vertex; different v/vt/vn triples are distinct vertices", "[loader][mesh][obj]") {
  const MeshData m = parse_mesh_obj(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.25 0.75\n"
      "vn 0 0 1\nvn 0 0.6 0.8\n"
      "f 1/1/1 2/2/1 3/3/2\n"
      "f 1/1/1 3/3/2 4/4/2\n"
      "f 1/5/2 -2/-3/-1 -1/-2/-1\n",  // position 1 again with other vt and vn; relative indices
      "q.obj");
  REQUIRE(m.triangles.size() == 3);
  REQUIRE(m.positions.size() == 5);  // (1,1,1) (2,2,1) (3,3,2) (4,4,2) (1,5,2)
  REQUIRE(m.normals.size() == 5);
  REQUIRE(m.uvs.size() == 5);
  CHECK(m.triangles[0] == glm::uvec3(0, 1, 2));
  CHECK(m.triangles[1] == glm::uvec3(0, 2, 3));
  CHECK(m.triangles[2] == glm::uvec3(4, 2, 3));
  CHECK(m.positions[1] == glm::vec3(1, 0, 0));
  CHECK(m.positions[4] == glm::vec3(0, 0, 0));
  CHECK(m.normals[0] == glm::vec3(0, 0, 1));
  CHECK(m.normals[2] == glm::vec3(0, 0.6f, 0.8f));
  CHECK(m.normals[4] == glm::vec3(0, 0.6f, 0.8f));
  CHECK(m.uvs[1] == glm::vec2(1, 0));
  CHECK(m.uvs[3] == glm::vec2(0, 1));
  CHECK(m.uvs[4] == glm::vec2(0.25f, 0.75f));
}

TEST_CASE("OBJ with normals only, uv only, or neither", "[loader][mesh][obj]") {
  const MeshData n = parse_mesh_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 0\nf 1//1 2//1 3//1\n", "n.obj");
  CHECK(n.positions.size() == 3);
  CHECK(n.normals == std::vector<glm::vec3>(3, glm::vec3(1, 0, 0)));
  CHECK(n.uvs.empty());
  const MeshData t = parse_mesh_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nf 1/1 2/1 3/1\n", "t.obj");
  CHECK(t.normals.empty());
  CHECK(t.uvs == std::vector<glm::vec2>(3, glm::vec2(0.5f)));
  const MeshData p = parse_mesh_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n", "p.obj");
  CHECK(p.positions.size() == 4);  // shared corners stay shared
  CHECK(p.normals.empty());
  CHECK(p.uvs.empty());
  // A face without vn in a file whose other faces have them: zero normals, which the
  // packer leaves out (that face shades with its geometric normal).
  const MeshData mixed = parse_mesh_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1 3 2\n", "m.obj");
  REQUIRE(mixed.normals.size() == 6);
  CHECK(mixed.normals[5] == glm::vec3(0.0f));
}
