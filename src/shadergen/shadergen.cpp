#include "shadergen/shadergen.h"

#include <cctype>
#include <cstring>
#include <set>
#include <sstream>

#include "core/records.h"
#include "core/sobol.h"
#include "materials/gltf_map.h"
#include "shadergen/embedded.h"
#include "shadergen/textured_gen.h"

namespace pt {

const char* find_embedded_glsl(const char* name) {
  for (int i = 0; i < kEmbeddedGlslCount; ++i)
    if (!std::strcmp(kEmbeddedGlsl[i].name, name)) return kEmbeddedGlsl[i].text;
  return nullptr;
}

Features Features::of(const Scene& scene) {
  Features f;
  f.env_map = scene.environment.map != nullptr;
  for (const Shape& s : scene.shapes) f.motion |= velocity(s.params) != glm::vec3(0.0f);
  for (const Shape& s : scene.shapes) f.shapes |= shape_bit(s.kind());
  // Every material in the list is used (by a shape or as a composite's child), with the
  // kinds whose functions its own call (a texture shades as Diffuse).
  for (const Material& m : scene.materials) f.materials |= kind_bit(m.kind()) | kMaterialTraits[int(m.kind())].needs;
  for (const Material& m : scene.materials) f.material_features |= pt::material_features(m.params);
  for (int i : sampled_light_shapes(scene)) f.lights |= 1u << int(scene.shapes[size_t(i)].kind());
  for (const PunctualLight& l : scene.punctual) f.punctual |= 1u << int(l.kind());
  // flat: left to the renderer, whose rule reads the scene's packed BVH (render/packing.h: accel_costs).
  f.flat_order = scene_primitives(scene) <= kFlatOrderMax;
  return f;
}

long scene_primitives(const Scene& scene) {
  long n = 0;
  for (const Shape& s : scene.shapes) {
    const BvhRole role = info(s.kind()).bvh;
    if (role == BvhRole::Instanced) n += long(scene.meshes[size_t(s.as<Mesh>()->mesh)]->triangles.size());
    else if (role != BvhRole::None) ++n;
  }
  return n;
}

namespace {

struct Resolver {
  ShaderSource out;
  std::set<std::string> done;

  void file(const std::string& name, const std::string& text, const std::string& from) {
    if (!done.insert(name).second) return;
    const int id = int(out.files.size());
    out.files.push_back(name);
    std::istringstream in(text);
    std::string line;
    int n = 0;
    bool first = true;
    while (std::getline(in, line)) {
      ++n;
      if (first && line.rfind("#version", 0) == 0) {  // must stay the very first line
        out.text += line + "\n#line " + std::to_string(n + 1) + " " + std::to_string(id) + "\n";
        first = false;
        continue;
      }
      if (first) {
        out.text += "#line " + std::to_string(n) + " " + std::to_string(id) + "\n";
        first = false;
      }
      const auto inc = line.find("#include");
      if (inc != std::string::npos && line.find_first_not_of(" \t") == inc) {
        const auto a = line.find('"', inc), b = line.find('"', a + 1);
        if (a == std::string::npos || b == std::string::npos)
          throw ShaderGenError(name + ":" + std::to_string(n) + ": malformed #include");
        const std::string inc_name = line.substr(a + 1, b - a - 1);
        const char* inc_text = find_embedded_glsl(inc_name.c_str());
        if (!inc_text)
          throw ShaderGenError(name + ":" + std::to_string(n) + ": unknown include \"" + inc_name + "\"");
        file(inc_name, inc_text, name);
        out.text += "#line " + std::to_string(n + 1) + " " + std::to_string(id) + "\n";
        continue;
      }
      out.text += line + "\n";
    }
    (void)from;
  }
};

std::string kind_defines() {
  std::string s;
  for (int i = 0; i < kNumShapeKinds; ++i) {
    std::string up = kShapeKinds[i].glsl;
    for (char& c : up) c = char(std::toupper(c));
    s += "#define SHAPE_" + up + " " + std::to_string(i) + "\n";
  }
  for (int i = 0; i < kNumMaterialKinds; ++i) {
    std::string up = kMaterialKinds[i].glsl;
    for (char& c : up) c = char(std::toupper(c));
    s += "#define MAT_" + up + " " + std::to_string(i) + "\n";
  }
  return s;
}

std::string capitalized(const char* s) {
  std::string c = s;
  c[0] = char(std::toupper(c[0]));
  return c;
}

std::string upper(const char* s) {
  std::string u = s;
  for (char& c : u) c = char(std::toupper(c));
  return u;
}

// A kind's record as its GLSL sees it: struct <Type>Rec with the fields the kind declares
// (core/kind_record.h), <glsl>_rec(<Record>Rec m) reading them from the payload slots
// m.<slot>0.. in order, and with_<glsl>_rec writing them back (a material's hit fields).
std::string kind_record(const std::string& type, const std::string& fn, const KindField* fields, int num_fields,
                        const std::string& record, const std::string& slot_prefix) {
  if (num_fields == 0) return "";
  static const char* kTypes[] = {"", "float", "vec2", "vec3", "vec4"};
  const std::string rec = type + "Rec";
  std::string decl = "struct " + rec + " {", get = rec + " " + fn + "_rec(" + record + " m) {\n  " + rec + " r;\n",
              put = record + " with_" + fn + "_rec(" + record + " m, " + rec + " r) {\n";
  int slot = 0;
  for (int i = 0; i < num_fields; ++i) {
    const KindField& f = fields[i];
    const bool is_int = f.type[0] == 'i';
    decl += " " + std::string(f.type) + " " + f.name + ";";
    std::string src;
    for (int c = 0; c < f.width; ++c) {
      const std::string p = "m." + slot_prefix + std::to_string(slot + c);
      src += (c ? ", " : "") + p;
      const std::string comp = f.width == 1 ? "" : std::string(".") + "xyzw"[c];
      put += "  " + p + " = " + (is_int ? "float(r." + std::string(f.name) + ")" : "r." + std::string(f.name) + comp) + ";\n";
    }
    get += "  r." + std::string(f.name) + " = " + (is_int ? "int(" + src + ")" : f.width == 1 ? src : std::string(kTypes[f.width]) + "(" + src + ")") + ";\n";
    slot += f.width;
  }
  return decl + " };\n" + get + "  return r;\n}\n" + put + "  return m;\n}\n";
}

}  // namespace

ShaderSource resolve_includes(const std::string& root_text, const std::string& root_name) {
  Resolver r;
  r.file(root_name, root_text, "");
  return std::move(r.out);
}

// Shape kind i is present and tested as an analytic primitive (a plane's too: unbounded).
static bool analytic_present(const Features& f, int i) {
  const BvhRole role = kShapeKinds[i].bvh;
  return f.has(ShapeKind(i)) && (role == BvhRole::Analytic || role == BvhRole::Unbounded);
}

// The call of kind i's intersection for shape record `s`, shape index `id`.
static std::string intersect_call(int i, const std::string& s, const std::string& id) {
  const std::string k = kShapeKinds[i].glsl;
  return "intersect_" + k + "(" + s + ", " + id + ", r, " + (kShapeKinds[i].per_ray ? "pre." + k + ", " : std::string()) + "h)";
}

// The flat loop kind by kind (HAS_FLAT_ORDER; bvh.glsl declares flat_groups): one loop per
// group of render/packing.h's flat_order, in its order, each with its kind's test alone; a
// shadow query (any_hit) ends at its first hit, through the loops' condition.
static std::string flat_groups(const Features& f) {
  std::string g = "uniform ivec4 u_flat_order[" + std::to_string(kFlatOrderMax / 4) +
                  "];  // primitive indices, group by group (render/packing.h: flat_order)\n"
                  "uniform int u_flat_end[" + std::to_string(kFlatGroups) + "];  // where each group ends in it\n"
                  "void flat_groups(Ray r, RayPre pre, bool any_hit, int skip, inout Hit h) {\n";
  auto loop = [](int group, const std::string& body) {
    return "  for (int j = " + (group == 0 ? std::string("0") : "u_flat_end[" + std::to_string(group - 1) + "]") +
           "; j < u_flat_end[" + std::to_string(group) + "] && !(any_hit && h.id >= 0); ++j) {\n"
           "    int i = u_flat_order[j >> 2][j & 3];\n    PrimRec p = load_prim(i);\n    COUNT_OPS(g_prim_tests, 1);\n" + body + "  }\n";
  };
  // The unbounded kinds (planes) first, as they come first in leaf order (where two
  // surfaces meet at the same t the first tested wins: so the BVH's result stays).
  for (int pass = 0; pass < 2; ++pass)
    for (int i = 0; i < kNumShapeKinds; ++i)
      if (analytic_present(f, i) && (kShapeKinds[i].bvh == BvhRole::Unbounded) == (pass == 0))
        g += loop(i, "    float before = h.t;\n    if (-1 - p.tag != skip) " + intersect_call(i, "prim_shape(p)", "-1 - p.tag") +
                       ";\n    if (h.t < before) h.prim = i;\n");
  g += "#ifdef HAS_PRIM_TRIANGLES\n" + loop(kNumShapeKinds, "    bvh_triangle(i, p, r, pre, skip, h);\n") + "#endif\n";
  return g + "}\n";
}

// The punctual light kinds present (lights/kinds.h): their snippets and
// punctual_sample(l, p, wi, dist, e), dispatching on the light record's shape = -1 - kind.
static std::string punctual_dispatch(const Features& f) {
  if (!f.punctual) return "";
  std::string g = "#define HAS_PUNCTUAL 1\n", d = "bool punctual_sample(LightRec l, vec3 p, out vec3 wi, out float dist, out vec3 e) {\n";
  for (int i = 0; i < kNumLightKinds; ++i) {
    if (!f.has(LightKind(i))) continue;
    g += "#include \"lights/" + std::string(kLightKinds[i].glsl) + ".glsl\"\n";
    d += "  if (l.shape == " + std::to_string(-1 - i) + ") return punctual_" + kLightKinds[i].glsl + "(l, p, wi, dist, e);\n";
  }
  return g + d + "  wi = vec3(0.0);\n  dist = 0.0;\n  e = vec3(0.0);\n  return false;\n}\n";
}

std::string generate_prelude(const Features& features) {
  Features f = features;
  for (int i = 0; i < kNumShapeKinds; ++i)  // with the kinds whose GLSL theirs calls (a mesh's triangles)
    if (features.has(ShapeKind(i))) f.shapes |= kShapeTraits[i].needs;
  std::string g = f.compute ? "#version 310 es\n" : "#version 300 es\n";
  g += "// Generated by shadergen for this scene's features.\n";
  g += "precision highp float;\nprecision highp int;\nprecision highp sampler2D;\n";
  if (f.compute)
    g += "precision highp image2D;\n#define PT_COMPUTE 1\n#define PT_GROUP_SIZE 64\n"
         "layout(local_size_x = 8, local_size_y = 8) in;  // PT_GROUP_SIZE invocations (renderer.cpp dispatches 8x8)\n";
  g += kind_defines();
  for (int i = 0; i < kNumShapeKinds; ++i)
    if (f.has(ShapeKind(i))) g += "#define HAS_SHAPE_" + upper(kShapeKinds[i].glsl) + " 1\n";
  for (int i = 0; i < kNumShapeKinds; ++i)
    if (f.has_light(ShapeKind(i))) g += "#define HAS_LIGHT_" + upper(kShapeKinds[i].glsl) + " 1\n";
  for (int i = 0; i < kNumMaterialKinds; ++i)
    if (f.has(MaterialKind(i))) g += "#define HAS_MAT_" + upper(kMaterialKinds[i].glsl) + " 1\n";
  for (int i = 0; i < kNumMaterialFeatures; ++i)
    if (f.has(MaterialFeature(i))) g += std::string("#define HAS_") + kMaterialFeatureNames[i] + " 1\n";
  if (f.image_maps()) g += "#define HAS_IMAGE_MAPS 1\n";
  if (f.env_map) g += "#define HAS_ENV_MAP 1\n";
  for (int i = 0; i < kNumShapeKinds; ++i)
    if (f.has(ShapeKind(i)) && (kShapeKinds[i].bvh == BvhRole::Triangles || kShapeKinds[i].bvh == BvhRole::Instanced)) {
      g += "#define HAS_PRIM_TRIANGLES 1\n";
      break;
    }
  if (f.motion) g += "#define HAS_MOTION 1\n";
  if (f.aux) g += "#define PT_AUX 1\n";
  if (f.adaptive) g += "#define PT_ADAPTIVE 1\n";
  if (f.flat) g += "#define HAS_FLAT 1\n";
  if (f.flat && f.flat_order) g += "#define HAS_FLAT_ORDER 1\n";
  if (f.count_ops) g += "#define PT_COUNT_OPS 1\n";
  g += "#include \"common.glsl\"\n";
  g += glsl_record(shape_layout()) + glsl_record(material_glsl()) + glsl_record(light_layout());
  if (!f.flat) g += glsl_record(node_layout());  // flat: no traversal reads a node (bvh.glsl)
  g += glsl_record(prim_layout());
  for (int i = 0; i < kNumShapeKinds; ++i)
    if (f.has(ShapeKind(i)) && kShapeKinds[i].bvh == BvhRole::Instanced) {  // per-vertex attributes
      g += glsl_record(vertex_layout());
      break;
    }
  if (f.image_maps()) g += "precision highp sampler2DArray;\n" + glsl_record(uv_layout()) + glsl_record(texinfo_layout());
  g += glsl_sobol_dims();
  g += "#include \"rng.glsl\"\n#include \"sampler.glsl\"\n#include \"sampling.glsl\"\n#include \"surface_types.glsl\"\n";
  for (int i = 0; i < kNumMaterialKinds; ++i)
    if (f.has(MaterialKind(i)))
      g += kind_record(info(MaterialKind(i)).type, kMaterialKinds[i].glsl, kMaterialTraits[i].fields, kMaterialTraits[i].num_fields,
                       "MaterialRec", "p");
  for (int i = 0; i < kNumShapeKinds; ++i)
    if (f.has(ShapeKind(i)))
      g += kind_record(capitalized(kShapeKinds[i].glsl), kShapeKinds[i].glsl, kShapeTraits[i].fields, kShapeTraits[i].num_fields,
                       "ShapeRec", "q");
  if (f.motion) {  // a moving shape's velocity (a triangle primitive's: triangle.glsl; a BVH node's: bvh.glsl)
    g += "vec3 prim_velocity(int shape) {\n  ShapeRec s = load_shape(shape);\n";
    for (int i = 0; i < kNumShapeKinds; ++i) {
      if (!f.has(ShapeKind(i))) continue;
      for (int k = 0; k < kShapeTraits[i].num_fields; ++k)
        if (!std::strcmp(kShapeTraits[i].fields[k].name, "velocity"))
          g += "  if (s.kind == SHAPE_" + upper(kShapeKinds[i].glsl) + ") return " + kShapeKinds[i].glsl + "_rec(s).velocity;\n";
    }
    g += "  return vec3(0.0);\n}\n";
  }
  for (int i = 0; i < kNumShapeKinds; ++i)
    if (f.has(ShapeKind(i))) g += "#include \"shapes/" + std::string(kShapeKinds[i].glsl) + ".glsl\"\n";
  for (int i = 0; i < kNumMaterialFeatures; ++i)
    if (f.has(MaterialFeature(i)) && kMaterialFeatureSnippets[i]) g += std::string("#include \"") + kMaterialFeatureSnippets[i] + "\"\n";
  for (int i = 0; i < kNumMaterialKinds; ++i)
    if (f.has(MaterialKind(i))) g += "#include \"materials/" + std::string(kMaterialKinds[i].glsl) + ".glsl\"\n";

  // Per-ray data of the kinds present, and the analytic shapes' dispatch, for bvh.glsl.
  g += "struct RayPre { int unused;";
  for (int i = 0; i < kNumShapeKinds; ++i)
    if (f.has(ShapeKind(i)) && kShapeKinds[i].per_ray) g += " " + capitalized(kShapeKinds[i].glsl) + "Ray " + kShapeKinds[i].glsl + ";";
  g += " };\nRayPre prepare_ray(Ray r) {\n  RayPre p;\n  p.unused = 0;\n";
  for (int i = 0; i < kNumShapeKinds; ++i)
    if (f.has(ShapeKind(i)) && kShapeKinds[i].per_ray)
      g += "  p." + std::string(kShapeKinds[i].glsl) + " = prepare_" + kShapeKinds[i].glsl + "(r);\n";
  // The primitive carries the fields of the shape record that intersection reads.
  g += "  return p;\n}\nShapeRec prim_shape(PrimRec p) {\n  ShapeRec s;\n  s.kind = p.kind;\n";
  for (int i = 0; i < prim_rec::kAnalyticSlots; ++i)
    g += "  s." + std::string(shape_rec::kPayload[i]->name) + " = p." + prim_rec::kAnalytic[i]->name + ";\n";
  g += "  return s;\n}\nvoid intersect_analytic(PrimRec p, Ray r, RayPre pre, inout Hit h) {\n  int id = -1 - p.tag;\n"
       "  ShapeRec s = prim_shape(p);\n";
  for (int i = 0; i < kNumShapeKinds; ++i)
    if (analytic_present(f, i)) g += "  if (s.kind == SHAPE_" + upper(kShapeKinds[i].glsl) + ") " + intersect_call(i, "s", "id") + ";\n";
  g += "}\n";
  if (f.has(MaterialFeature::HitCuts)) {  // the traversal asks the kinds that cut hits (bvh.glsl)
    g += "bool hit_present(int shape, int prim, Ray r, Hit h) {\n  MaterialRec m = load_material(load_shape(shape).material);\n";
    for (int i = 0; i < kNumMaterialKinds; ++i)
      if (f.has(MaterialKind(i)) && kMaterialTraits[i].cuts_hits)
        g += "  if (m.kind == MAT_" + upper(kMaterialKinds[i].glsl) + ") return hit_present_" + kMaterialKinds[i].glsl + "(m, prim, r, h);\n";
    g += "  return true;\n}\n";
  }
  g += "#include \"bvh.glsl\"\n";
  if (f.flat && f.flat_order) g += flat_groups(f);
  if (f.has(MaterialFeature::Media)) {  // the media the path tracks (integrator.glsl): the kinds that bound one
    g += "bool material_medium(MaterialRec m, out vec3 sigma) {\n";
    for (int i = 0; i < kNumMaterialKinds; ++i)
      if (f.has(MaterialKind(i)) && kMaterialTraits[i].medium)
        g += "  if (m.kind == MAT_" + upper(kMaterialKinds[i].glsl) + ") return medium_" + kMaterialKinds[i].glsl + "(m, sigma);\n";
    g += "  sigma = vec3(0.0);\n  return false;\n}\n#include \"media.glsl\"\n";
  }
  std::string delta = "bool material_is_delta(MaterialRec m) {\n";
  std::string eval = "vec3 material_eval(MaterialRec m, vec3 wo, vec3 wi, bool entering, out float pdf) {\n";
  std::string smp = "bool material_sample(MaterialRec m, vec3 wo, bool entering, vec3 u, out BsdfSample s) {\n";
  std::string alb = "vec3 material_albedo(MaterialRec m) {\n";
  for (int i = 0; i < kNumMaterialKinds; ++i) {
    if (!f.has(MaterialKind(i))) continue;
    const std::string k = kMaterialKinds[i].glsl, cond = "  if (m.kind == MAT_" + upper(kMaterialKinds[i].glsl) + ") ";
    delta += cond + "return delta_" + k + "(m);\n";
    eval += cond + "return eval_" + k + "(m, wo, wi, entering, pdf);\n";
    smp += cond + "return sample_" + k + "(m, wo, entering, u, s);\n";
    alb += cond + "return albedo_" + k + "(m);\n";
  }
  g += delta + "  return true;\n}\n" + eval + "  pdf = 0.0;\n  return vec3(0.0);\n}\n" + smp + "  return false;\n}\n" + alb +
       "  return m.tint;\n}\n";
  // The surface step's hooks (surface.glsl): a composite kind picks a child, level by
  // level; a kind resolved at the hit becomes what shades there.
  std::string comp = "MaterialRec resolve_composites(MaterialRec m, float cos_o, bool entering, float u) {\n", hit =
                     "void resolve_hit(inout Surface sf, Ray r, Hit h) {\n";
  std::string emit = "void emission_hit(inout Surface sf, Ray r, Hit h) {\n";
  std::string comp_cases;
  for (int i = 0; i < kNumMaterialKinds; ++i) {
    if (!f.has(MaterialKind(i))) continue;
    const std::string k = kMaterialKinds[i].glsl, cond = "if (m.kind == MAT_" + upper(kMaterialKinds[i].glsl) + ") ";
    if (kMaterialTraits[i].composite) comp_cases += std::string(comp_cases.empty() ? "    " : "    else ") + cond + "m = choose_" + k + "(m, cos_o, entering, u);\n";
    if (kMaterialTraits[i].resolves_at_hit) hit += "  if (sf.m.kind == MAT_" + upper(kMaterialKinds[i].glsl) + ") resolve_hit_" + k + "(sf, r, h);\n";
    if (kMaterialTraits[i].emission_at_hit) emit += "  if (sf.m.kind == MAT_" + upper(kMaterialKinds[i].glsl) + ") emission_hit_" + k + "(sf, r, h);\n";
  }
  if (!comp_cases.empty())
    comp += "  for (int level = 0; level < " + std::to_string(kMaxCompositeDepth) + "; ++level) {\n" + comp_cases + "    else break;\n  }\n";
  if (f.image_maps()) g += glsl_textured_support(f);  // image maps: uv of the shapes present
  // A shape kind's shading normal at the hit (a mesh's interpolated vertex normals).
  std::string sn = "bool shape_shading_normal(ShapeRec s, Hit h, out vec3 ns) {\n";
  for (int i = 0; i < kNumShapeKinds; ++i)
    if (f.has(ShapeKind(i)) && kShapeTraits[i].shading_normal)
      sn += "  if (s.kind == SHAPE_" + upper(kShapeKinds[i].glsl) + ") return shading_normal_" + kShapeKinds[i].glsl + "(s, h, ns);\n";
  g += comp + "  return m;\n}\n" + hit + "}\n" + emit + "}\n" + sn + "  ns = vec3(0.0);\n  return false;\n}\n";
  // Light sampling over the emitter kinds present (solid-angle densities).
  std::string lsmp = "bool light_sample_shape(ShapeRec s, vec3 p, vec2 u, out vec3 wi, out float pdf, out float dist) {\n";
  std::string lpdf = "float light_pdf_shape(ShapeRec s, vec3 p, vec3 wi, float t, vec3 n) {\n";
  for (int i = 0; i < kNumShapeKinds; ++i) {
    if (!f.has_light(ShapeKind(i))) continue;
    const std::string k = kShapeKinds[i].glsl, cond = "  if (s.kind == SHAPE_" + upper(kShapeKinds[i].glsl) + ") ";
    lsmp += cond + "return sample_light_" + k + "(s, p, u, wi, pdf, dist);\n";
    lpdf += cond + "return pdf_light_" + k + "(s, p, wi, t, n);\n";
  }
  g += lsmp + "  pdf = 0.0;\n  dist = 0.0;\n  return false;\n}\n" + lpdf + "  return 0.0;\n}\n";
  if (f.env_map) g += "#include \"environment.glsl\"\n";
  g += punctual_dispatch(f);
  g += "#include \"lights.glsl\"\n";
  return g;
}

ShaderSource generate_integrator(const Features& f) {
  Features g = f;
  if (f.mode == RenderMode::SphericalHarmonics) g.lights = 0;  // it samples no light
  return resolve_includes(generate_prelude(g) + "#include \"" + kRenderModeRoots[int(f.mode)] + "\"\n",
                          "<generated integrator>");
}

ShaderSource generate_display(ToneMap tonemap) {
  return resolve_includes(
      "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
      "#define PT_TONEMAP " + std::to_string(int(tonemap)) + "\n#include \"tonemap.glsl\"\n#include \"display.glsl\"\n",
      "<generated display>");
}

ShaderSource fullscreen_vertex() {
  return resolve_includes(find_embedded_glsl("fullscreen_vert.glsl"), "fullscreen_vert.glsl");
}

}  // namespace pt
