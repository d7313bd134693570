#include "scene/mesh_generate.h"

#include <cmath>
#include <unordered_map>

namespace pt {
namespace {

float bumps(glm::vec3 p) {
  // A few incommensurate waves: detail at every scale down to a few triangles.
  return std::sin(7.0f * p.x + 1.3f) * std::sin(9.0f * p.y + 0.7f) * std::sin(11.0f * p.z + 2.1f) +
         0.5f * std::sin(23.0f * p.x - 17.0f * p.z) * std::cos(19.0f * p.y + 5.0f * p.x) +
         0.25f * std::sin(61.0f * p.y + 47.0f * p.z) * std::sin(53.0f * p.x);
}

}  // namespace

MeshData generate_icosphere(int level, float displace) {
  MeshData m;
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  for (glm::vec3 v : {glm::vec3(-1, t, 0), glm::vec3(1, t, 0), glm::vec3(-1, -t, 0), glm::vec3(1, -t, 0), glm::vec3(0, -1, t),
                      glm::vec3(0, 1, t), glm::vec3(0, -1, -t), glm::vec3(0, 1, -t), glm::vec3(t, 0, -1), glm::vec3(t, 0, 1),
                      glm::vec3(-t, 0, -1), glm::vec3(-t, 0, 1)})
    m.positions.push_back(glm::normalize(v));
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    std::unordered_map<uint64_t, unsigned> mid;
    mid.reserve(m.triangles.size() * 2);
    auto midpoint = [&](unsigned a, unsigned b) {
      const uint64_t key = a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a);
      auto [it, fresh] = mid.try_emplace(key, unsigned(m.positions.size()));
      if (fresh) m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
      return it->second;
    };
    std::vector<glm::uvec3> next;
    next.reserve(m.triangles.size() * 4);
    for (const glm::uvec3 tri : m.triangles) {
      const unsigned ab = midpoint(tri.x, tri.y), bc = midpoint(tri.y, tri.z), ca = midpoint(tri.z, tri.x);
      next.insert(next.end(), {{tri.x, ab, ca}, {tri.y, bc, ab}, {tri.z, ca, bc}, {ab, bc, ca}});
    }
    m.triangles.swap(next);
  }
  for (glm::vec3& p : m.positions) p *= 1.0f + displace * bumps(p);
  // Area-weighted vertex normals of the displaced surface; uv by longitude and latitude.
  m.normals.assign(m.positions.size(), glm::vec3(0.0f));
  for (const glm::uvec3 tri : m.triangles) {
    const glm::vec3 n = glm::cross(m.positions[tri.y] - m.positions[tri.x], m.positions[tri.z] - m.positions[tri.x]);
    for (int k = 0; k < 3; ++k) m.normals[tri[k]] += n;
  }
  m.uvs.resize(m.positions.size());
  for (size_t i = 0; i < m.positions.size(); ++i) {
    m.normals[i] = glm::normalize(m.normals[i]);
    const glm::vec3 d = glm::normalize(m.positions[i]);
    m.uvs[i] = glm::vec2(0.5f + std::atan2(d.z, d.x) / 6.2831853f, std::acos(glm::clamp(d.y, -1.0f, 1.0f)) / 3.14159265f);
  }
  return m;
}

}  // namespace pt
