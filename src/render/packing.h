// Scene -> the record buffers of core/records.h, including the BVH over every bounded
// primitive (accel/bvh.h) and the primitives in its leaf order.
#pragma once
#include <array>
#include <memory>

#include "accel/accel_choice.h"
#include "accel/bvh.h"
#include "core/records.h"
#include "scene/scene.h"
#include "shadergen/shadergen.h"

namespace pt {

struct PackedScene {
  RecordBuffer shapes{shape_rec::kTexels};
  RecordBuffer materials{material_rec::kTexels};
  RecordBuffer lights{light_rec::kTexels};
  RecordBuffer nodes{node_rec::kTexels};
  RecordBuffer prims{prim_rec::kTexels};
  RecordBuffer vertices{vertex_rec::kTexels};
  int unbounded = 0;  // prims [0, unbounded) lie outside the BVH (planes): every ray tests them
  int bvh_depth = 0;
  float motion_bound = 0.0f;  // moving shapes are bounded over times [0, motion_bound]
  double bvh_build_ms = 0.0;
  // The BVH's expected cost per ray in the SAH model (accel/bvh.h: Bvh::sah_cost; one node
  // visit costs one primitive test), for the flat-or-BVH rule (accel/accel_choice.h).
  double bvh_sah_cost = 0.0;
  // Who is whose, as integers from the packing itself (never read back from the float
  // records): each light record's shape (Renderer::update_values compares them); for
  // refit_shape, each BVH node's parent (-1: the root), first child or primitive and
  // count (node_prims: 0 for an interior node; node_mover), each primitive's leaf (-1: unbounded) and shape, and
  // each analytic shape's or lone triangle's primitive (-1: none). A PackedScene of
  // pack_values has none of them.
  std::vector<int> light_shape;
  // The boxes that seal lights off (render/light_select.h): light selection is by power
  // while the camera is outside all of them, uniform while inside one.
  std::vector<glm::vec3> seal_lo, seal_hi;
  std::vector<int> node_parent, node_first, node_count, prim_leaf, prim_shape, shape_prim;
};

// A BVH node record's count (and PackedScene::node_count): the leaf's primitive count in
// bits 0..4 (0: interior) and, for a node whose primitives all belong to one moving shape
// m (motion blur), m + 1 from bit 5 up: its box is at time 0 and moves with m (bvh.glsl;
// render/packing_motion.cpp). 0 above bit 4 in a scene without motion.
inline int node_prims(int count) { return count & 31; }
inline int node_mover(int count) { return (count >> 5) - 1; }
inline constexpr int kMaxMover = (1 << 19) - 2;  // the largest m whose count stays exact in a float

// Motion blur: for a BVH built over boxes at time 0 of the primitives of moving shapes
// (mover[prim] = its shape; -1: still, its box holding it at every time), the shape whose
// velocity moves each node's box (-1: none), with the boxes of the other nodes grown to
// hold their primitives over [0, motion_bound] (render/packing_motion.cpp).
std::vector<int> sweep_bvh(Bvh& bvh, const std::vector<Aabb>& boxes, const std::vector<int>& mover,
                           const std::vector<glm::vec3>& velocity, float motion_bound);
Aabb swept_box(const Aabb& b, glm::vec3 velocity, float motion_bound);  // b and b + velocity * motion_bound

// The traversal's stack holds at most depth - 1 entries: hierarchies deeper than this are
// rebuilt with median splits below that depth (see build_bvh's max_depth).
inline constexpr int kBvhStackSize = 48;

PackedScene pack_scene(const Scene& scene);  // runs a PackJob to completion

// What the flat-or-BVH rule (accel/accel_choice.h: auto_flat) weighs: the primitives in
// the BVH (planes excluded: every ray tests them either way) and the BVH's SAH cost per
// ray. Only for a scene of at most kFlatMaxConsidered of them (above, sah is 0: the rule
// does not need it), from `packed` when given, else from a packing made here.
struct AccelCosts {
  long bounded = 0;
  double sah = 0.0;
  bool flat() const;  // auto_flat(bounded, sah)
};
AccelCosts accel_costs(const Scene& scene, const PackedScene* packed = nullptr);

// The flat loop's order kind by kind (shaders/bvh.glsl, HAS_FLAT_ORDER; for a scene of at
// most kFlatOrderMax primitives): every primitive's index, grouped as kFlatGroups says (an
// analytic primitive by its shape's kind, a triangle in the last group), in leaf order
// within a group; group g ends at end[g]. Empty for a larger scene (or a pack_values).
struct FlatOrder {
  std::vector<int> prims;
  std::array<int, kFlatGroups> end{};
};
FlatOrder flat_order(const Scene& scene, const PackedScene& p);
// An edit that moved or resized shape `shape` in place: its primitive record is written
// again and the boxes of the BVH nodes above it recomputed up to the root
// (the tree stays: it may bound less tightly than a new build, never wrongly). Analytic
// shapes and lone triangles only: false, changing nothing, for a mesh instance or a
// triangle that became degenerate (or stopped being), which need pack_scene. The indices
// of the primitive and node records it changed are appended to the lists (for the upload).
// The shape, material and light records are not touched: Renderer::update_geometry packs
// those from the scene (update_values), so they go stale in `p`.
bool refit_shape(const Scene& scene, PackedScene& p, int shape, std::vector<int>& prims, std::vector<int>& nodes);

// The shape of each light record, in record order: the emitters that pack_shapes makes
// lights of (sampled by next-event estimation: sampled_light_shapes), then -1 - the kind
// of each punctual light (Scene::punctual).
std::vector<int> light_shapes(const Scene& scene);

// Only the shape, material and light records (no BVH, primitives or vertices): what an
// edit of values - materials, emission - changes (Renderer::update_values).
PackedScene pack_values(const Scene& scene);

// pack_scene in slices, so that a page packs a large scene a few milliseconds at a time
// while the previous one keeps rendering: run(work) does at most about `work` units (one
// unit: one vertex, triangle, BVH primitive visit, record) and returns true when the
// scene is packed. The result does not depend on the slicing. `scene` must outlive it.
class PackJob {
 public:
  explicit PackJob(const Scene& scene);
  PackJob(const PackJob&) = delete;  // its BvhBuilder refers to boxes_
  PackJob& operator=(const PackJob&) = delete;
  bool run(long work);
  bool done() const { return stage_ == Stage::Done; }
  const char* stage() const;  // what it is doing, for a progress line
  double progress() const;    // 0..1, by the stages' typical shares of the time
  PackedScene take();         // once done()
  const std::vector<Aabb>& boxes() const { return boxes_; }  // the BVH's input (tests)

 private:
  enum class Stage { Boxes, Bvh, Prims, Nodes, Done };
  // What one BVH primitive is: an analytic shape, or triangle `tri` of a shape (a lone
  // Triangle has tri 0).
  struct PrimRef {
    int shape;
    int tri;  // -1: analytic
  };
  void boxes_step(long& work);
  void prims_step(long& work);
  void nodes_step(long& work);

  const Scene& scene_;
  PackedScene p_;
  Stage stage_ = Stage::Boxes;
  // Bounded primitives and their boxes; unbounded shapes go first in the primitive list.
  std::vector<PrimRef> refs_;
  std::vector<Aabb> boxes_;
  std::vector<int> vertex_base_;
  // Each mesh instance's vertices in world space, transformed once: the boxes and the
  // primitives written after the build both read them.
  std::vector<std::vector<glm::vec3>> world_;
  size_t shape_ = 0;  // Boxes: the shape in progress,
  int pass_ = 0;      // its pass (a mesh: vertex attributes, world positions, triangles)
  size_t at_ = 0;     // and the next item of that pass; Prims and Nodes: the next record
  long box_work_ = 0, box_done_ = 0;
  std::unique_ptr<BvhBuilder> builder_;
  Bvh bvh_;
  // Motion blur (only for a scene with a moving bounded shape): each shape's velocity,
  // each BVH input box's moving shape (-1: none; see sweep_bvh) and each node's.
  std::vector<glm::vec3> velocity_;
  std::vector<int> mover_, node_mover_;
  void init_motion(size_t prims);
  void add_box(int shape, const Aabb& at0, const Aabb& all_times);
};

// World-space vertices of a mesh instance's triangle.
void mesh_triangle(const Scene& scene, const Shape& s, size_t tri, glm::vec3 out[3]);

}  // namespace pt
