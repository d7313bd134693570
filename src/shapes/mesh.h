// Mesh: <Mesh src="model.gltf|.glb|.obj|.json" | generate="icosphere" position=".."
// rotation=".." scale=".." [velocity="x y z" | end="x y z"]>: an instance of a triangle
// mesh (Scene::meshes[mesh], shared by its instances) placed by `transform` (object to
// world), the instance translated by velocity * t over the shutter (motion blur,
// extension; `end`: its `position` at time 1). Its element reads files, so the loader
// builds it (scene/xml_meshes.cpp). Its shape record holds the velocity; in the BVH each
// of its triangles is a primitive with world-space vertices (at time 0) inline,
// intersected by triangle.glsl (a moving instance's marked: the ray is translated by
// -velocity * t, the instance's translation applied to the ray instead of its
// triangles), bounded over the shutter; mesh.glsl interpolates its vertex attributes.
#pragma once
#include "shapes/shape.h"
#include "shapes/triangle.h"

namespace pt {

struct Mesh {
  static constexpr const char* kXml = "Mesh";
  static constexpr const char* kExample = "<Mesh generate=\"icosphere\" level=\"1\" scale=\"0.7\" position=\"0.1 0 -0.2\"/>";
  static constexpr const char* kUvArgs = "h.prim, ";  // its attributes hang off the primitive of the hit
  static constexpr bool kLoadedByLoader = true;
  static constexpr bool kShadingNormal = true;
  static constexpr unsigned kNeeds = shape_bit(ShapeKind::Triangle);  // its triangles are intersected by triangle.glsl  // mesh.glsl: shading_normal_mesh, its interpolated vertex normals
  int mesh = -1;
  glm::mat4 transform{1.0f};
  glm::vec3 velocity{0.0f};

#define PT_MESH_FIELDS(F) F(vec3, velocity)
  PT_KIND_RECORD(PT_MESH_FIELDS, PT_NO_FIELDS)
  void pack(ShapeWriter& w) const { w.set(rec::velocity, velocity); }
  // Triangle `tri` in world space (the packer's arithmetic: render/packing.h mesh_triangle).
  Triangle triangle(const MeshData& m, size_t tri) const {
    const glm::uvec3 t = m.triangles[tri];
    Triangle w;
    w.v0 = glm::vec3(transform * glm::vec4(m.positions[t[0]], 1.0f));
    w.v1 = glm::vec3(transform * glm::vec4(m.positions[t[1]], 1.0f));
    w.v2 = glm::vec3(transform * glm::vec4(m.positions[t[2]], 1.0f));
    return w;
  }
  ShapeBounds bounds(const ShapeContext& ctx) const {
    ShapeBounds b;
    for (const glm::vec3& p : (*ctx.meshes)[size_t(mesh)]->positions) b.grow(glm::vec3(transform * glm::vec4(p, 1.0f)));
    return swept(b, velocity, ctx.motion_bound);
  }
  // Every triangle (a click is rare; the BVH is the GPU's).
  template <class Q>
  void intersect(const Q& q, int id, Hit& h) const {
    const MeshData& m = *(*q.ctx.meshes)[size_t(mesh)];
    for (size_t t = 0; t < m.triangles.size(); ++t) intersect_triangle(triangle(m, t), id, q.r, q.triangle, h);
  }
  glm::vec3 position() const { return glm::vec3(transform[3]); }  // the instance's origin
  void move(glm::vec3 d) { transform[3] += glm::vec4(d, 0.0f); }  // the whole instance
  template <class E>
  bool edit(E&) { return false; }
};

}  // namespace pt
