// The integer tables of a packing (PackedScene::light_shape, node_parent, node_first,
// node_count, prim_leaf, prim_shape, shape_prim) come from the builder, and they say what
// the float records say: each light record's shape, each node's parent, children or
// primitives, each primitive's leaf and shape, each analytic shape's or lone triangle's
// primitive. Checked against the records on the shipped scenes and on a scene
// of every shape role (planes outside the BVH, lone triangles, one degenerate, mesh instances),
// packed in one run and in slices.
#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstring>
#include <string>

#include <catch2/catch.hpp>

#include "render/packing.h"
#include "scene/xml_loader.h"
#include "test_paths.h"

using namespace pt;

namespace {

const char* kRoles = R"(<SceneLevel><Camera position="0 0 3" yaw="90" pitch="0"/>
  <Light position="1 2 2" radius="0.3" color="1 1 1" intensity="40"/><Objects>
  <Sphere center="1.5 0 0" radius="0.4"><Diffuse/></Sphere>
  <Plane normal="0 1 0" d="-1"><Diffuse/></Plane>
  <Plane normal="0 0 1" d="-5"><Diffuse/></Plane>
  <Box min="-1 -1 -1" max="-0.5 -0.5 -0.5"><Emit><Absorb intensity="3" color="1 1 1"/></Emit></Box>
  <Triangle v0="0 0 0" v1="1 0 0" v2="0 1 0"><Emit><Absorb intensity="2" color="1 1 1"/></Emit></Triangle>
  <Triangle v0="0 0 0" v1="1 0 0" v2="0 0 1"><Diffuse/></Triangle>
  <Mesh generate="icosphere" level="3" position="0 0.5 0"><Diffuse/></Mesh>
  <Mesh generate="icosphere" level="2" scale="0.3" position="-2 0 0"><Diffuse/></Mesh>
</Objects></SceneLevel>)";

void check_tables(const Scene& scene, const PackedScene& p) {
  REQUIRE(p.light_shape.size() == size_t(p.lights.count()));
  for (int i = 0; i < p.lights.count(); ++i) CHECK(p.light_shape[size_t(i)] == int(p.lights.get(i, light_rec::shape)));
  CHECK(light_shapes(scene) == p.light_shape);

  REQUIRE(p.node_parent.size() == size_t(p.nodes.count()));
  REQUIRE(p.prim_leaf.size() == size_t(p.prims.count()));
  REQUIRE(p.shape_prim.size() == scene.shapes.size());
  std::vector<int> parent(p.node_parent.size(), -1), leaf(p.prim_leaf.size(), -1), prim(scene.shapes.size(), -1), owners;
  std::vector<int> firsts, counts;
  for (int n = 0; n < p.nodes.count(); ++n) {
    const int first = int(p.nodes.get(n, node_rec::first)), count = int(p.nodes.get(n, node_rec::count));
    firsts.push_back(first);
    counts.push_back(count);
    if (node_prims(count) > 0)  // (a moving shape's node carries it above bit 4: packing.h)
      for (int q = first; q < first + node_prims(count); ++q) leaf[size_t(q)] = n;
    else
      parent[size_t(first)] = parent[size_t(first) + 1] = n;
  }
  for (int q = 0; q < p.prims.count(); ++q) {
    const int tag = int(p.prims.get(q, prim_rec::tag));
    const int owner = tag < 0 ? -1 - tag : tag;
    owners.push_back(owner);
    if (tag < 0 || scene.shapes[size_t(owner)].kind() != ShapeKind::Mesh) prim[size_t(owner)] = q;
  }
  CHECK(p.node_parent == parent);
  CHECK(p.prim_leaf == leaf);
  CHECK(p.shape_prim == prim);
  CHECK(p.prim_shape == owners);
  CHECK(p.node_first == firsts);
  CHECK(p.node_count == counts);
  for (int q = 0; q < p.unbounded; ++q) CHECK(p.prim_leaf[size_t(q)] == -1);  // planes are outside the BVH
  if (p.nodes.count() > 0) CHECK(p.node_parent[0] == -1);
}

}  // namespace

TEST_CASE("the packing's light, parent, leaf and primitive tables agree with its records", "[packing]") {
  std::vector<Scene> scenes;
  scenes.push_back(load_scene_text(kRoles, "roles.xml", false));
  // The last triangle made degenerate (an edit can; the loader refuses one).
  Scene flat = scenes.front();
  int degenerate = -1;
  for (size_t i = 0; i < flat.shapes.size(); ++i)
    if (flat.shapes[i].kind() == ShapeKind::Triangle) degenerate = int(i);
  REQUIRE(degenerate >= 0);
  flat.shapes[size_t(degenerate)].as<Triangle>()->v2 = glm::vec3(2, 0, 0);
  scenes.push_back(flat);
  for (const char* f : {"scenes/reference/scene2.xml", "scenes/mesh-cube.xml", "scenes/gltf-instances.xml"})
    scenes.push_back(load_scene_file(repo_path(f)));
  for (const Scene& scene : scenes) {
    INFO(scene.path);
    const PackedScene one = pack_scene(scene);
    check_tables(scene, one);
    PackJob job(scene);
    while (!job.run(5)) {
    }
    const PackedScene sliced = job.take();
    CHECK(sliced.node_parent == one.node_parent);
    CHECK(sliced.prim_leaf == one.prim_leaf);
    CHECK(sliced.shape_prim == one.shape_prim);
    CHECK(sliced.light_shape == one.light_shape);
  }
  const PackedScene p = pack_scene(scenes.front());
  CHECK(p.unbounded == 2);
  CHECK(p.light_shape.size() == 3);  // the light's sphere, the emitting box and triangle
  CHECK(p.shape_prim[size_t(degenerate)] >= 0);
  const PackedScene q = pack_scene(flat);
  CHECK(q.shape_prim[size_t(degenerate)] == -1);  // not in the BVH: nothing to draw
}

// The flat-or-BVH rule (accel/accel_choice.h) weighs the scene's own BVH: at an equal
// count, spheres nested in one place (every ray that meets one meets the others' boxes:
// the BVH culls nothing, SAH cost above the count) get the loop, spheres spread in a row
// (the BVH culls all but a few) the BVH. Planes are outside the BVH and do not count.
TEST_CASE("auto traversal: the loop where it costs at most kFlatPerSah x the BVH's SAH cost", "[accel]") {
  CHECK(auto_flat(1, 1.0));
  CHECK(auto_flat(22, 10.0));
  CHECK_FALSE(auto_flat(23, 10.0));
  CHECK_FALSE(auto_flat(kFlatMaxConsidered + 1, 1e9));
  const auto spheres = [](int n, float spacing) {
    std::string xml = "<SceneLevel><Camera position=\"0 0 30\"/><Objects><Plane normal=\"0 1 0\" d=\"-5\"><Diffuse/></Plane>";
    for (int i = 0; i < n; ++i)
      xml += "<Sphere center=\"" + std::to_string(float(i) * spacing) + " 0 0\" radius=\"" + std::to_string(0.4f + 0.01f * float(i)) + "\"><Diffuse/></Sphere>";
    return load_scene_text(xml + "</Objects></SceneLevel>", "spheres.xml");
  };
  const Scene nested = spheres(20, 0.0f), row = spheres(20, 3.0f);
  const AccelCosts a = accel_costs(nested), b = accel_costs(row);
  std::printf("20 nested spheres: SAH cost %.2f; 20 in a row: %.2f\n", a.sah, b.sah);
  CHECK(a.bounded == 20);
  CHECK(b.bounded == 20);
  CHECK(a.sah > 10.0);
  CHECK(b.sah < 8.0);
  CHECK(a.flat());
  CHECK_FALSE(b.flat());
  // From the packing when given, the same figures; above kFlatMaxConsidered no packing at all.
  const PackedScene p = pack_scene(row);
  CHECK(accel_costs(row, &p).sah == b.sah);
  const AccelCosts big = accel_costs(spheres(int(kFlatMaxConsidered) + 1, 0.0f));
  CHECK(big.bounded == kFlatMaxConsidered + 1);
  CHECK(big.sah == 0.0);
  CHECK_FALSE(big.flat());
  // The shipped scenes the rule was fitted on (docs/benchmarks.md): scene2's room gets the
  // loop, scene0 and the Cornell box the BVH.
  CHECK(accel_costs(load_scene_file(repo_path("scenes/reference/scene2.xml"))).flat());
  CHECK_FALSE(accel_costs(load_scene_file(repo_path("scenes/reference/scene0.xml"))).flat());
  CHECK_FALSE(accel_costs(load_scene_file(repo_path("scenes/cornell-box.xml"))).flat());
}

// The flat loop's order (render/packing.h: flat_order; shaders/bvh.glsl HAS_FLAT_ORDER):
// every primitive once, grouped by what tests it (an analytic primitive by its kind, read
// back from its record; a triangle last), in leaf order within a group; none for a scene
// above kFlatOrderMax primitives.
TEST_CASE("the flat loop's order: kind by kind, leaf order within a kind", "[packing][accel]") {
  std::string small = kRoles;
  for (const char* level : {"level=\"3\"", "level=\"2\""}) small.replace(small.find(level), std::strlen(level), "level=\"0\"");
  const Scene scene = load_scene_text(small, "roles.xml");
  const PackedScene p = pack_scene(scene);
  REQUIRE(p.prims.count() <= kFlatOrderMax);
  const FlatOrder o = flat_order(scene, p);
  REQUIRE(o.prims.size() == size_t(p.prims.count()));
  std::vector<int> seen(o.prims.size(), 0);
  int begin = 0, groups = 0;
  for (int g = 0; g < kFlatGroups; ++g) {
    const int end = o.end[size_t(g)];
    REQUIRE(end >= begin);
    groups += end > begin;
    for (int j = begin; j < end; ++j) {
      const int q = o.prims[size_t(j)];
      ++seen[size_t(q)];
      const int tag = int(p.prims.get(q, prim_rec::tag));
      CHECK((tag >= 0 ? kNumShapeKinds : int(p.prims.get(q, prim_rec::kind))) == g);
      if (j > begin) CHECK(q > o.prims[size_t(j) - 1]);
    }
    begin = end;
  }
  CHECK(begin == p.prims.count());
  CHECK(std::count(seen.begin(), seen.end(), 1) == p.prims.count());
  CHECK(groups == 4);  // spheres, boxes, planes, triangles (lone and the meshes')
  const Scene large = load_scene_text(kRoles, "roles.xml");
  CHECK(flat_order(large, pack_scene(large)).prims.empty());
}
