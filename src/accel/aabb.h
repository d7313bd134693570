// Axis-aligned bounding boxes for the BVH builder.
#pragma once
#include <glm/glm.hpp>

namespace pt {

struct Aabb {
  glm::vec3 lo{3.0e38f}, hi{-3.0e38f};  // empty: lo > hi

  void grow(glm::vec3 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void grow(const Aabb& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  glm::vec3 center() const { return 0.5f * (lo + hi); }
  // Half the surface area (the SAH only compares ratios); 0 for an empty box.
  float half_area() const {
    if (empty()) return 0.0f;
    const glm::vec3 e = hi - lo;
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
  // Widened outward by a few ulps of its largest coordinate, so that a point computed on
  // a primitive's surface (or a ray lying in one of its faces) is strictly inside, and
  // the traversal's float slab test cannot reject what the primitive's own test accepts.
  Aabb padded() const {
    const float m = glm::max(glm::max(glm::max(std::abs(lo.x), std::abs(lo.y)), std::abs(lo.z)),
                             glm::max(glm::max(std::abs(hi.x), std::abs(hi.y)), std::abs(hi.z)));
    const float eps = m * 2.4e-7f + 1e-30f;  // 4 ulps of m
    return Aabb{lo - eps, hi + eps};
  }
};

}  // namespace pt
