// Test input for the BVH tests: boxes clustered like real scenes, most in a few dense
// clumps, the rest spread thin. Deterministic for a seed.
#pragma once
#include <cmath>
#include <random>
#include <vector>

#include "accel/aabb.h"

namespace pt {

inline std::vector<Aabb> random_boxes(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-100.0f, 100.0f), s(0.01f, 3.0f), clump(-4.0f, 4.0f);
  std::vector<Aabb> boxes(static_cast<size_t>(n));
  const glm::vec3 centres[3] = {{-60.0f, 10.0f, 30.0f}, {50.0f, -70.0f, 0.0f}, {10.0f, 80.0f, -40.0f}};
  for (size_t i = 0; i < boxes.size(); ++i) {
    Aabb& b = boxes[i];
    const glm::vec3 c = i % 10 == 0 ? glm::vec3(u(rng), u(rng), u(rng)) : centres[i % 3] + glm::vec3(clump(rng), clump(rng), clump(rng));
    b.grow(c - glm::vec3(s(rng), s(rng), s(rng)));
    b.grow(c + glm::vec3(s(rng), s(rng), s(rng)));
  }
  return boxes;
}

// Boxes shrinking geometrically towards the origin: SAH peels one per level, so without a
// depth bound the tree would be n deep.
inline std::vector<Aabb> geometric_chain(int n) {
  std::vector<Aabb> chain;
  for (int i = 0; i < n; ++i) {
    Aabb b;
    const float x = std::pow(0.9f, float(i)) * 1e3f;
    b.grow(glm::vec3(x));
    b.grow(glm::vec3(x * 1.01f));
    chain.push_back(b);
  }
  return chain;
}

}  // namespace pt
