#include "shadergen/textured_gen.h"

#include <cctype>

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
    // A Triangle's vertex uv live in the uv records (one per shape index).
    // A mesh triangle's attributes hang off the primitive of the hit (mesh.glsl).
    const std::string args = ShapeKind(i) == ShapeKind::Triangle ? "(s, load_uv(h.id), p, n)"
                             : ShapeKind(i) == ShapeKind::Mesh   ? "(s, h.prim, p, n)"
                                                                 : "(s, p, n)";
    g += "  if (s.kind == SHAPE_" + up + ") return SurfaceUv(uv_" + k + args + ", tangent_" + k + args + ");\n";
  }
  g += "  return SurfaceUv(vec2(0.0), vec4(frame_from(n).t, 1.0));\n}\n";
  g += "#include \"materials/textured_resolve.glsl\"\n";
  return g;
}

}  // namespace pt
