// What a kind's stem (materials/<kind>.h, shapes/<kind>.h) uses to declare its record
// fields and write them: the fields are laid out, in the order the kind lists them, over
// the payload slots of its record (core/records.h: a material record's p0..p8, a shape
// record's q0..q12); the shader generator emits the GLSL struct <Type>Rec and
// <glsl>_rec(<Record>Rec) from the same list, so no two kinds share a slot by hand and
// the packer and the shader cannot disagree. Also the variant of a kind list.
#pragma once
#include <cassert>
#include <variant>

#include <glm/glm.hpp>

#include "core/records.h"

namespace pt {

// A record field of a kind: its GLSL type and name; hit fields are filled by the shader
// at the hit (never packed).
struct KindField {
  const char* type;
  const char* name;
  int width;
  bool hit;
};

constexpr int kind_slot(const KindField* f, int i) {
  int s = 0;
  for (int k = 0; k < i; ++k) s += f[k].width;
  return s;
}

// The width of a kind's stored (packed) fields, in slots.
template <class K>
constexpr int stored_width() {
  int w = 0;
  for (int i = 0; i < K::kNumFields; ++i) w += K::kFields[i].hit ? 0 : K::kFields[i].width;
  return w;
}

// Inside a kind's struct: PT_KIND_RECORD(PT_METAL_FIELDS, PT_NO_FIELDS) with
// #define PT_METAL_FIELDS(F) F(float, roughness) F(float, sampling) ...; the second list
// holds the hit fields (materials only). Gives rec::<name> (a field's index: a scoped
// enum, so a field may share a name with a parameter), kFields and kNumFields.
#define PT_NO_FIELDS(F)
#define PT_KIND_FIELD_ENUM(t, n) n,
#define PT_KIND_FIELD_INFO(t, n) {#t, #n, ::pt::glsl_width(#t), false},
#define PT_KIND_HIT_INFO(t, n) {#t, #n, ::pt::glsl_width(#t), true},
#define PT_KIND_RECORD(stored, hit)                                                            \
  enum class rec : int { stored(PT_KIND_FIELD_ENUM) hit(PT_KIND_FIELD_ENUM) kCount };            \
  static constexpr ::pt::KindField kFields[] = {stored(PT_KIND_FIELD_INFO) hit(PT_KIND_HIT_INFO){nullptr, nullptr, 0, false}}; \
  static constexpr int kNumFields = int(rec::kCount);

// The payload slots of a record, in slot order (each a one-float Field).
struct PayloadSlots {
  const Field* const* slot;
  int count;
};

// Writes a kind's fields by index into record `record` of `b`, over the given slots.
class KindWriter {
 public:
  KindWriter(RecordBuffer& b, int record, const KindField* fields, PayloadSlots slots)
      : b_(b), i_(record), fields_(fields), slots_(slots) {}
  int record() const { return i_; }  // the record's index (a material's in the scene's list)
  // `field`: a kind's rec::<name>.
  template <class Field>
  void set(Field field, float v) { slot(int(field), 1, v); }
  template <class Field>
  void set(Field field, int v) { slot(int(field), 1, float(v)); }
  template <class Field>
  void set(Field field, glm::vec2 v) {
    slot(int(field), 2, v.x);
    slot(int(field), 2, v.y, 1);
  }
  template <class Field>
  void set(Field field, glm::vec3 v) {
    slot(int(field), 3, v.x);
    slot(int(field), 3, v.y, 1);
    slot(int(field), 3, v.z, 2);
  }

 private:
  void slot(int field, int width, float v, int comp = 0) {
    assert(fields_[field].width == width && !fields_[field].hit);
    (void)width;
    const int s = kind_slot(fields_, field) + comp;
    assert(s < slots_.count);
    b_.set(i_, *slots_.slot[s], v);
  }
  RecordBuffer& b_;
  int i_;
  const KindField* fields_;
  PayloadSlots slots_;
};

// std::variant<A, B, ...> of a kind list written as KindVariant<X(A) X(B) ... ListEnd>,
// where each X expands to "Type," (a macro list cannot drop its last comma; ListEnd
// takes it and is not an alternative).
struct ListEnd;
template <class... T>
struct TypeList {};
template <class Done, class... Rest>
struct KindVariantOf;
template <class... Done>
struct KindVariantOf<TypeList<Done...>, ListEnd> {
  using type = std::variant<Done...>;
};
template <class... Done, class H, class... Rest>
struct KindVariantOf<TypeList<Done...>, H, Rest...> : KindVariantOf<TypeList<Done..., H>, Rest...> {};
template <class... T>
using KindVariant = typename KindVariantOf<TypeList<>, T...>::type;

}  // namespace pt
