#include "scene/mesh_generate.h"

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

namespace pt {
namespace {

float bumps(glm::vec3 p) {
  // A few incommensurate waves: detail at every scale down to a few triangles.
  return std::sin(7.0f * p.x + 1.3f) * std::sin(9.0f * p.y + 0.7f) * std::sin(11.0f * p.z + 2.1f) +
         0.5f * std::sin(23.0f * p.x - 17.0f * p.z) * std::cos(19.0f * p.y + 5.0f * p.x) +
         0.25f * std::sin(61.0f * p.y + 47.0f * p.z) * std::sin(53.0f * p.x);
}

constexpr long kStep = 1024;  // triangles or vertices between two checks of the work left

}  // namespace

Resumable generate_icosphere_steps(int level, float displace, MeshData& m) {
  m = MeshData();
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  for (glm::vec3 v : {glm::vec3(-1, t, 0), glm::vec3(1, t, 0), glm::vec3(-1, -t, 0), glm::vec3(1, -t, 0), glm::vec3(0, -1, t),
                      glm::vec3(0, 1, t), glm::vec3(0, -1, -t), glm::vec3(0, 1, -t), glm::vec3(t, 0, -1), glm::vec3(t, 0, 1),
                      glm::vec3(-t, 0, -1), glm::vec3(-t, 0, 1)})
    m.positions.push_back(glm::normalize(v));
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    // Each edge's midpoint, made once: an open-addressing table of (edge + 1) keys, a
    // power of two at least twice the edges (3/2 per triangle), freed in one piece (a map
    // of nodes took a long, unsliced while to free at the last level).
    size_t capacity = 64;
    int shift = 58;  // 64 - log2(capacity): the product's top bits index the table
    while (capacity < 3 * m.triangles.size()) capacity *= 2, --shift;
    m.positions.reserve(m.positions.size() + 3 * m.triangles.size() / 2);
    // Cleared in slices (a fresh 32 MB table touched in one step took 60 ms here).
    std::vector<uint64_t> keys;
    keys.reserve(capacity);
    while (keys.size() < capacity) {
      keys.resize(std::min(capacity, keys.size() + 16 * size_t(kStep)), 0);
      co_await Work{kStep};
    }
    std::unique_ptr<unsigned[]> values(new unsigned[capacity]);  // read only where a key is set
    auto midpoint = [&](unsigned a, unsigned b) {
      const uint64_t key = (a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a)) + 1;
      size_t i = size_t((key * 0x9E3779B97F4A7C15ull) >> shift);
      while (keys[i] != 0 && keys[i] != key) i = (i + 1) & (capacity - 1);
      if (keys[i] == 0) {
        keys[i] = key;
        values[i] = unsigned(m.positions.size());
        m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
      }
      return values[i];
    };
    std::vector<glm::uvec3> next;
    next.reserve(m.triangles.size() * 4);
    for (size_t i = 0; i < m.triangles.size(); ++i) {
      const glm::uvec3 tri = m.triangles[i];
      const unsigned ab = midpoint(tri.x, tri.y), bc = midpoint(tri.y, tri.z), ca = midpoint(tri.z, tri.x);
      next.insert(next.end(), {{tri.x, ab, ca}, {tri.y, bc, ab}, {tri.z, ca, bc}, {ab, bc, ca}});
      if (i % kStep == kStep - 1) co_await Work{kStep};
    }
    m.triangles.swap(next);
  }
  for (size_t i = 0; i < m.positions.size(); ++i) {
    m.positions[i] *= 1.0f + displace * bumps(m.positions[i]);
    if (i % kStep == kStep - 1) co_await Work{kStep};
  }
  // Area-weighted vertex normals of the displaced surface; uv by longitude and latitude.
  // Fresh arrays are filled in slices, like the edge table: touching 8 MB of new pages in
  // one step is slow where page faults are (20 MB took 100 ms natively on the test VM).
  m.normals.reserve(m.positions.size());
  while (m.normals.size() < m.positions.size()) {
    m.normals.resize(std::min(m.positions.size(), m.normals.size() + 16 * size_t(kStep)), glm::vec3(0.0f));
    co_await Work{kStep};
  }
  for (size_t i = 0; i < m.triangles.size(); ++i) {
    const glm::uvec3 tri = m.triangles[i];
    const glm::vec3 n = glm::cross(m.positions[tri.y] - m.positions[tri.x], m.positions[tri.z] - m.positions[tri.x]);
    for (int k = 0; k < 3; ++k) m.normals[tri[k]] += n;
    if (i % kStep == kStep - 1) co_await Work{kStep};
  }
  m.uvs.reserve(m.positions.size());
  for (size_t i = 0; i < m.positions.size(); ++i) {
    m.normals[i] = glm::normalize(m.normals[i]);
    const glm::vec3 d = glm::normalize(m.positions[i]);
    m.uvs.emplace_back(0.5f + std::atan2(d.z, d.x) / 6.2831853f, std::acos(glm::clamp(d.y, -1.0f, 1.0f)) / 3.14159265f);
    if (i % kStep == kStep - 1) co_await Work{kStep};
  }
}

MeshData generate_icosphere(int level, float displace) {
  MeshData m;
  generate_icosphere_steps(level, displace, m).finish();
  return m;
}

}  // namespace pt
