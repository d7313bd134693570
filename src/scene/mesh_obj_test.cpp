// Wavefront OBJ normals and texture coordinates: each distinct (v, vt, vn) triple of the
// faces is one vertex of the loaded mesh, carrying the numbers of the file.
#include <catch2/catch.hpp>

#include <map>
#include <string>
#include <tuple>

#include "scene/tinyobj.h"  // the oracle (its definitions are compiled in scene/mesh_obj.cpp)

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

namespace {

// tinyobjloader's reading of the same text, each distinct (v, vt, vn) a vertex numbered as
// first used: the oracle for our own reader (which splits quads as tinyobjloader does).
MeshData tinyobj_mesh(const std::string& text) {
  tinyobj::ObjReaderConfig config;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  REQUIRE(reader.ParseFromString(text, "", config));
  const tinyobj::attrib_t& a = reader.GetAttrib();
  bool vn = false, vt = false;
  for (const auto& s : reader.GetShapes())
    for (const auto& c : s.mesh.indices) vn |= c.normal_index >= 0, vt |= c.texcoord_index >= 0;
  MeshData m;
  std::map<std::tuple<int, int, int>, unsigned> index;
  for (const auto& s : reader.GetShapes())
    for (size_t f = 0; f < s.mesh.indices.size(); f += 3) {
      glm::uvec3 tri;
      for (size_t k = 0; k < 3; ++k) {
        const tinyobj::index_t c = s.mesh.indices[f + k];
        const auto [it, fresh] = index.try_emplace({c.vertex_index, c.texcoord_index, c.normal_index}, unsigned(m.positions.size()));
        if (fresh) {
          m.positions.emplace_back(a.vertices[3 * size_t(c.vertex_index)], a.vertices[3 * size_t(c.vertex_index) + 1], a.vertices[3 * size_t(c.vertex_index) + 2]);
          if (vn) m.normals.push_back(c.normal_index < 0 ? glm::vec3(0.0f) : glm::vec3(a.normals[3 * size_t(c.normal_index)], a.normals[3 * size_t(c.normal_index) + 1], a.normals[3 * size_t(c.normal_index) + 2]));
          if (vt) m.uvs.push_back(c.texcoord_index < 0 ? glm::vec2(0.0f) : glm::vec2(a.texcoords[2 * size_t(c.texcoord_index)], a.texcoords[2 * size_t(c.texcoord_index) + 1]));
        }
        tri[int(k)] = it->second;
      }
      m.triangles.push_back(tri);
    }
  return m;
}

// Positions within a float's rounding (tinyobjloader parses numbers its own way), the rest exactly.
void require_same(const MeshData& a, const MeshData& b) {
  REQUIRE(a.triangles == b.triangles);
  REQUIRE(a.positions.size() == b.positions.size());
  for (size_t i = 0; i < a.positions.size(); ++i) CHECK(glm::all(glm::lessThanEqual(glm::abs(a.positions[i] - b.positions[i]), glm::vec3(1e-6f * (1.0f + glm::length(a.positions[i]))))));
  REQUIRE(a.normals.size() == b.normals.size());
  for (size_t i = 0; i < a.normals.size(); ++i) CHECK(glm::all(glm::lessThanEqual(glm::abs(a.normals[i] - b.normals[i]), glm::vec3(1e-6f))));
  REQUIRE(a.uvs.size() == b.uvs.size());
  for (size_t i = 0; i < a.uvs.size(); ++i) CHECK(glm::all(glm::lessThanEqual(glm::abs(a.uvs[i] - b.uvs[i]), glm::vec2(1e-6f))));
}

}  // namespace

TEST_CASE("our OBJ reader gives tinyobjloader's mesh: triangles, quads split along the shorter diagonal, vt/vn mixes, relative indices", "[loader][mesh][obj]") {
  // A grid of irregular quads (both diagonals occur), some faces as triangles, some
  // corners relative, one object per row, normals on half the rows and uv on others.
  std::string text = "# grid\nmtllib none.mtl\n";
  const int n = 24;
  uint32_t h = 12345;
  auto jitter = [&h] { return float((h = h * 1664525u + 1013904223u) >> 8) / float(1u << 24) - 0.5f; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) text += "v " + std::to_string(i + 0.45f * jitter()) + " " + std::to_string(0.3f * jitter()) + " " + std::to_string(j + 0.45f * jitter()) + "\n";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) text += "vt " + std::to_string(float(i) / n) + " " + std::to_string(float(j) / n) + "\n";
  text += "vn 0 1 0\nvn 0.6 0.8 0\n";
  for (int j = 0; j < n; ++j) {
    text += "o row" + std::to_string(j) + "\ns 1\n";
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 2, d = a + n + 1;
      auto corner = [&](int v) {
        const std::string vs = (i % 3 == 0) ? std::to_string(v - (n + 1) * (n + 1) - 1) : std::to_string(v);  // relative: -count + v - 1
        if (j % 3 == 0) return vs + "//" + std::to_string(1 + (i & 1));
        if (j % 3 == 1) return vs + "/" + std::to_string(v);
        return vs;
      };
      // Relative vertex indices count back from the last v; uv and normals are absolute here.
      if ((i + j) % 5 == 0) text += "f " + corner(a) + " " + corner(b) + " " + corner(c) + "\nf " + corner(a) + " " + corner(c) + " " + corner(d) + "\n";
      else text += "f " + corner(a) + " " + corner(b) + " " + corner(c) + " " + corner(d) + "\n";
    }
  }
  const MeshData ours = parse_mesh_obj(text, "grid.obj");
  CHECK(ours.triangles.size() == size_t(2 * n * n));
  require_same(ours, tinyobj_mesh(text));
}

TEST_CASE("an OBJ polygon of more than four corners is triangulated by tinyobjloader's ear clipping", "[loader][mesh][obj]") {
  // A concave hexagon (an L shape) and a triangle: a fan from corner 1 would leave the L.
  const std::string text = "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 5 5 5\nf 1 2 3 4 5 6\nf 1 2 7\n";
  const MeshData m = parse_mesh_obj(text, "l.obj");
  CHECK(m.triangles.size() == 5);
  require_same(m, tinyobj_mesh(text));
  float area = 0.0f;
  for (size_t t = 0; t < 4; ++t) {
    const glm::uvec3 tri = m.triangles[t];
    area += 0.5f * glm::length(glm::cross(m.positions[tri.y] - m.positions[tri.x], m.positions[tri.z] - m.positions[tri.x]));
  }
  CHECK(area == Approx(3.0f));  // the L's area: the triangles cover it without overlap
}

TEST_CASE("an OBJ polygon is split as this reader read it (a comment after its last corner holds a number)", "[loader][mesh][obj]") {
  // A fuzzer finding: handed the whole file, tinyobjloader read "5# 82" as corners 5 and
  // 82 and the mesh was built past its vertices; the polygon is now passed to it alone.
  const MeshData m = parse_mesh_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 2 0\nf 1 2 3 4 5# 82\n", "c.obj");
  CHECK(m.triangles.size() == 3);
  CHECK(m.positions.size() == 5);
}
