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
// into what shades at the hit, e.g. a texture into a Diffuse record), kComposite (it
// defines choose_<glsl>: it picks one of its children, surface.glsl), kImageMaps (it reads
// the scene's image maps: the program gets the texture array and the shapes' surface uv),
// kEmissionAtHit (it defines emission_hit_<glsl>(inout Surface, Ray, Hit): its emission
// varies over the surface) and kCutsHits (it defines hit_present_<glsl>(MaterialRec,
// int prim, Ray, Hit): whether a candidate hit on a mesh triangle is a surface at all,
// asked by the traversal itself so that every ray, shadow rays too, sees the same
// surface; compiled only under HAS_HIT_CUTS, materials/features.h) and kMedium (it
// defines bool medium_<glsl>(MaterialRec, out vec3 sigma): where it returns true, its
// surface bounds a homogeneous medium of absorption coefficient sigma per unit length
// (asked before a kind resolved at the hit becomes its hit record), which a path that crosses into it
// travels in until it crosses out (Beer-Lambert; shaders/integrator.glsl); compiled only
// under HAS_MEDIA, which a kind's features() reports where a material absorbs).
#pragma once
#include <cstring>
#include <initializer_list>
#include <type_traits>

#include <glm/glm.hpp>

#include "core/kind_record.h"
#include "core/records.h"
#include "core/xml_attrs.h"
#include "materials/features.h"
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
  // The same for a map of linear values (no sRGB decoding: glTF's metallicRoughnessTexture).
  virtual int image_map_linear(XmlAttrs& a, const char* attr) = 0;
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

// Writes one material record: the header's tint and the kind's fields by index
// (core/kind_record.h) over the payload slots p0..p8.
class MaterialWriter : public KindWriter {
 public:
  MaterialWriter(RecordBuffer& b, int record, const KindField* fields)
      : KindWriter(b, record, fields, {material_rec::kPayload, material_rec::kPayloadSlots}) {}
  glm::vec3 tint{1.0f};  // starts as the Attenuate tint; a kind multiplies its own colour in
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
struct KindImageMaps : std::false_type {};
template <class K>
struct KindImageMaps<K, std::void_t<decltype(K::kImageMaps)>> : std::bool_constant<K::kImageMaps> {};
template <class K, class = void>
struct KindEmissionAtHit : std::false_type {};
template <class K>
struct KindEmissionAtHit<K, std::void_t<decltype(K::kEmissionAtHit)>> : std::bool_constant<K::kEmissionAtHit> {};
template <class K, class = void>
struct KindCutsHits : std::false_type {};
template <class K>
struct KindCutsHits<K, std::void_t<decltype(K::kCutsHits)>> : std::bool_constant<K::kCutsHits> {};
template <class K, class = void>
struct KindMedium : std::false_type {};
template <class K>
struct KindMedium<K, std::void_t<decltype(K::kMedium)>> : std::bool_constant<K::kMedium> {};
template <class K, class = void>
struct KindFurnace {
  static constexpr const char* value = nullptr;
};
template <class K>
struct KindFurnace<K, std::void_t<decltype(K::kFurnace)>> {
  static constexpr const char* value = K::kFurnace;
};
template <class K, class = void>
struct KindComposite : std::false_type {};
template <class K>
struct KindComposite<K, std::void_t<decltype(K::kComposite)>> : std::bool_constant<K::kComposite> {};

// An index of refraction: in [kMinIor, kMaxMagnitude] (material.cpp says why).
inline constexpr float kMinIor = 1e-9f;
float parse_ior(XmlAttrs& a, const char* name, float fallback);

}  // namespace pt
