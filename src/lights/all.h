// Every punctual light kind (lights/kinds.h) and the scene's punctual light: a
// std::variant of the kinds, with what the loader, the packer and the light selection
// ask of any of them.
#pragma once
#include <cstring>
#include <optional>
#include <variant>

#include "core/kind_record.h"
#include "lights/directional.h"
#include "lights/point.h"
#include "lights/spot.h"

namespace pt {

#define PT_X(e, g, x) e,
using LightParams = KindVariant<PT_LIGHT_KINDS(PT_X) ListEnd>;
#undef PT_X

struct PunctualLight {
  LightParams params{PointLight{}};
  int line = 0;  // scene-file line, for messages
  LightKind kind() const { return LightKind(params.index()); }
  template <class K>
  const K* as() const { return std::get_if<K>(&params); }
  void pack(RecordBuffer& b, int record) const {
    LightWriter w{b, record};
    std::visit([&](const auto& k) { k.pack(w); }, params);
  }
  float power(const LightContext& ctx) const {
    return std::visit([&](const auto& k) { return k.power(ctx); }, params);
  }
};

// The kind whose element is `name`, parsed strictly from `a`; nullopt when no light kind
// has that element.
inline std::optional<LightParams> parse_light_element(const char* name, XmlAttrs& a) {
  std::optional<LightParams> out;
  [&]<size_t... I>(std::index_sequence<I...>) {
    (([&] {
       using K = std::variant_alternative_t<I, LightParams>;
       if (out || std::strcmp(name, K::kXml) != 0) return;
       K k;
       k.parse(a);
       out = k;
     }()),
     ...);
  }(std::make_index_sequence<std::variant_size_v<LightParams>>{});
  return out;
}

}  // namespace pt
