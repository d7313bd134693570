// The BVH builder: structure invariants on random and adversarial inputs, the SAH doing
// better than median splits, the depth bound the GPU stack relies on, and build speed.
#include <algorithm>
#include <ctime>
#include <cstdio>
#include <random>

#include <catch2/catch.hpp>

#include "accel/bvh.h"
#include "accel/test_boxes.h"

using namespace pt;

namespace {

// Every primitive in exactly one leaf; boxes nest; leaves within the size bound.
void check_structure(const Bvh& bvh, const std::vector<Aabb>& boxes, const BvhBuildOptions& o) {
  REQUIRE(bvh.order.size() == boxes.size());
  std::vector<int> seen(boxes.size(), 0);
  int depth = 0;
  struct Item {
    int node, depth;
  };
  std::vector<Item> todo{{0, 1}};
  while (!todo.empty()) {
    const Item it = todo.back();
    todo.pop_back();
    depth = std::max(depth, it.depth);
    const BvhNode& n = bvh.nodes.at(size_t(it.node));
    auto inside = [&](const Aabb& b) {
      return glm::all(glm::lessThanEqual(n.box.lo, b.lo)) && glm::all(glm::greaterThanEqual(n.box.hi, b.hi));
    };
    if (n.count > 0) {
      REQUIRE(n.count <= std::max(o.max_leaf, boxes.size() <= size_t(o.single_leaf_max) ? o.single_leaf_max : 0));
      for (int i = n.first; i < n.first + n.count; ++i) {
        const int p = bvh.order.at(size_t(i));
        ++seen.at(size_t(p));
        REQUIRE(inside(boxes[size_t(p)]));
      }
    } else {
      REQUIRE(n.first > it.node);
      REQUIRE(inside(bvh.nodes.at(size_t(n.first)).box));
      REQUIRE(inside(bvh.nodes.at(size_t(n.first) + 1).box));
      todo.push_back({n.first, it.depth + 1});
      todo.push_back({n.first + 1, it.depth + 1});
    }
  }
  CHECK(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
  CHECK(depth == bvh.depth);
  CHECK(bvh.depth <= o.max_depth);
}


}  // namespace

TEST_CASE("BVH: structure on random boxes, and SAH beats object-median splits", "[bvh]") {
  const std::vector<Aabb> boxes = random_boxes(20000, 3);
  BvhBuildOptions o;
  const Bvh bvh = build_bvh(boxes, o);
  check_structure(bvh, boxes, o);
  BvhBuildOptions median = o;
  median.max_depth = 1;  // forces median splits everywhere
  const Bvh m = build_bvh(boxes, median);
  BvhBuildOptions loose = o;
  loose.max_depth = 64;
  check_structure(m, boxes, loose);
  std::printf("BVH of 20000 random boxes: %zu nodes, depth %d, SAH cost %.1f (median splits: depth %d, cost %.1f)\n",
              bvh.nodes.size(), bvh.depth, bvh.sah_cost(), m.depth, m.sah_cost());
  CHECK(bvh.sah_cost() < 0.9 * m.sah_cost());
}

TEST_CASE("BVH: degenerate inputs (one primitive, coincident centroids, a geometric chain) stay bounded", "[bvh]") {
  BvhBuildOptions o;
  o.max_depth = 20;
  CHECK(build_bvh({}, o).nodes.empty());
  std::vector<Aabb> one(1);
  one[0].grow(glm::vec3(1.0f));
  const Bvh b1 = build_bvh(one, o);
  check_structure(b1, one, o);
  CHECK(b1.nodes.size() == 1);
  std::vector<Aabb> same(1000, one[0]);  // every centroid equal: SAH finds no plane
  check_structure(build_bvh(same, o), same, o);
  const std::vector<Aabb> chain = geometric_chain(1000);  // about 1000 deep without the bound
  const Bvh bc = build_bvh(chain, o);
  check_structure(bc, chain, o);
  std::printf("geometric chain of 1000 boxes: depth %d (bound %d)\n", bc.depth, o.max_depth);
}

TEST_CASE("BVH: build time for one million triangles", "[bvh][speed]") {
  // Triangles of a 1000 x 500 grid on a bumpy sphere-like surface: realistic boxes.
  const int W = 1000, H = 500;
  std::vector<Aabb> boxes;
  boxes.reserve(size_t(W) * H * 2);
  auto vertex = [&](int i, int j) {
    const float th = 3.14159265f * float(j) / float(H), ph = 6.2831853f * float(i) / float(W);
    const float r = 1.0f + 0.05f * std::sin(13.0f * ph) * std::sin(17.0f * th);
    return glm::vec3(r * std::sin(th) * std::cos(ph), r * std::cos(th), r * std::sin(th) * std::sin(ph));
  };
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const glm::vec3 a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i, j + 1), d = vertex(i + 1, j + 1);
      Aabb t1, t2;
      for (glm::vec3 p : {a, b, d}) t1.grow(p);
      for (glm::vec3 p : {a, d, c}) t2.grow(p);
      boxes.push_back(t1);
      boxes.push_back(t2);
    }
  // CPU time of this thread: the builder runs on one core, and a busy machine (other
  // jobs of a parallel ctest) must not make it look slower than it is.
  auto cpu_seconds = [] {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
  };
  const double t0 = cpu_seconds();
  const Bvh bvh = build_bvh(boxes);
  const double s = cpu_seconds() - t0;
  std::printf("BVH build: %zu triangles in %.3f s of CPU time (one core), %zu nodes, depth %d\n", boxes.size(), s, bvh.nodes.size(),
              bvh.depth);
  check_structure(bvh, boxes, BvhBuildOptions{});
#if defined(__SANITIZE_ADDRESS__)
  WARN("AddressSanitizer build: the 2 s target applies to the release build only");
#else
  CHECK(s < 2.0);  // the target for one million triangles natively
#endif
}
