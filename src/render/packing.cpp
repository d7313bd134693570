#include "render/packing.h"

#include <climits>
#include <chrono>
#include <optional>
#include <variant>

#include "core/error.h"
#include "render/light_select.h"
#include "shadergen/shadergen.h"
#include "shapes/triangle.h"

namespace pt {
namespace {

// The header every material has, and the kind's own fields (materials/<kind>.h: pack).
void pack_materials(const Scene& scene, PackedScene& p) {
  for (const Material& m : scene.materials) {
    const int i = p.materials.add();
    p.materials.set(i, material_rec::kind, int(m.kind()));
    std::visit(
        [&](const auto& k) {
          MaterialWriter w(p.materials, i, k.kFields);
          w.tint = m.tint;
          k.pack(w);
          p.materials.set(i, material_rec::tint, w.tint);
        },
        m.params);
    p.materials.set(i, material_rec::emission, m.emission);
  }
}

// Emitters of samplable kinds become lights for next-event estimation, then the punctual
// lights (render/light_select.h: their records and the selection by power).
void pack_shapes(const Scene& scene, PackedScene& p) {
  const std::vector<int> lights = sampled_light_shapes(scene);
  pack_lights(scene, lights, p.lights, p.seal_lo, p.seal_hi);
  std::vector<int> light_of(scene.shapes.size(), -1);
  for (size_t k = 0; k < lights.size(); ++k) light_of[size_t(lights[k])] = int(k);
  for (const Shape& s : scene.shapes) {
    namespace f = shape_rec;
    const int i = p.shapes.add();
    p.shapes.set(i, f::kind, int(s.kind()));
    p.shapes.set(i, f::material, s.material);
    p.shapes.set(i, f::light, light_of[size_t(i)]);
    pack_shape(s.params, p.shapes, i, {f::kPayload, f::kPayloadSlots});  // the kind's own fields
  }
}

// An analytic shape's primitive: its kind and a copy of its record's fields (what
// intersect_<kind> reads).
void write_analytic_prim(PackedScene& p, int k, const Shape& s, int shape) {
  p.prims.set(k, prim_rec::tag, -1 - shape);
  p.prims.set(k, prim_rec::kind, int(s.kind()));
  pack_shape(s.params, p.prims, k, {prim_rec::kAnalytic, prim_rec::kAnalyticSlots});
}

void pack_analytic_prim(PackedScene& p, const Shape& s, int shape) { write_analytic_prim(p, p.prims.add(), s, shape); }

// The box the BVH holds for an analytic shape: its kind's bounds (a moving one's over
// the motion's times), padded.
Aabb analytic_box(const Shape& s, float motion_bound) {
  const ShapeBounds k = bounds(s.params, ShapeContext{nullptr, motion_bound});
  Aabb b;
  b.grow(k.lo);
  b.grow(k.hi);
  return b.padded();
}

// A lone triangle's vertices (a Mesh's come from its mesh).
void triangle_vertices(const Shape& s, glm::vec3 v[3]) { shape_vertices(s.params, v); }

// `moving`: its shape has a velocity (motion blur; triangle.glsl: prim_offset).
void write_triangle_prim(PackedScene& p, int k, int tag, const glm::vec3 v[3], glm::vec3 attr, bool moving) {
  p.prims.set(k, prim_rec::tag, tag);
  if (moving) p.prims.set(k, prim_rec::extra, 1.0f);
  p.prims.set(k, prim_rec::kind, triangle_edge_order(v[0], v[1], v[2]));
  p.prims.set(k, prim_rec::v0, v[0]);
  p.prims.set(k, prim_rec::v1, v[1]);
  p.prims.set(k, prim_rec::v2, v[2]);
  p.prims.set(k, prim_rec::attr, attr);
}

bool degenerate(const glm::vec3 v[3]) { return !(glm::length(glm::cross(v[1] - v[0], v[2] - v[0])) > 0.0f); }

// A triangle primitive's box, padded; a moving one's: the union of its boxes at times 0
// and motion_bound (what a translation sweeps, exactly).
Aabb triangle_box(const glm::vec3 v[3], glm::vec3 velocity, float motion_bound) {
  Aabb b;
  for (int i = 0; i < 6; ++i)
    if (i < 3 || velocity != glm::vec3(0.0f)) b.grow(i < 3 ? v[i] : v[i - 3] + velocity * motion_bound);
  return b.padded();
}

}  // namespace

void mesh_triangle(const Scene& scene, const Shape& s, size_t tri, glm::vec3 out[3]) {
  const Mesh& mesh = *s.as<Mesh>();
  const Triangle t = mesh.triangle(*scene.meshes[size_t(mesh.mesh)], tri);
  out[0] = t.v0, out[1] = t.v1, out[2] = t.v2;
}

std::vector<int> light_shapes(const Scene& scene) {
  std::vector<int> out = sampled_light_shapes(scene);
  for (const PunctualLight& l : scene.punctual) out.push_back(-1 - int(l.kind()));
  return out;
}

PackJob::PackJob(const Scene& scene) : scene_(scene), vertex_base_(scene.shapes.size(), -1), world_(scene.shapes.size()) {
  pack_shapes(scene, p_);
  pack_materials(scene, p_);
  p_.light_shape = light_shapes(scene);
  p_.shape_prim.assign(scene.shapes.size(), -1);
  p_.motion_bound = std::max(1.0f, scene.camera.shutter);
  size_t prims = 0;
  for (const Shape& s : scene.shapes) {
    if (info(s.kind()).bvh != BvhRole::Instanced) {
      ++box_work_;
      ++prims;
      continue;
    }
    const MeshData& m = *scene.meshes[size_t(s.as<Mesh>()->mesh)];
    const bool attributes = !m.normals.empty() || !m.uvs.empty() || !m.uvs1.empty() || !m.colors.empty();
    box_work_ += long(m.positions.size()) * (attributes ? 2 : 1) + long(m.triangles.size());
    prims += m.triangles.size();
  }
  // Allocated once: growing them by doubling copied tens of MB in one slice.
  refs_.reserve(prims);
  boxes_.reserve(prims);
  init_motion(prims);  // packing_motion.cpp
}

const char* PackJob::stage() const {
  switch (stage_) {
    case Stage::Boxes: return "transforming, bounding";
    case Stage::Bvh: return "building the BVH";
    case Stage::Prims: return "writing primitives";
    case Stage::Nodes: return "writing BVH nodes";
    case Stage::Done: break;
  }
  return "packed";
}

double PackJob::progress() const {
  // Shares of the time measured for a 1.3-million-triangle mesh (docs/benchmarks.md).
  constexpr double kBoxes = 0.2, kBvh = 0.65, kPrims = 0.1;
  switch (stage_) {
    case Stage::Boxes: return kBoxes * double(box_done_) / double(std::max(1L, box_work_));
    case Stage::Bvh: return kBoxes + kBvh * builder_->progress();
    case Stage::Prims: return kBoxes + kBvh + kPrims * double(at_) / double(std::max<size_t>(1, bvh_.order.size()));
    case Stage::Nodes: return kBoxes + kBvh + kPrims + (1.0 - kBoxes - kBvh - kPrims) * double(at_) / double(std::max<size_t>(1, bvh_.nodes.size()));
    case Stage::Done: break;
  }
  return 1.0;
}

bool PackJob::run(long work) {
  while (work > 0 && stage_ != Stage::Done) {
    switch (stage_) {
      case Stage::Boxes: {
        boxes_step(work);
        if (shape_ < scene_.shapes.size()) break;
        // Indices travel as floats: exact up to 2^24.
        if (refs_.size() + size_t(p_.unbounded) >= (1u << 24) || scene_.shapes.size() >= (1u << 24) || p_.vertices.count() >= (1 << 24))
          throw InputError(scene_.path, 0, "the scene has more than 16,777,216 primitives, shapes or mesh vertices");
        BvhBuildOptions opt;
        opt.max_depth = kBvhStackSize + 1;
        builder_ = std::make_unique<BvhBuilder>(boxes_, opt);
        stage_ = Stage::Bvh;
        break;
      }
      case Stage::Bvh: {
        const auto t0 = std::chrono::steady_clock::now();
        const long before = builder_->work_done();
        const bool built = builder_->run(work);
        p_.bvh_build_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        work -= builder_->work_done() - before;
        if (!built) break;
        bvh_ = builder_->take();
        builder_.reset();
        if (!velocity_.empty()) node_mover_ = sweep_bvh(bvh_, boxes_, mover_, velocity_, p_.motion_bound);
        p_.bvh_depth = bvh_.depth;
        p_.bvh_sah_cost = bvh_.sah_cost();
        p_.prims.reserve(p_.unbounded + int(refs_.size()));
        p_.prim_leaf.assign(size_t(p_.unbounded) + refs_.size(), -1);
        p_.prim_shape.reserve(p_.prim_leaf.size());
        at_ = 0;
        stage_ = Stage::Prims;
        break;
      }
      case Stage::Prims: {
        prims_step(work);
        if (at_ < bvh_.order.size()) break;
        p_.nodes.reserve(int(bvh_.nodes.size()));
        p_.node_parent.assign(bvh_.nodes.size(), -1);
        p_.node_first.reserve(bvh_.nodes.size());
        p_.node_count.reserve(bvh_.nodes.size());
        at_ = 0;
        stage_ = Stage::Nodes;
        break;
      }
      case Stage::Nodes: {
        nodes_step(work);
        if (at_ == bvh_.nodes.size()) stage_ = Stage::Done;
        break;
      }
      case Stage::Done: break;
    }
  }
  return stage_ == Stage::Done;
}

void PackJob::boxes_step(long& work) {
  for (; shape_ < scene_.shapes.size() && work > 0; ++shape_, pass_ = 0, at_ = 0) {
    const Shape& s = scene_.shapes[shape_];
    const int i = int(shape_);
    if (info(s.kind()).bvh != BvhRole::Instanced) {
      --work;
      ++box_done_;
      switch (info(s.kind()).bvh) {
        case BvhRole::Unbounded: {
          p_.shape_prim[shape_] = p_.prims.count();
          p_.prim_shape.push_back(i);
          pack_analytic_prim(p_, s, i);
          ++p_.unbounded;
          break;
        }
        case BvhRole::Analytic: {
          refs_.push_back({i, -1});
          add_box(i, analytic_box(s, 0.0f), analytic_box(s, p_.motion_bound));
          break;
        }
        case BvhRole::Triangles: {  // a lone Triangle
          glm::vec3 v[3];
          triangle_vertices(s, v);
          if (degenerate(v)) break;
          refs_.push_back({i, 0});
          add_box(i, triangle_box(v, velocity(s.params), 0.0f), triangle_box(v, velocity(s.params), p_.motion_bound));
          break;
        }
        case BvhRole::Instanced:  // handled below
        case BvhRole::None: break;
      }
      continue;
    }
    // A mesh instance, in three passes that each stop where the work runs out.
    const glm::mat4& transform = s.as<Mesh>()->transform;
    const MeshData& m = *scene_.meshes[size_t(s.as<Mesh>()->mesh)];
    const auto chunk = [&](size_t total) {
      const size_t end = at_ + size_t(std::min<long>(long(total - at_), work));
      work -= long(end - at_);
      box_done_ += long(end - at_);
      return end;
    };
    if (pass_ == 0) {
      if (!m.normals.empty() || !m.uvs.empty() || !m.uvs1.empty() || !m.colors.empty()) {
        // World-space shading normals (inverse transpose), uv, uv1 and colour, one record per vertex.
        if (at_ == 0) {
          vertex_base_[shape_] = p_.vertices.count();
          p_.vertices.reserve(p_.vertices.count() + int(m.positions.size()));
        }
        const glm::mat3 nm = glm::transpose(glm::inverse(glm::mat3(transform)));
        for (const size_t end = chunk(m.positions.size()); at_ < end; ++at_) {
          const int k = p_.vertices.add();
          if (!m.normals.empty()) {
            const glm::vec3 n = nm * m.normals[at_];
            const float len = glm::length(n);
            if (len > 0.0f && std::isfinite(len)) p_.vertices.set(k, vertex_rec::normal, n / len);
          }
          if (!m.uvs.empty()) {
            p_.vertices.set(k, vertex_rec::u, m.uvs[at_].x);
            p_.vertices.set(k, vertex_rec::v, m.uvs[at_].y);
          }
          const glm::vec2 uv1 = !m.uvs1.empty() ? m.uvs1[at_] : !m.uvs.empty() ? m.uvs[at_] : glm::vec2(0.0f);
          p_.vertices.set(k, vertex_rec::u1, uv1.x);
          p_.vertices.set(k, vertex_rec::v1, uv1.y);
          const glm::vec4 c = m.colors.empty() ? glm::vec4(1.0f) : m.colors[at_];
          p_.vertices.set(k, vertex_rec::color, glm::vec3(c));
          p_.vertices.set(k, vertex_rec::alpha, c.w);
        }
        if (at_ < m.positions.size()) return;
      }
      pass_ = 1;
      at_ = 0;
    }
    std::vector<glm::vec3>& w = world_[shape_];
    if (pass_ == 1) {
      if (at_ == 0) w.reserve(m.positions.size());
      for (const size_t end = chunk(m.positions.size()); at_ < end; ++at_) w.emplace_back(transform * glm::vec4(m.positions[at_], 1.0f));
      if (at_ < m.positions.size()) return;
      pass_ = 2;
      at_ = 0;
    }
    for (const size_t end = chunk(m.triangles.size()); at_ < end; ++at_) {
      const glm::uvec3 tri = m.triangles[at_];
      const glm::vec3 v[3] = {w[tri.x], w[tri.y], w[tri.z]};
      if (degenerate(v)) continue;
      refs_.push_back({i, int(at_)});
      add_box(i, triangle_box(v, glm::vec3(0.0f), 0.0f), triangle_box(v, s.as<Mesh>()->velocity, p_.motion_bound));
    }
    if (at_ < m.triangles.size()) return;
  }
}

void PackJob::prims_step(long& work) {
  for (const size_t end = at_ + size_t(std::min<long>(long(bvh_.order.size() - at_), work)); at_ < end; ++at_, --work) {
    const PrimRef& ref = refs_[size_t(bvh_.order[at_])];
    const Shape& s = scene_.shapes[size_t(ref.shape)];
    if (info(s.kind()).bvh != BvhRole::Instanced) p_.shape_prim[size_t(ref.shape)] = p_.prims.count();  // analytic, or a lone triangle
    p_.prim_shape.push_back(ref.shape);
    if (ref.tri < 0) {
      pack_analytic_prim(p_, s, ref.shape);
      continue;
    }
    const int k = p_.prims.add();
    glm::vec3 v[3];
    triangle_vertices(s, v);
    glm::vec3 attr(-1.0f);
    if (const Mesh* mesh = s.as<Mesh>()) {
      const glm::uvec3 tri = scene_.meshes[size_t(mesh->mesh)]->triangles[size_t(ref.tri)];
      const std::vector<glm::vec3>& w = world_[size_t(ref.shape)];
      v[0] = w[tri.x];
      v[1] = w[tri.y];
      v[2] = w[tri.z];
      if (vertex_base_[size_t(ref.shape)] >= 0) attr = glm::vec3(tri) + float(vertex_base_[size_t(ref.shape)]);
    }
    write_triangle_prim(p_, k, ref.shape, v, attr, velocity(s.params) != glm::vec3(0.0f));
  }
}

void PackJob::nodes_step(long& work) {
  for (const size_t end = at_ + size_t(std::min<long>(long(bvh_.nodes.size() - at_), work)); at_ < end; ++at_, --work) {
    const BvhNode& n = bvh_.nodes[at_];
    const int k = p_.nodes.add();
    const int first = n.count > 0 ? n.first + p_.unbounded : n.first;
    const int count = n.count + (node_mover_.empty() ? 0 : 32 * (node_mover_[at_] + 1));  // packing.h: node_mover
    p_.nodes.set(k, node_rec::lo, n.box.lo);
    p_.nodes.set(k, node_rec::hi, n.box.hi);
    p_.nodes.set(k, node_rec::first, first);
    p_.nodes.set(k, node_rec::count, count);
    p_.node_first.push_back(first);
    p_.node_count.push_back(count);
    if (n.count > 0)
      for (int q = first; q < first + n.count; ++q) p_.prim_leaf[size_t(q)] = k;
    else
      p_.node_parent[size_t(first)] = p_.node_parent[size_t(first) + 1] = k;
  }
}

PackedScene PackJob::take() {
  world_.clear();
  return std::move(p_);
}

bool refit_shape(const Scene& scene, PackedScene& p, int shape, std::vector<int>& prims, std::vector<int>& nodes) {
  const Shape& s = scene.shapes[size_t(shape)];
  const BvhRole role = info(s.kind()).bvh;
  if (role == BvhRole::Instanced || role == BvhRole::None) return false;
  if (p.shape_prim.size() != scene.shapes.size()) return false;  // not a pack_scene of this scene's shapes
  const int k = p.shape_prim[size_t(shape)];
  glm::vec3 v[3];
  triangle_vertices(s, v);
  if (role == BvhRole::Triangles && (k < 0) != degenerate(v)) return false;  // it enters or leaves the BVH
  if (k < 0) return true;  // a degenerate triangle that stays one: nothing to draw
  if (role == BvhRole::Triangles) write_triangle_prim(p, k, shape, v, glm::vec3(-1.0f), velocity(s.params) != glm::vec3(0.0f));
  else write_analytic_prim(p, k, s, shape);
  prims.push_back(k);
  if (role == BvhRole::Unbounded) return true;  // planes are outside the BVH
  // The leaf's box from its primitives, then each ancestor's from its two children (a
  // node marked with a moving shape: at time 0; any other: over the shutter, sweep_bvh).
  auto prim_box = [&](int q, float until) {
    const Shape& of = scene.shapes[size_t(p.prim_shape[size_t(q)])];
    if (info(of.kind()).bvh == BvhRole::Analytic) return analytic_box(of, until);
    // A triangle primitive: its vertices as written, swept by its shape's motion.
    const glm::vec3 w[3] = {p.prims.get3(q, prim_rec::v0), p.prims.get3(q, prim_rec::v1), p.prims.get3(q, prim_rec::v2)};
    return triangle_box(w, velocity(of.params), until);
  };
  for (int n = p.prim_leaf[size_t(k)]; n >= 0; n = p.node_parent[size_t(n)]) {
    const int first = p.node_first[size_t(n)], count = node_prims(p.node_count[size_t(n)]);
    const int mover = node_mover(p.node_count[size_t(n)]);
    Aabb b;
    if (count > 0) {
      for (int q = first; q < first + count; ++q) b.grow(prim_box(q, mover >= 0 ? 0.0f : p.motion_bound));
    } else {
      for (int c : {first, first + 1}) {
        const Aabb cb{p.nodes.get3(c, node_rec::lo), p.nodes.get3(c, node_rec::hi)};
        const int m = node_mover(p.node_count[size_t(c)]);
        b.grow(m >= 0 && mover < 0 ? swept_box(cb, velocity(scene.shapes[size_t(m)].params), p.motion_bound) : cb);
      }
    }
    p.nodes.set(n, node_rec::lo, b.lo);
    p.nodes.set(n, node_rec::hi, b.hi);
    nodes.push_back(n);
  }
  return true;
}

PackedScene pack_values(const Scene& scene) {
  PackedScene p;
  pack_materials(scene, p);
  pack_shapes(scene, p);
  return p;
}

PackedScene pack_scene(const Scene& scene) {
  PackJob job(scene);
  while (!job.run(LONG_MAX)) {  // (long is 32 bits in wasm)
  }
  return job.take();
}

bool AccelCosts::flat() const { return auto_flat(bounded, sah); }

FlatOrder flat_order(const Scene& scene, const PackedScene& p) {
  FlatOrder o;
  if (p.prims.count() > kFlatOrderMax || p.prim_shape.size() != size_t(p.prims.count())) return o;
  for (int g = 0; g < kFlatGroups; ++g) {
    for (int q = 0; q < p.prims.count(); ++q) {
      const ShapeKind kind = scene.shapes[size_t(p.prim_shape[size_t(q)])].kind();
      const BvhRole role = info(kind).bvh;
      const bool analytic = role == BvhRole::Analytic || role == BvhRole::Unbounded;
      if ((analytic ? int(kind) : kNumShapeKinds) == g) o.prims.push_back(q);
    }
    o.end[size_t(g)] = int(o.prims.size());
  }
  return o;
}

AccelCosts accel_costs(const Scene& scene, const PackedScene* packed) {
  // The count from the scene first, so that the choice is the same with and without a
  // packing at hand (a packing drops degenerate triangles).
  AccelCosts c;
  c.bounded = scene_primitives(scene);
  for (const Shape& s : scene.shapes) c.bounded -= info(s.kind()).bvh == BvhRole::Unbounded;
  if (c.bounded > kFlatMaxConsidered) return c;
  std::optional<PackedScene> own;
  if (!packed) packed = &own.emplace(pack_scene(scene));  // a few dozen primitives: microseconds
  c.bounded = packed->prims.count() - packed->unbounded;
  c.sah = packed->bvh_sah_cost;
  return c;
}

}  // namespace pt
