#include "render/packing.h"

#include <chrono>

#include "render/image_maps.h"

#include "core/error.h"
#include "shapes/triangle.h"

namespace pt {
namespace {

void pack_materials(const Scene& scene, PackedScene& p) {
  for (const Material& m : scene.materials) {
    namespace f = material_rec;
    const int i = p.materials.add();
    p.materials.set(i, f::kind, int(m.kind));
    p.materials.set(i, f::roughness, m.glossiness);
    p.materials.set(i, f::sampling, m.montecarlo);
    p.materials.set(i, f::tint, m.tint);
    p.materials.set(i, f::ior_n, m.ior.x);
    p.materials.set(i, f::ior_k, m.ior.y);
    p.materials.set(i, f::emission, m.emission);
    p.materials.set(i, f::eta_outer, m.outer_ior);
    p.materials.set(i, f::eta_inner, m.inner_ior);
    p.materials.set(i, f::exponent, m.exponent);
    p.materials.set(i, f::child_a, m.child_a);
    p.materials.set(i, f::child_b, m.child_b);
    if (is_procedural_texture(m.kind)) {
      p.materials.set(i, f::color2, m.color2);  // aliases the dielectric fields (see records.h)
      p.materials.set(i, f::scale, m.scale);
    }
    if (m.kind == MaterialKind::Textured) pack_textured(p.materials, i, m);  // aliases too (see records.h)
  }
}

void pack_shapes(const Scene& scene, PackedScene& p) {
  for (const Shape& s : scene.shapes) {
    namespace f = shape_rec;
    const int i = p.shapes.add();
    p.shapes.set(i, f::kind, int(s.kind));
    p.shapes.set(i, f::material, s.material);
    // Emitters of samplable kinds become lights for next-event estimation.
    int light = -1;
    if (is_sampled_light(scene, s)) {
      light = p.lights.add();
      p.lights.set(light, light_rec::radiance, scene.materials[size_t(s.material)].emission);
      p.lights.set(light, light_rec::shape, i);
    }
    p.shapes.set(i, f::light, light);
    p.shapes.set(i, f::a, s.a);
    p.shapes.set(i, f::radius, s.radius);
    p.shapes.set(i, f::b, s.kind == ShapeKind::Sphere ? s.velocity : s.b);
    p.shapes.set(i, f::c, s.c);
  }
}

// What one BVH primitive is: an analytic shape, or triangle `tri` of a shape (a lone
// Triangle has tri 0).
struct PrimRef {
  int shape;
  int tri;  // -1: analytic
};

// An analytic shape's primitive: what intersect_<kind> reads of its shape record.
void pack_analytic_prim(PackedScene& p, const Shape& s, int shape) {
  const int k = p.prims.add();
  p.prims.set(k, prim_rec::tag, -1 - shape);
  p.prims.set(k, prim_rec::kind, int(s.kind));
  p.prims.set(k, prim_rec::v0, s.a);
  p.prims.set(k, prim_rec::v1, s.kind == ShapeKind::Sphere ? s.velocity : s.b);
  p.prims.set(k, prim_rec::radius, s.radius);
}

bool degenerate(const glm::vec3 v[3]) { return !(glm::length(glm::cross(v[1] - v[0], v[2] - v[0])) > 0.0f); }

}  // namespace

void mesh_triangle(const Scene& scene, const Shape& s, size_t tri, glm::vec3 out[3]) {
  const MeshData& m = *scene.meshes[size_t(s.mesh)];
  const glm::uvec3 t = m.triangles[tri];
  for (int k = 0; k < 3; ++k) out[k] = glm::vec3(s.transform * glm::vec4(m.positions[t[k]], 1.0f));
}

PackedScene pack_scene(const Scene& scene) {
  PackedScene p;
  pack_shapes(scene, p);
  pack_materials(scene, p);
  p.motion_bound = std::max(1.0f, scene.camera.shutter);

  // Bounded primitives and their boxes; unbounded shapes go first in the primitive list.
  std::vector<PrimRef> refs;
  std::vector<Aabb> boxes;
  std::vector<int> vertex_base(scene.shapes.size(), -1);
  // Each mesh instance's vertices in world space, transformed once: the boxes and the
  // primitives written after the build both read them.
  std::vector<std::vector<glm::vec3>> world(scene.shapes.size());
  for (size_t i = 0; i < scene.shapes.size(); ++i) {
    const Shape& s = scene.shapes[i];
    switch (info(s.kind).bvh) {
      case BvhRole::Unbounded: {
        pack_analytic_prim(p, s, int(i));
        ++p.unbounded;
        break;
      }
      case BvhRole::Analytic: {
        Aabb b;
        if (s.kind == ShapeKind::Sphere) {
          for (const glm::vec3 c : {s.a, s.a + s.velocity * p.motion_bound}) {
            b.grow(c - glm::vec3(s.radius));
            b.grow(c + glm::vec3(s.radius));
          }
        } else {
          b.grow(s.a);
          b.grow(s.b);
        }
        refs.push_back({int(i), -1});
        boxes.push_back(b.padded());
        break;
      }
      case BvhRole::Triangles: {
        if (s.kind == ShapeKind::Triangle) {
          const glm::vec3 v[3] = {s.a, s.b, s.c};
          if (degenerate(v)) break;
          Aabb b;
          for (const glm::vec3& q : v) b.grow(q);
          refs.push_back({int(i), 0});
          boxes.push_back(b.padded());
          break;
        }
        const MeshData& m = *scene.meshes[size_t(s.mesh)];
        if (!m.normals.empty() || !m.uvs.empty()) {
          // World-space shading normals (inverse transpose) and uv, one record per vertex.
          vertex_base[i] = p.vertices.count();
          const glm::mat3 nm = glm::transpose(glm::inverse(glm::mat3(s.transform)));
          p.vertices.reserve(p.vertices.count() + int(m.positions.size()));
          for (size_t v = 0; v < m.positions.size(); ++v) {
            const int k = p.vertices.add();
            if (!m.normals.empty()) {
              const glm::vec3 n = nm * m.normals[v];
              const float len = glm::length(n);
              if (len > 0.0f && std::isfinite(len)) p.vertices.set(k, vertex_rec::normal, n / len);
            }
            if (!m.uvs.empty()) {
              p.vertices.set(k, vertex_rec::u, m.uvs[v].x);
              p.vertices.set(k, vertex_rec::v, m.uvs[v].y);
            }
          }
        }
        std::vector<glm::vec3>& w = world[i];
        w.reserve(m.positions.size());
        for (const glm::vec3& q : m.positions) w.emplace_back(s.transform * glm::vec4(q, 1.0f));
        for (size_t t = 0; t < m.triangles.size(); ++t) {
          const glm::uvec3 tri = m.triangles[t];
          const glm::vec3 v[3] = {w[tri.x], w[tri.y], w[tri.z]};
          if (degenerate(v)) continue;
          Aabb b;
          for (const glm::vec3& q : v) b.grow(q);
          refs.push_back({int(i), int(t)});
          boxes.push_back(b.padded());
        }
        break;
      }
      case BvhRole::None: break;
    }
  }
  // Indices travel as floats: exact up to 2^24.
  if (refs.size() + size_t(p.unbounded) >= (1u << 24) || scene.shapes.size() >= (1u << 24) || p.vertices.count() >= (1 << 24))
    throw InputError(scene.path, 0, "the scene has more than 16,777,216 primitives, shapes or mesh vertices");

  const auto t0 = std::chrono::steady_clock::now();
  BvhBuildOptions opt;
  opt.max_depth = kBvhStackSize + 1;
  const Bvh bvh = build_bvh(boxes, opt);
  p.bvh_build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  p.bvh_depth = bvh.depth;

  p.prims.reserve(p.unbounded + int(refs.size()));
  for (int r : bvh.order) {
    const PrimRef& ref = refs[size_t(r)];
    const Shape& s = scene.shapes[size_t(ref.shape)];
    if (ref.tri < 0) {
      pack_analytic_prim(p, s, ref.shape);
      continue;
    }
    const int k = p.prims.add();
    glm::vec3 v[3] = {s.a, s.b, s.c};
    glm::vec3 attr(-1.0f);
    if (s.kind == ShapeKind::Mesh) {
      const glm::uvec3 tri = scene.meshes[size_t(s.mesh)]->triangles[size_t(ref.tri)];
      const std::vector<glm::vec3>& w = world[size_t(ref.shape)];
      v[0] = w[tri.x];
      v[1] = w[tri.y];
      v[2] = w[tri.z];
      if (vertex_base[size_t(ref.shape)] >= 0)
        attr = glm::vec3(tri) + float(vertex_base[size_t(ref.shape)]);
    }
    p.prims.set(k, prim_rec::tag, ref.shape);
    p.prims.set(k, prim_rec::kind, triangle_edge_order(v[0], v[1], v[2]));
    p.prims.set(k, prim_rec::v0, v[0]);
    p.prims.set(k, prim_rec::v1, v[1]);
    p.prims.set(k, prim_rec::v2, v[2]);
    p.prims.set(k, prim_rec::attr, attr);
  }
  p.nodes.reserve(int(bvh.nodes.size()));
  for (const BvhNode& n : bvh.nodes) {
    const int k = p.nodes.add();
    p.nodes.set(k, node_rec::lo, n.box.lo);
    p.nodes.set(k, node_rec::hi, n.box.hi);
    p.nodes.set(k, node_rec::first, n.count > 0 ? n.first + p.unbounded : n.first);
    p.nodes.set(k, node_rec::count, n.count);
  }
  return p;
}

}  // namespace pt
