// The generated icosphere (<Mesh generate="icosphere" level displace>): exact counts per
// level (20 * 4^l triangles, 10 * 4^l + 2 vertices: a closed genus-0 surface), every edge
// shared by exactly two triangles with opposite directions (closed, consistently
// oriented, no crack for the watertight intersection), outward winding and normals, and
// the displacement bound that keeps the surface from folding through the centre.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <utility>

#include "scene/mesh_generate.h"

using namespace pt;

TEST_CASE("generated icosphere: counts, closed and oriented, outward normals, bounded displacement", "[mesh][generate]") {
  for (int level = 0; level <= 5; ++level)
    for (float displace : {0.0f, 0.06f, 0.499f}) {
      const MeshData m = generate_icosphere(level, displace);
      INFO("level " << level << " displace " << displace);
      const size_t tris = size_t(20) << (2 * level), verts = (size_t(10) << (2 * level)) + 2;
      REQUIRE(m.triangles.size() == tris);
      REQUIRE(m.positions.size() == verts);
      REQUIRE(m.normals.size() == verts);
      REQUIRE(m.uvs.size() == verts);
      // Directed edges: each must appear once, and its reverse once.
      std::map<std::pair<unsigned, unsigned>, int> directed;
      int inward = 0, bad_index = 0;
      for (const glm::uvec3 t : m.triangles) {
        for (int k = 0; k < 3; ++k) {
          bad_index += t[k] >= verts;
          ++directed[{t[k], t[(k + 1) % 3]}];
        }
        const glm::vec3 a = m.positions[t.x], b = m.positions[t.y], c = m.positions[t.z];
        inward += glm::dot(glm::cross(b - a, c - a), a + b + c) <= 0.0f;
      }
      int unmatched = 0, repeated = 0;
      for (const auto& [e, n] : directed) {
        repeated += n != 1;
        unmatched += directed.count({e.second, e.first}) != 1;
      }
      CHECK(bad_index == 0);
      CHECK(repeated == 0);
      CHECK(unmatched == 0);
      // Radius within 1 +- 1.75 displace (the bumps lie in [-1.75, 1.75]); normals unit and outward.
      int out_of_bounds = 0, bad_normal = 0;
      for (size_t i = 0; i < verts; ++i) {
        const float r = glm::length(m.positions[i]);
        out_of_bounds += r < 1.0f - 1.75f * displace - 1e-5f || r > 1.0f + 1.75f * displace + 1e-5f;
        bad_normal += std::abs(glm::length(m.normals[i]) - 1.0f) > 1e-4f || !(glm::dot(m.normals[i], m.positions[i]) > 0.0f);
        bad_normal += !(m.uvs[i].x >= 0.0f && m.uvs[i].x <= 1.0f && m.uvs[i].y >= 0.0f && m.uvs[i].y <= 1.0f);
      }
      CHECK(out_of_bounds == 0);
      if (displace == 0.0f) CHECK(inward == 0);  // displaced: a steep bump may tilt a face
      if (displace < 0.1f) CHECK(bad_normal == 0);
    }
}
