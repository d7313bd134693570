// What every material kind's stem is written against (materials/<kind>.h):
//  - MaterialParse: its element's attributes (strict: core/xml_attrs.h), the tint of the
//    enclosing Attenuate colours and the loader's services for what nests or is a file;
//  - PT_KIND_RECORD: its record fields, laid out over the material record's payload
//    slots (core/records.h) in the order listed; the shader generator emits the GLSL
//    struct <Kind>Rec and <glsl>_rec(MaterialRec) from the same list;
//  - MaterialWriter: where its pack() writes them (and the header's tint);
//  - Common: the parts of a material that are not its kind's: the Attenuate tint and the
//    emission, which a kind's panel fields may edit.
// A stem declares, as static members: kXml (its element), kHasChildren (it takes child
// elements, which its parse reads), kNeeds (other kinds whose GLSL
// functions its own calls, so the generator includes their snippets and dispatch),
// kResolvesAtHit (its GLSL defines resolve_hit_<glsl>(inout Surface, Ray, Hit): it turns
// into what shades at the hit, e.g. a texture into a Diffuse record) and kComposite (it
// defines choose_<glsl>: it picks one of its children, surface.glsl).
#pragma once
#include <cstring>
#include <initializer_list>
#include <type_traits>

#include <glm/glm.hpp>

#include "core/records.h"
#include "core/xml_attrs.h"
#include "materials/kinds.h"

namespace tinyxml2 {
class XMLElement;
}

namespace pt {

// Composite kinds nest at most this deep: the shader resolves them in a loop of this many
// levels (GLSL has no recursion), and a deeper one would never scatter.
inline constexpr int kMaxCompositeDepth = 4;

// What a kind's parse may ask of the scene loader.
class MaterialLoader {
 public:
  virtual ~MaterialLoader() = default;
  // Parses material element `e` (a kind's child), with the given enclosing tint; returns
  // its index in the scene's material list.
  virtual int child(const tinyxml2::XMLElement* e, glm::vec3 tint) = 0;
  // The image map named by attribute `attr` of `a` (-1 when absent): loaded once per
  // scene and decoding, resolved against the scene file's folder; its index in the
  // scene's image list. A file that cannot be read fails with its name and line.
  virtual int image_map(XmlAttrs& a, const char* attr, bool normal) = 0;
  // FresnelComposites enclosing the element being parsed.
  virtual int composite_depth() const = 0;
};

// The parts of a material every kind has.
struct MaterialCommon {
  glm::vec3 tint{1.0f};      // the product of the enclosing <Attenuate> colours
  glm::vec3 emission{0.0f};  // radiance: <Emit> (with Absorb, or around this material)
};

struct MaterialParse {
  XmlAttrs& attrs;
  const tinyxml2::XMLElement* element;
  MaterialCommon& common;  // tint: the enclosing Attenuate colours (set); emission (Emit sets it)
  MaterialLoader& loader;
};

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

// Inside a kind's struct: PT_KIND_RECORD(PT_METAL_FIELDS, PT_NO_FIELDS) with
// #define PT_METAL_FIELDS(F) F(float, roughness) F(float, sampling) ...; the second list
// holds the hit fields. Gives rec::<name> (a field's index: a scoped enum, so a field may
// share a name with a parameter), kFields and kNumFields.
#define PT_NO_FIELDS(F)
#define PT_KIND_FIELD_ENUM(t, n) n,
#define PT_KIND_FIELD_INFO(t, n) {#t, #n, ::pt::glsl_width(#t), false},
#define PT_KIND_HIT_INFO(t, n) {#t, #n, ::pt::glsl_width(#t), true},
#define PT_KIND_RECORD(stored, hit)                                                            \
  enum class rec : int { stored(PT_KIND_FIELD_ENUM) hit(PT_KIND_FIELD_ENUM) kCount };            \
  static constexpr ::pt::KindField kFields[] = {stored(PT_KIND_FIELD_INFO) hit(PT_KIND_HIT_INFO){nullptr, nullptr, 0, false}}; \
  static constexpr int kNumFields = int(rec::kCount);

// Writes one material record: the header's tint and the kind's fields by index.
class MaterialWriter {
 public:
  MaterialWriter(RecordBuffer& b, int record, const KindField* fields) : b_(b), i_(record), fields_(fields) {}
  glm::vec3 tint{1.0f};  // starts as the Attenuate tint; a kind multiplies its own colour in
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
  void slot(int field, int width, float v, int comp = 0);
  RecordBuffer& b_;
  int i_;
  const KindField* fields_;
};

// A kind's edit(): true when any of its panel fields changed. Every field is drawn (the
// list evaluates each one), unlike a chain of ||.
inline bool any_changed(std::initializer_list<bool> changed) {
  for (bool c : changed)
    if (c) return true;
  return false;
}

// Defaults of the static members a stem may leave out.
template <class K, class = void>
struct KindNeeds : std::integral_constant<unsigned, 0> {};
template <class K>
struct KindNeeds<K, std::void_t<decltype(K::kNeeds)>> : std::integral_constant<unsigned, K::kNeeds> {};
template <class K, class = void>
struct KindResolvesAtHit : std::false_type {};
template <class K>
struct KindResolvesAtHit<K, std::void_t<decltype(K::kResolvesAtHit)>> : std::bool_constant<K::kResolvesAtHit> {};
template <class K, class = void>
struct KindHasChildren : std::false_type {};
template <class K>
struct KindHasChildren<K, std::void_t<decltype(K::kHasChildren)>> : std::bool_constant<K::kHasChildren> {};
template <class K, class = void>
struct KindComposite : std::false_type {};
template <class K>
struct KindComposite<K, std::void_t<decltype(K::kComposite)>> : std::bool_constant<K::kComposite> {};

// An index of refraction: in [kMinIor, kMaxMagnitude] (material.cpp says why).
inline constexpr float kMinIor = 1e-9f;
float parse_ior(XmlAttrs& a, const char* name, float fallback);

}  // namespace pt
