#include "shadergen/textured_gen.h"

#include <cctype>

#include "shapes/all.h"

namespace pt {

std::string glsl_textured_support(const Features& f) {
  std::string g =
      "// uv and tangent frame of the hit h on shape s (h.p on the surface, h.n outward):\n"
      "// tangent.xyz = unit dp/du, orthogonal to n; dp/dv lies along tangent.w * cross(n, tangent.xyz).\n"
      "struct SurfaceUv { vec2 uv; vec4 tangent; };\n"
      "SurfaceUv surface_uv(ShapeRec s, Hit h) {\n  vec3 p = h.p, n = h.n;\n";
  for (int i = 0; i < kNumShapeKinds; ++i) {
    if (!f.has(ShapeKind(i))) continue;
    std::string k = kShapeKinds[i].glsl, up = k;
    for (char& c : up) c = char(std::toupper(static_cast<unsigned char>(c)));
    // What the kind's uv_ and tangent_ take besides the record, p and n (its stem's
    // kUvArgs: a Triangle's vertex uv record, a mesh triangle's primitive).
    const std::string args = std::string("(s, ") + kShapeTraits[i].uv_args + "p, n)";
    g += "  if (s.kind == SHAPE_" + up + ") return SurfaceUv(uv_" + k + args + ", tangent_" + k + args + ");\n";
  }
  g += "  return SurfaceUv(vec2(0.0), vec4(frame_from(n).t, 1.0));\n}\n";
  // Each image-map kind's resolution at the hit: materials/<kind>_resolve.glsl.
  for (int i = 0; i < kNumMaterialKinds; ++i)
    if (f.has(MaterialKind(i)) && kMaterialTraits[i].image_maps)
      g += "#include \"materials/" + std::string(kMaterialKinds[i].glsl) + "_resolve.glsl\"\n";
  return g;
}

}  // namespace pt
