#include "glsl_harness.h"

#include <algorithm>
#include <cstdio>

#include "gl_context.h"
#include "gpu/texture.h"
#include "core/records.h"

namespace pt {

std::string glsl_material(const Material& m, const char* name) {
  Scene s;
  s.materials.push_back(m);
  const PackedScene p = pack_values(s);
  char buf[64];
  auto num = [&](float v) {
    std::snprintf(buf, sizeof buf, "%.9g", double(v));
    std::string t = buf;
    if (t.find_first_of(".en") == std::string::npos) t += ".0";  // a GLSL float literal
    return t;
  };
  std::string g = "MaterialRec " + std::string(name) + "() {\n  MaterialRec m;\n";
  for (const Field& f : material_layout().fields) {
    if (f.type[0] == 'i') {
      g += "  m." + std::string(f.name) + " = " + std::to_string(int(p.materials.get(0, f))) + ";\n";
    } else if (f.width == 1) {
      g += "  m." + std::string(f.name) + " = " + num(p.materials.get(0, f)) + ";\n";
    } else {
      const glm::vec3 v = p.materials.get3(0, f);
      g += "  m." + std::string(f.name) + " = vec3(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ");\n";
    }
  }
  for (const char* l : material_glsl().locals) g += "  m." + std::string(l) + " = 0.0;\n";
  return g + "  return m;\n}\n";
}

float sampled_weight_error(const Material& m, glm::vec3 wo, int n) {
  char decl[128];
  std::snprintf(decl, sizeof decl, "const vec3 WO = vec3(%.9g, %.9g, %.9g);\n", double(wo.x), double(wo.y), double(wo.z));
  GlslKernel k(glsl_material(m) + decl +
               "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 99u), 0u);\n  BsdfSample s;\n"
               "  if (!material_sample(make_material(), WO, true, vec3(rand01(), rand01(), rand01()), s)) return vec4(0.0);\n"
               "  float pdf;\n  vec3 f = material_eval(make_material(), WO, s.wi, true, pdf);\n"
               "  return vec4(abs(s.weight - f / pdf) / max(f / pdf, vec3(1e-6)), abs(pdf - s.pdf) / pdf);\n}\n");
  k.program().use();
  k.program().set("u_dot_weight", 1);
  float worst = 0;
  for (const glm::vec4& v : k.run(n)) worst = std::max({worst, v.x, v.y, v.z, v.w});
  return worst;
}

std::vector<float> sampled_weight_errors(const std::string& material, const Features& f, const std::vector<double>& cosines,
                                         bool entering, int n) {
  const std::string side = entering ? "true" : "false";
  // One kernel, the incidence from the input (compiling is most of the time on llvmpipe).
  GlslKernel k(material +
                   "vec4 kernel(vec4 x, int i) {\n  rng_init(uvec2(uint(i), 99u), 0u);\n  BsdfSample s;\n"
                   "  vec3 WO = vec3(sqrt(1.0 - x.x * x.x), 0.0, x.x);\n"
                   "  if (!material_sample(make_material(), WO, " + side + ", vec3(rand01(), rand01(), rand01()), s) || s.delta) return vec4(0.0);\n"
                   "  float pdf;\n  vec3 f = material_eval(make_material(), WO, s.wi, " + side + ", pdf);\n"
                   "  return vec4(abs(s.weight - f / pdf) / max(f / pdf, vec3(1e-6)), abs(pdf - s.pdf) / pdf);\n}\n",
               f);
  k.program().use();
  k.program().set("u_dot_weight", 1);
  std::vector<float> worst;
  for (double c : cosines) {
    float w = 0;
    for (const glm::vec4& v : k.run(std::vector<glm::vec4>(size_t(n), glm::vec4(float(c), 0.0f, 0.0f, 0.0f))))
      w = std::max({w, v.x, v.y, v.z, v.w});
    worst.push_back(w);
  }
  return worst;
}

Features gltf_lobe_features() {
  Features f = all_features();
  f.material_features |= feature_bit(MaterialFeature::GltfSpecular) | feature_bit(MaterialFeature::GltfClearcoat) |
                         feature_bit(MaterialFeature::GltfSheen) | feature_bit(MaterialFeature::GltfTransmission) |
                         feature_bit(MaterialFeature::GltfMs);
  return f;
}

Features all_features() {
  Features f;
  f.shapes = (1u << kNumShapeKinds) - 1;
  f.materials = (1u << kNumMaterialKinds) - 1;
  for (int i = 0; i < kNumShapeKinds; ++i)
    if (kShapeKinds[i].samplable) f.lights |= 1u << i;
  f.env_map = true;
  f.motion = true;
  return f;
}

GlslKernel::GlslKernel(const std::string& body, const Features& f) {
  test_gl();
  const std::string main =
      "\nuniform highp sampler2D u_input;\nuniform int u_count;\nout vec4 o_out;\n"
      "void main() {\n  ivec2 px = ivec2(gl_FragCoord.xy);\n  int i = px.y * " +
      std::to_string(kDataWidth) + " + px.x;\n  o_out = i < u_count ? kernel(texelFetch(u_input, px, 0), i) : vec4(0.0);\n}\n";
  program_ = Program(fullscreen_vertex(), resolve_includes(generate_prelude(f) + "#line 1\n" + body + main, "<kernel>"));
  tables_.attach(program_);
}

void GlslKernel::bind(const char* sampler, const Texture& t) { textures_.emplace_back(sampler, &t); }

void GlslKernel::bind_scene(const Scene& scene, const PackedScene& p) {
  auto add = [&](const char* sampler, const RecordBuffer& b) {
    const std::vector<float> t = b.texels();
    owned_.push_back(std::make_unique<Texture>(kDataWidth, b.rows(), GL_RGBA32F, t.data()));
    bind(sampler, *owned_.back());
  };
  add("u_shape_data", p.shapes);
  add("u_material_data", p.materials);
  add("u_light_data", p.lights);
  add("u_node_data", p.nodes);
  add("u_prim_data", p.prims);
  add("u_vertex_data", p.vertices);
  program_.use();
  program_.set("u_num_lights", p.lights.count());
  program_.set("u_num_prims", p.prims.count());
  program_.set("u_num_unbounded", p.unbounded);
  program_.set("u_num_nodes", p.nodes.count());
  bind_flat_order(program_, flat_order(scene, p));  // a flat program kind by kind
}

std::vector<glm::vec4> GlslKernel::run(const std::vector<glm::vec4>& inputs) {
  const int n = int(inputs.size());
  const int rows = (n + kDataWidth - 1) / kDataWidth;
  std::vector<glm::vec4> padded(size_t(rows) * kDataWidth, glm::vec4(0.0f));
  std::copy(inputs.begin(), inputs.end(), padded.begin());
  Texture in(kDataWidth, rows, GL_RGBA32F, &padded[0].x);
  Texture out(kDataWidth, rows, GL_RGBA32F, nullptr);
  Framebuffer fb(out);
  GLuint vao = 0;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  program_.use();
  in.bind(0);
  program_.set("u_input", 0);
  for (size_t k = 0; k < textures_.size(); ++k) {
    textures_[k].second->bind(int(k) + 1);
    program_.set(textures_[k].first.c_str(), int(k) + 1);
  }
  program_.set("u_count", n);
  tables_.bind();
  glBindFramebuffer(GL_FRAMEBUFFER, fb.id());
  glViewport(0, 0, kDataWidth, rows);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<glm::vec4> result(size_t(rows) * kDataWidth);
  glReadPixels(0, 0, kDataWidth, rows, GL_RGBA, GL_FLOAT, &result[0].x);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteVertexArrays(1, &vao);
  result.resize(size_t(n));
  return result;
}

}  // namespace pt
