// The GLSL test harness: runs production GLSL over a buffer of inputs on the GPU through
// headless EGL. A kernel is GLSL text defining
//     vec4 kernel(vec4 x, int i)
// compiled after the generated prelude of the given features (so every shape, material,
// sampling and light function of the real shader is callable by name); it runs once per
// input in a fullscreen pass into RGBA32F and the outputs are read back.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/program.h"
#include "gpu/texture.h"
#include "render/packing.h"
#include "render/scene_textures.h"
#include "render/uniform_tables.h"
#include <memory>
#include "shadergen/shadergen.h"

namespace pt {

Features all_features();
// all_features() with every lobe of the glTF BSDF (KHR_materials_specular, _clearcoat,
// _sheen, thin-walled _transmission) and the multiple-scattering compensation.
Features gltf_lobe_features();

// GLSL defining `MaterialRec <name>()` that returns material m as the production packer
// writes it (render/packing.h) and the shader loads it: kind, tint, emission and the
// kind's payload slots (the hit slots zero).
std::string glsl_material(const Material& m, const char* name = "make_material");

// The largest relative difference, over n samples of material m at incidence wo, between
// a sample's weight and pdf and f cos / pdf and the pdf of the evaluated BSDF there.
float sampled_weight_error(const Material& m, glm::vec3 wo, int n = 20000);
// The same for GLSL `material` that defines make_material(), at each incidence cos_o (wo in
// the xz plane), from the side `entering` says, with features f: the worst per incidence.
std::vector<float> sampled_weight_errors(const std::string& material, const Features& f, const std::vector<double>& cosines,
                                         bool entering = true, int n = 20000);

class GlslKernel {
 public:
  explicit GlslKernel(const std::string& body, const Features& f = all_features());
  std::vector<glm::vec4> run(const std::vector<glm::vec4>& inputs);
  std::vector<glm::vec4> run(int n) { return run(std::vector<glm::vec4>(size_t(n), glm::vec4(0.0f))); }
  // Set uniforms (u_dot_weight, ...) before run().
  Program& program() { return program_; }
  // A texture bound to `sampler` on every run (units 1 and up; 0 holds the inputs).
  void bind(const char* sampler, const Texture& t);
  // Uploads a packed scene (shapes, materials, lights, BVH nodes, primitives, mesh
  // vertices) and binds it with its counts, as the renderer does.
  void bind_scene(const Scene& scene, const PackedScene& p);

 private:
  Program program_;
  std::vector<std::unique_ptr<Texture>> owned_;
  std::vector<std::pair<std::string, const Texture*>> textures_;
  UniformTables tables_;  // the build's tables (render/uniform_tables.h)
};

}  // namespace pt
