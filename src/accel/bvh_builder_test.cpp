// The resumable BVH build and the sliced scene packing give, bit for bit, what one
// uninterrupted run gives (build_bvh, pack_scene): stopping and resuming at any unit of
// work cannot change a hierarchy. (When slicing was introduced, this compared against a
// verbatim copy of the builder before it, commit 6f7cd2c, and matched.) Boxes of random
// clumps, degenerate inputs, and the shipped scenes.
#include <cstring>

#include <catch2/catch.hpp>

#include "accel/bvh.h"
#include "accel/test_boxes.h"
#include "render/packing.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

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


void check_slicing(const std::vector<Aabb>& boxes, const BvhBuildOptions& o, const char* what) {
  const Bvh want = build_bvh(boxes, o);  // one uninterrupted run
  INFO(what << ": " << boxes.size() << " boxes, " << want.nodes.size() << " nodes");
  for (long work : {1L, 7L, 1000L, 65536L}) {
    int slices = 0;
    const Bvh got = sliced(boxes, o, work, &slices);
    INFO("slices of " << work << " units: " << slices);
    CHECK(same(got, want));
    if (work <= 1000 && boxes.size() > 100) CHECK(slices > 0);  // it did stop and resume
  }
}

}  // namespace

TEST_CASE("BVH: the sliced build equals the one-shot build, bit for bit", "[bvh]") {
  BvhBuildOptions o;
  check_slicing(random_boxes(20000, 3), o, "random clumps");
  check_slicing(random_boxes(3000, 11), BvhBuildOptions{8, 4, 1, 1.0f, 10}, "shallow depth bound (median splits)");
  std::vector<Aabb> one(1);
  one[0].grow(glm::vec3(1.0f));
  check_slicing(one, o, "one box");
  check_slicing(std::vector<Aabb>(1000, one[0]), o, "coincident centroids");
  const std::vector<Aabb> chain = geometric_chain(1000);  // peeled one per level down to the depth bound
  BvhBuildOptions deep = o;
  deep.max_depth = 20;
  check_slicing(chain, deep, "geometric chain");
  CHECK(build_bvh({}, o).nodes.empty());
  const std::vector<Aabb> none;
  BvhBuilder empty(none, o);
  CHECK(empty.done());
  CHECK(empty.progress() == 1.0);
}

TEST_CASE("packing in slices gives the one-shot pack; its BVH is the one-shot build's", "[bvh][packing]") {
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
      const Bvh want = build_bvh(job.boxes(), o);
      const PackedScene p = job.take();
      CHECK(p.bvh_depth == want.depth);
      CHECK(p.nodes.count() == int(want.nodes.size()));
      for (const auto& [a, b] : {std::pair{&one.shapes, &p.shapes}, {&one.materials, &p.materials}, {&one.lights, &p.lights},
                                 {&one.nodes, &p.nodes}, {&one.prims, &p.prims}, {&one.vertices, &p.vertices}})
        CHECK(a->texels() == b->texels());
      CHECK(p.unbounded == one.unbounded);
      // The node records hold the one-shot build's boxes and links.
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
