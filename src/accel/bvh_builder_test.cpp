// The resumable BVH build and the sliced scene packing give, bit for bit, what the
// one-shot builder gave before them: the reference below is the builder as it was
// (commit 6f7cd2c, verbatim but for its name), so slicing cannot change a hierarchy
// unnoticed. Boxes of random clumps, degenerate inputs, and the shipped scenes.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>

#include <catch2/catch.hpp>

#include "accel/bvh.h"
#include "accel/test_boxes.h"
#include "render/packing.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace reference {

constexpr int kMaxBins = 64;

struct Task {
  int node, begin, end, depth;
};

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin] go left
  float cost = 3.0e38f;
};

class Builder {
 public:
  Builder(const std::vector<Aabb>& boxes, const BvhBuildOptions& o, Bvh& out) : boxes_(boxes), o_(o), out_(out) {
    const size_t n = boxes.size();
    centers_.resize(n);
    out_.order.resize(n);
    for (size_t i = 0; i < n; ++i) {
      centers_[i] = boxes[i].center();
      out_.order[i] = int(i);
    }
    o_.bins = std::clamp(o_.bins, 2, kMaxBins);
    o_.max_leaf = std::clamp(o_.max_leaf, 1, 16);
    o_.single_leaf_max = std::clamp(o_.single_leaf_max, 1, 16);
  }

  void run() {
    if (boxes_.empty()) return;
    out_.nodes.reserve(2 * boxes_.size() / std::min(o_.max_leaf, 2) + 1);
    out_.nodes.emplace_back();
    if (int(boxes_.size()) <= o_.single_leaf_max) {
      for (const Aabb& b : boxes_) out_.nodes[0].box.grow(b);
      out_.nodes[0].first = 0;
      out_.nodes[0].count = int(boxes_.size());
      out_.depth = 1;
      return;
    }
    std::vector<Task> stack{{0, 0, int(boxes_.size()), 1}};
    while (!stack.empty()) {
      const Task t = stack.back();
      stack.pop_back();
      out_.depth = std::max(out_.depth, t.depth);
      Aabb box, cbox;
      for (int i = t.begin; i < t.end; ++i) {
        const int p = out_.order[size_t(i)];
        box.grow(boxes_[size_t(p)]);
        cbox.grow(centers_[size_t(p)]);
      }
      out_.nodes[size_t(t.node)].box = box;
      const int n = t.end - t.begin;
      int mid = -1;
      if (n > o_.max_leaf && t.depth + levels_below(n) >= o_.max_depth) {
        mid = median_split(t, cbox);  // keeps the depth within max_depth
      } else if (n > 1 && t.depth < o_.max_depth) {
        const Split s = best_split(t, box, cbox);
        const float leaf_cost = float(n);
        if (s.axis >= 0 && (n > o_.max_leaf || s.cost < leaf_cost)) {
          mid = partition(t, cbox, s);
        } else if (s.axis < 0 && n > o_.max_leaf) {
          mid = median_split(t, cbox);  // all centroids coincide: any split is as good
        }
      }
      BvhNode& node = out_.nodes[size_t(t.node)];
      if (mid < 0) {
        node.first = t.begin;
        node.count = n;
        continue;
      }
      const int c = int(out_.nodes.size());
      node.first = c;
      node.count = 0;
      out_.nodes.emplace_back();
      out_.nodes.emplace_back();
      stack.push_back({c + 1, mid, t.end, t.depth + 1});  // the left child is built first
      stack.push_back({c, t.begin, mid, t.depth + 1});
    }
  }

 private:
  // Levels a balanced tree needs below a node of n primitives.
  int levels_below(int n) const {
    int levels = 0;
    for (int leaves = (n + o_.max_leaf - 1) / o_.max_leaf; (1 << levels) < leaves;) ++levels;
    return levels;
  }

  int median_split(const Task& t, const Aabb& cbox) {
    const glm::vec3 e = cbox.hi - cbox.lo;
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const int mid = t.begin + (t.end - t.begin) / 2;
    int* base = out_.order.data();
    std::nth_element(base + t.begin, base + mid, base + t.end,
                     [&](int a, int b) { return centers_[size_t(a)][axis] < centers_[size_t(b)][axis]; });
    return mid;
  }

  // NaN-safe: a centroid below the range (it cannot be) or a NaN lands in bin 0.
  int bin_of(float c, float lo, float scale) const {
    const float f = (c - lo) * scale;
    return f > 0.0f ? std::min(o_.bins - 1, int(std::min(f, float(o_.bins)))) : 0;
  }

  Split best_split(const Task& t, const Aabb& box, const Aabb& cbox) const {
    Split best;
    const glm::vec3 extent = cbox.hi - cbox.lo;
    for (int axis = 0; axis < 3; ++axis) {
      const float lo = cbox.lo[axis], scale = float(o_.bins) / extent[axis];
      if (!(extent[axis] > 0.0f) || !std::isfinite(scale)) continue;
      std::array<Aabb, kMaxBins> bin_box;
      std::array<int, kMaxBins> bin_count{};
      for (int i = t.begin; i < t.end; ++i) {
        const int p = out_.order[size_t(i)];
        const int b = bin_of(centers_[size_t(p)][axis], lo, scale);
        bin_box[size_t(b)].grow(boxes_[size_t(p)]);
        ++bin_count[size_t(b)];
      }
      // Right-to-left sweep of areas and counts, then left-to-right evaluation.
      std::array<float, kMaxBins> right_area{};
      std::array<int, kMaxBins> right_count{};
      Aabb acc;
      int cnt = 0;
      for (int b = o_.bins - 1; b > 0; --b) {
        acc.grow(bin_box[size_t(b)]);
        cnt += bin_count[size_t(b)];
        right_area[size_t(b)] = acc.half_area();
        right_count[size_t(b)] = cnt;
      }
      acc = Aabb{};
      cnt = 0;
      for (int b = 0; b < o_.bins - 1; ++b) {
        acc.grow(bin_box[size_t(b)]);
        cnt += bin_count[size_t(b)];
        if (cnt == 0 || right_count[size_t(b) + 1] == 0) continue;
        const float cost = acc.half_area() * float(cnt) + right_area[size_t(b) + 1] * float(right_count[size_t(b) + 1]);
        if (cost < best.cost) best = Split{axis, b, cost};
      }
    }
    if (best.axis >= 0) {
      const float area = box.half_area();
      best.cost = o_.traversal_cost + (area > 0.0f ? best.cost / area : float(t.end - t.begin));
    }
    return best;
  }

  int partition(const Task& t, const Aabb& cbox, const Split& s) {
    const float lo = cbox.lo[s.axis], scale = float(o_.bins) / (cbox.hi[s.axis] - lo);
    auto* first = out_.order.data() + t.begin;
    auto* mid = std::partition(first, out_.order.data() + t.end,
                               [&](int p) { return bin_of(centers_[size_t(p)][s.axis], lo, scale) <= s.bin; });
    return int(mid - out_.order.data());
  }

  const std::vector<Aabb>& boxes_;
  BvhBuildOptions o_;
  Bvh& out_;
  std::vector<glm::vec3> centers_;
};

}  // namespace reference

namespace {

Bvh reference_build(const std::vector<Aabb>& boxes, const BvhBuildOptions& o) {
  Bvh bvh;
  reference::Builder(boxes, o, bvh).run();
  return bvh;
}

// Equal to the bit: boxes compared as bytes (-0 and +0 differ), links, counts, order.
bool same(const Bvh& a, const Bvh& b) {
  if (a.nodes.size() != b.nodes.size() || a.order != b.order || a.depth != b.depth) return false;
  for (size_t i = 0; i < a.nodes.size(); ++i) {
    const BvhNode &x = a.nodes[i], &y = b.nodes[i];
    if (std::memcmp(&x.box, &y.box, sizeof(Aabb)) != 0 || x.first != y.first || x.count != y.count) return false;
  }
  return true;
}

// Runs the builder in slices of `work` units; counts the slices.
Bvh sliced(const std::vector<Aabb>& boxes, const BvhBuildOptions& o, long work, int* slices) {
  BvhBuilder b(boxes, o);
  *slices = 0;
  double last = -1.0;
  while (!b.run(work)) {
    ++*slices;
    REQUIRE(b.progress() >= last);  // progress never goes back
    last = b.progress();
  }
  CHECK(b.progress() == 1.0);
  return b.take();
}


void check_against_reference(const std::vector<Aabb>& boxes, const BvhBuildOptions& o, const char* what) {
  const Bvh want = reference_build(boxes, o);
  INFO(what << ": " << boxes.size() << " boxes, " << want.nodes.size() << " nodes");
  CHECK(same(build_bvh(boxes, o), want));
  for (long work : {1L, 7L, 1000L, 65536L}) {
    int slices = 0;
    const Bvh got = sliced(boxes, o, work, &slices);
    INFO("slices of " << work << " units: " << slices);
    CHECK(same(got, want));
    if (work <= 1000 && boxes.size() > 100) CHECK(slices > 0);  // it did stop and resume
  }
}

}  // namespace

TEST_CASE("BVH: the sliced build equals the one-shot reference builder, bit for bit", "[bvh]") {
  BvhBuildOptions o;
  check_against_reference(random_boxes(20000, 3), o, "random clumps");
  check_against_reference(random_boxes(3000, 11), BvhBuildOptions{8, 4, 1, 1.0f, 10}, "shallow depth bound (median splits)");
  std::vector<Aabb> one(1);
  one[0].grow(glm::vec3(1.0f));
  check_against_reference(one, o, "one box");
  check_against_reference(std::vector<Aabb>(1000, one[0]), o, "coincident centroids");
  const std::vector<Aabb> chain = geometric_chain(1000);  // peeled one per level down to the depth bound
  BvhBuildOptions deep = o;
  deep.max_depth = 20;
  check_against_reference(chain, deep, "geometric chain");
  CHECK(build_bvh({}, o).nodes.empty());
  const std::vector<Aabb> none;
  BvhBuilder empty(none, o);
  CHECK(empty.done());
  CHECK(empty.progress() == 1.0);
}

TEST_CASE("packing in slices gives the one-shot pack; its BVH is the reference builder's", "[bvh][packing]") {
  const std::string icosphere = R"(<SceneLevel><Camera position="0 0 3" yaw="90" pitch="0"/><Objects>
    <Sphere center="2 0 0" radius="0.5"><Diffuse/></Sphere>
    <Plane normal="0 1 0" d="-1"><Diffuse/></Plane>
    <Mesh generate="icosphere" level="5" displace="0.05" position="0 0.2 0"><Diffuse/></Mesh>
    <Mesh generate="icosphere" level="3" scale="0.3" position="-2 0 0"><Diffuse/></Mesh>
  </Objects></SceneLevel>)";
  std::vector<Scene> scenes;
  for (const char* f : {"scenes/gltf-instances.xml", "scenes/reference/scene2.xml", "scenes/mesh-cube.xml", "scenes/textures.xml"})
    scenes.push_back(load_scene_file(repo_path(f)));
  scenes.push_back(load_scene_text(icosphere, "icosphere.xml", false));
  for (const Scene& scene : scenes) {
    INFO(scene.path);
    const PackedScene one = pack_scene(scene);
    for (long work : {1L, 333L, 100000L}) {
      PackJob job(scene);
      int slices = 0;
      double last = 0.0;
      while (!job.run(work)) {
        ++slices;
        REQUIRE(job.progress() >= last);
        REQUIRE(job.progress() <= 1.0);
        last = job.progress();
      }
      INFO("slices of " << work << " units: " << slices);
      CHECK(job.progress() == 1.0);
      BvhBuildOptions o;
      o.max_depth = kBvhStackSize + 1;
      const Bvh want = reference_build(job.boxes(), o);
      const PackedScene p = job.take();
      CHECK(p.bvh_depth == want.depth);
      CHECK(p.nodes.count() == int(want.nodes.size()));
      for (const auto& [a, b] : {std::pair{&one.shapes, &p.shapes}, {&one.materials, &p.materials}, {&one.lights, &p.lights},
                                 {&one.nodes, &p.nodes}, {&one.prims, &p.prims}, {&one.vertices, &p.vertices}})
        CHECK(a->texels() == b->texels());
      CHECK(p.unbounded == one.unbounded);
      // The node records hold the reference's boxes and links.
      const std::vector<float> t = p.nodes.texels();
      bool nodes_match = true;
      for (size_t i = 0; i < want.nodes.size() && nodes_match; ++i) {
        const BvhNode& n = want.nodes[i];
        const float* r = &t[i * size_t(node_rec::kTexels) * 4];
        const glm::vec3 lo(r[node_rec::lo.texel * 4 + node_rec::lo.comp], r[node_rec::lo.texel * 4 + node_rec::lo.comp + 1],
                           r[node_rec::lo.texel * 4 + node_rec::lo.comp + 2]);
        const float count = r[node_rec::count.texel * 4 + node_rec::count.comp];
        nodes_match = std::memcmp(&lo, &n.box.lo, sizeof lo) == 0 && count == float(n.count);
      }
      CHECK(nodes_match);
    }
  }
}
