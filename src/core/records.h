// The packed layouts of scene data in RGBA32F textures, declared once. The packer writes
// through these constants and the shader generator emits the GLSL struct and loader
// from the same lists, so the two sides cannot disagree.
//
//   F(glsl type, field, texel, first component)
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

// A shape: a header every kind shares (kind, material, light: its light record or -1)
// and thirteen payload floats q0..q12 that belong to the kind: each kind lays out its own
// fields over them in order (shapes/<kind>.h, PT_KIND_RECORD: core/kind_record.h).
#define PT_SHAPE_RECORD(F)                                                              \
  F(int, kind, 0, 0) F(int, material, 0, 1) F(int, light, 0, 2) F(float, q12, 0, 3)     \
  F(float, q0, 1, 0) F(float, q1, 1, 1) F(float, q2, 1, 2) F(float, q3, 1, 3)           \
  F(float, q4, 2, 0) F(float, q5, 2, 1) F(float, q6, 2, 2) F(float, q7, 2, 3)           \
  F(float, q8, 3, 0) F(float, q9, 3, 1) F(float, q10, 3, 2) F(float, q11, 3, 3)

// A material: a header every kind shares (kind, tint: the enclosing Attenuate colours
// times the kind's own colour, emission) and nine payload floats p0..p8 that belong to
// the kind: each kind lays out its own fields over them (materials/material.h,
// PT_KIND_RECORD), so no two kinds share a slot by hand. The GLSL struct has three more
// floats, p9..p11, that the kind may fill at the hit (its hit fields; zero when loaded).
#define PT_MATERIAL_RECORD(F)                                                          \
  F(int, kind, 0, 0) F(float, p0, 0, 1) F(float, p1, 0, 2) F(float, p2, 0, 3)           \
  F(vec3, tint, 1, 0) F(float, p3, 1, 3)                                                \
  F(vec3, emission, 2, 0) F(float, p4, 2, 3)                                            \
  F(float, p5, 3, 0) F(float, p6, 3, 1) F(float, p7, 3, 2) F(float, p8, 3, 3)

// Texture coordinates of a Triangle's vertices, one record per shape (indexed like the
// shape records), packed and bound only for scenes with a Textured material.
#define PT_UV_RECORD(F) \
  F(vec2, uv0, 0, 0) F(vec2, uv1, 0, 2) F(vec2, uv2, 1, 0)

// BVH node (accel/bvh.h): bounds; interior: first = index of the first of its two
// adjacent children, count = 0; leaf: first = its first primitive, count = how many.
#define PT_NODE_RECORD(F) \
  F(vec3, lo, 0, 0) F(int, first, 0, 3) \
  F(vec3, hi, 1, 0) F(int, count, 1, 3)

// A primitive of the BVH, in leaf order. tag >= 0: a triangle of shape `tag` (vertices
// in world space; kind = its edge-order bits, shapes/triangle.h; attr = the indices of its
// vertices in the vertex-attribute records, or -1 when the mesh has none); tag < 0: the
// analytic shape -1 - tag (sphere, box, or an unbounded plane), kind = its shape kind,
// with a copy of the first kAnalyticSlots payload slots of its shape record in v0, v1,
// v2, extra (prim_rec::kAnalytic), so the traversal never fetches the shape record.
#define PT_PRIM_RECORD(F) \
  F(vec3, v0, 0, 0) F(int, tag, 0, 3) \
  F(vec3, v1, 1, 0) F(int, kind, 1, 3) \
  F(vec3, v2, 2, 0) F(float, extra, 2, 3) \
  F(vec3, attr, 3, 0)

// Per-vertex attributes of mesh instances (world space): shading normal (0 when the mesh
// has none), uv (TEXCOORD_0), uv1 (glTF's TEXCOORD_1; uv when absent) and colour with
// alpha (glTF's COLOR_0; 1 when absent). Four texels: a record's texel count divides the
// row (three would straddle one); the fourth is free.
#define PT_VERTEX_RECORD(F) \
  F(vec3, normal, 0, 0) F(float, u, 0, 3) \
  F(float, v, 1, 0) F(float, u1, 1, 1) F(float, v1, 1, 2) F(float, alpha, 1, 3) \
  F(vec3, color, 2, 0)

// A light that next-event estimation samples: an emissive shape of a samplable kind
// (shape >= 0: its shape record, which holds the geometry; radiance: its emitted
// radiance) or a punctual light (shape = -1 - its LightKind, lights/light.h: radiance is
// colour x intensity, and the kind uses position, direction, range and the cone's
// cosines). pmf, alias_p and alias: the light selection's alias table (Walker/Vose,
// render/light_select.h): slot i is chosen uniformly, then kept with probability alias_p,
// else its alias is taken; pmf is the probability that a light is selected.
#define PT_LIGHT_RECORD(F) \
  F(vec3, radiance, 0, 0) F(int, shape, 0, 3) \
  F(vec3, position, 1, 0) F(float, range, 1, 3) \
  F(vec3, direction, 2, 0) F(float, cos_inner, 2, 3) \
  F(float, pmf, 3, 0) F(float, alias_p, 3, 1) F(int, alias, 3, 2) F(float, cos_outer, 3, 3)

namespace pt {

// Data textures are this many texels wide (a power of two: the shader addresses them
// with a mask and a shift); a record never straddles a row because every record's texel
// count divides it. Rows are limited by GL_MAX_TEXTURE_SIZE (queried by the renderer).
inline constexpr int kDataWidthLog2 = 12;
inline constexpr int kDataWidth = 1 << kDataWidthLog2;

struct Field {
  const char* type;
  const char* name;
  int texel;
  int comp;
  int width;
};

constexpr int glsl_width(const char* t) { return t[0] == 'v' ? t[3] - '0' : 1; }

struct RecordLayout {
  const char* name;  // GLSL: struct <Name>Rec, load_<name>(int), sampler u_<name>_data
  int texels;
  std::vector<Field> fields;
  std::vector<const char*> locals;  // GLSL-only float fields, zero when loaded
};

#define PT_FIELD_CONST(t, n, tex, comp) inline constexpr Field n{#t, #n, tex, comp, glsl_width(#t)};
#define PT_FIELD_REF(t, n, tex, comp) n,
// Every record kind: X(name, texels per record, its field list). Each gets a namespace
// <name>_rec of Field constants (the packer's side) and <name>_layout() (the generator's).
#define PT_RECORDS(X)                 \
  X(shape, 4, PT_SHAPE_RECORD)        \
  X(material, 4, PT_MATERIAL_RECORD)  \
  X(light, 4, PT_LIGHT_RECORD)        \
  X(node, 2, PT_NODE_RECORD)          \
  X(prim, 4, PT_PRIM_RECORD)          \
  X(vertex, 4, PT_VERTEX_RECORD)      \
  X(uv, 2, PT_UV_RECORD)

#define PT_RECORD_DECL(name, texels, fields) \
  namespace name##_rec {                     \
  inline constexpr int kTexels = texels;     \
  fields(PT_FIELD_CONST)                     \
  }                                          \
  const RecordLayout& name##_layout();
PT_RECORDS(PT_RECORD_DECL)
#undef PT_RECORD_DECL

namespace material_rec {
// The payload in slot order, and how many slots the GLSL struct has in all (p9..p11 are
// hit fields: never packed).
inline constexpr const Field* kPayload[] = {&p0, &p1, &p2, &p3, &p4, &p5, &p6, &p7, &p8};
inline constexpr int kPayloadSlots = 9;
inline constexpr int kGlslSlots = 12;
}  // namespace material_rec

namespace shape_rec {
inline constexpr const Field* kPayload[] = {&q0, &q1, &q2, &q3, &q4, &q5, &q6, &q7, &q8, &q9, &q10, &q11, &q12};
inline constexpr int kPayloadSlots = 13;
}  // namespace shape_rec

namespace prim_rec {
// Where an analytic primitive holds its shape's payload slots q0..q9, in slot order.
inline constexpr int kAnalyticSlots = 10;
inline constexpr Field kAnalyticField[kAnalyticSlots] = {
    {"float", "v0.x", 0, 0, 1}, {"float", "v0.y", 0, 1, 1}, {"float", "v0.z", 0, 2, 1}, {"float", "v1.x", 1, 0, 1},
    {"float", "v1.y", 1, 1, 1}, {"float", "v1.z", 1, 2, 1}, {"float", "v2.x", 2, 0, 1}, {"float", "v2.y", 2, 1, 1},
    {"float", "v2.z", 2, 2, 1}, {"float", "extra", 2, 3, 1}};
inline constexpr const Field* kAnalytic[kAnalyticSlots] = {&kAnalyticField[0], &kAnalyticField[1], &kAnalyticField[2],
                                                           &kAnalyticField[3], &kAnalyticField[4], &kAnalyticField[5],
                                                           &kAnalyticField[6], &kAnalyticField[7], &kAnalyticField[8],
                                                           &kAnalyticField[9]};
}  // namespace prim_rec

// The material record as the shader sees it: material_layout() and the hit slots.
const RecordLayout& material_glsl();

// GLSL for one layout: the struct, the sampler uniform and the loader function.
std::string glsl_record(const RecordLayout& layout);

// A growable array of records in texel order, ready to upload as kDataWidth x rows.
class RecordBuffer {
 public:
  explicit RecordBuffer(int texels_per_record) : texels_(texels_per_record) {}
  int add();  // appends a zeroed record, returns its index
  void reserve(int records) { data_.reserve(size_t(records) * texels_ * 4); }
  void set(int rec, const Field& f, float v);
  void set(int rec, const Field& f, glm::vec3 v);
  void set(int rec, const Field& f, glm::vec2 v);
  void set(int rec, const Field& f, int v) { set(rec, f, float(v)); }
  float get(int rec, const Field& f) const { return data_[(size_t(rec) * size_t(texels_) + size_t(f.texel)) * 4 + size_t(f.comp)]; }
  glm::vec3 get3(int rec, const Field& f) const {
    const float* p = &data_[(size_t(rec) * size_t(texels_) + size_t(f.texel)) * 4 + size_t(f.comp)];
    return glm::vec3(p[0], p[1], p[2]);
  }
  int count() const { return count_; }
  int texels_per_record() const { return texels_; }
  int rows() const;  // at least 1
  // Padded to rows() * kDataWidth texels of 4 floats.
  std::vector<float> texels() const;
  const std::vector<float>& raw() const { return data_; }  // count() records, not padded

 private:
  int texels_;
  int count_ = 0;
  std::vector<float> data_;
};

}  // namespace pt
