// Assembles GLSL ES 3.00 programs from the features a scene uses: per kind, never per
// object. Objects are data (see core/records.h); a program depends only on Features.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "accel/accel_choice.h"
#include "core/render_mode.h"
#include "core/shader_source.h"
#include "core/tonemap.h"
#include "scene/scene.h"

namespace pt {

// Each group of the flat loop by kind (HAS_FLAT_ORDER; render/packing.h: flat_order): the
// analytic primitives of each shape kind, in kind order, then every triangle.
inline constexpr int kFlatGroups = kNumShapeKinds + 1;

struct Features {
  uint32_t shapes = 0;     // bit i: ShapeKind i is present
  uint32_t materials = 0;  // bit i: MaterialKind i is present
  uint32_t lights = 0;     // bit i: an emitter of ShapeKind i is light-sampled
  uint32_t punctual = 0;   // bit i: a punctual light of LightKind i (lights/kinds.h)
  uint32_t material_features = 0;  // bit i: MaterialFeature i is used (materials/features.h)
  RenderMode mode = RenderMode::PathTracer;  // a render setting, not the scene's: the renderer sets it
  bool env_map = false;    // an HDR environment map (importance-sampled)
  bool motion = false;     // a shape moves (velocity): intersection depends on time
  // A GLSL ES 3.10 compute kernel instead of the WebGL 2 fragment pass (native GL ES 3.1+
  // only; the same code, run on every core: some GPUs, the H100 among them, give
  // fragment shaders a small part of their cores). A renderer setting too.
  bool compute = false;
  // The camera pass also writes the denoiser's first-hit auxiliaries (camera_aux.glsl);
  // a renderer setting too.
  bool aux = false;
  // Adaptive sampling: each tile's count and samples per pass from a texture
  // (camera_pass.glsl, render/adaptive.h); a renderer setting too.
  bool adaptive = false;
  // No acceleration structure: every ray tests every primitive in a plain loop, and the
  // program has no traversal code and no stack (accel/accel_choice.h). Features::of sets
  // it by the primitive count (auto); the renderer's Accel setting may override it.
  bool flat = false;
  // The camera pass counts the traversal's work (box tests, primitive tests) into the
  // statistics' z and w instead of the variance (`render --count-ops`); a renderer setting.
  bool count_ops = false;
  // The scene has at most kFlatOrderMax primitives (accel/accel_choice.h): a flat program
  // loops kind by kind over them (HAS_FLAT_ORDER). Features::of sets it; it only counts
  // with flat (in the key too: a BVH program is the same for every count).
  bool flat_order = false;
  bool has(ShapeKind k) const { return shapes >> int(k) & 1u; }
  bool has(MaterialKind k) const { return materials >> int(k) & 1u; }
  bool has_light(ShapeKind k) const { return lights >> int(k) & 1u; }
  bool has(LightKind k) const { return punctual >> int(k) & 1u; }
  bool has(MaterialFeature m) const { return material_features >> int(m) & 1u; }
  // A kind present reads the scene's image maps (the texture array, surface uv).
  bool image_maps() const {
    for (int i = 0; i < kNumMaterialKinds; ++i)
      if (has(MaterialKind(i)) && kMaterialTraits[i].image_maps) return true;
    return false;
  }
  // The program cache's key: every field, each in its own bytes (no packing to outgrow).
  std::string key() const {
    std::string k;
    auto put = [&k](uint32_t v) { k.append(reinterpret_cast<const char*>(&v), sizeof v); };
    put(shapes), put(materials), put(lights), put(punctual), put(material_features);
    put(uint32_t(env_map) | uint32_t(motion) << 1 | uint32_t(compute) << 2 | uint32_t(aux) << 3 | uint32_t(adaptive) << 4 | uint32_t(flat) << 5 | uint32_t(count_ops) << 6 | uint32_t(flat && flat_order) << 7 |
        uint32_t(mode) << 8);
    return k;
  }
  static Features of(const Scene& scene);
};
// The primitives a flat loop would test: one per analytic shape and lone triangle, one per
// mesh triangle (the rule of accel/accel_choice.h counts these).
long scene_primitives(const Scene& scene);
// A field added to Features must go into key() too (else two programs share a cache slot).
// Five words, the mode and eight flags (env_map .. flat_order): a new word or a ninth flag
// changes the size.
static_assert(sizeof(Features) == 5 * sizeof(uint32_t) + sizeof(RenderMode) + 8,
              "a new field of Features: add it to key() and to this count");
static_assert(kNumShapeKinds <= 32 && kNumLightKinds <= 32 && kNumMaterialKinds <= 32 && kNumMaterialFeatures <= 32,
              "Features: one bit per kind in 32");

class ShaderGenError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Expands #include "name" recursively, each file once; unknown names throw.
ShaderSource resolve_includes(const std::string& root_text, const std::string& root_name);

// Everything a program for `f` shares, up to and including light sampling: version,
// kind ids, record loaders, the kinds' snippets and the generated dispatch (unresolved
// text). The integrator appends its main; the GLSL test harness appends a kernel.
std::string generate_prelude(const Features& f);
// The render program: the prelude and the mode's root file (kRenderModeRoots).
ShaderSource generate_integrator(const Features& f);
// The display pass for one tone map: a constant, not a uniform, so that the other maps'
// branches are compiled away (SwiftShader runs every branch of a uniform switch for
// every pixel: the uniform made the display pass about twice as slow there).
ShaderSource generate_display(ToneMap tonemap);
ShaderSource fullscreen_vertex();

}  // namespace pt
