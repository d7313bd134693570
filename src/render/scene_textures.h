// The scene on the GPU: its record textures (shapes, materials, lights, the BVH, its
// primitives, mesh vertex attributes), the image maps of Textured materials with their uv
// records, and the environment (its map, the map's sampling CDF, the SH coefficients of
// the SH mode). Renderer::set_scene fills it once everything that can fail has passed;
// edits of values replace records without a new program; bind() hands it to a program.
#pragma once
#include <memory>
#include <vector>

#include "core/render_mode.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "gpu/texture_array.h"
#include "render/image_maps.h"
#include "render/packing.h"
#include "render/sh.h"
#include "scene/scene.h"

namespace pt {

// A HAS_FLAT_ORDER program's uniforms (u_flat_order, u_flat_end) from the order (every
// bind: uniforms are the program's, and programs are shared between scenes); a program
// without them ignores them (location -1).
void bind_flat_order(Program& p, const FlatOrder& o);
class StagedScene;

class SceneTextures {
 public:
  // The scene's records, taken from `staged` (uploaded: done()), and its image maps
  // (`maps`: built when the scene is textured, else null). The environment is set apart.
  void set(const Scene& scene, const PackedScene& p, StagedScene& staged, const MapArray* maps);
  // An edit of values: the shape, material and light records again (pack_values), whose
  // lights are those of `light_shapes` (packing.h). false, changing nothing, when other
  // shapes are lights than those set (Renderer::set_scene then says why not).
  bool update_values(const PackedScene& values, const std::vector<int>& light_shapes);
  // An edit that moved shapes (refit_shape): the rows of the records it changed.
  void update_rows(const PackedScene& p, const std::vector<int>& prims, const std::vector<int>& nodes);
  // The environment's textures (a new map only: rotation and intensity are uniforms) and,
  // when `mode` needs them, its SH coefficients (computed again only after a change).
  void set_environment(const Environment& env, RenderMode mode);
  void update_sh(RenderMode mode);

  // Binds every texture to its unit (render/texture_units.h) and sets the program's
  // uniforms of the scene (counts, environment, SH when `mode` is the SH mode).
  void bind(Program& p, RenderMode mode) const;

  int lights() const { return num_lights_; }
  int shapes() const { return num_shapes_; }
  int prims() const { return num_prims_; }
  int nodes() const { return num_nodes_; }
  float motion_bound() const { return motion_bound_; }

 private:
  Texture shape_tex_, material_tex_, light_tex_;
  Texture node_tex_, prim_tex_, vertex_tex_;  // the BVH, its primitives, mesh vertex attributes
  TextureArray maps_;  // Textured scenes: the image maps (render/image_maps.h)
  Texture uv_tex_;     // and the Triangle uv records
  Texture texinfo_tex_;  // and the maps' texinfo records (GltfPbr: materials/gltf_map.h)
  int num_lights_ = 0, num_unbounded_ = 0, num_nodes_ = 0, num_shapes_ = 0, num_prims_ = 0;
  std::vector<int> light_shapes_;  // the shape of each light record (update_values keeps them)
  FlatOrder flat_order_;  // the flat loop's order kind by kind (render/packing.h)
  float motion_bound_ = 1.0f;
  bool dot_weight_ = true;

  Environment env_;  // as last set (for the SH projection)
  ShCoeffs sh_{};
  bool sh_valid_ = false;
  Texture env_tex_, env_cdf_tex_;  // when the scene has an environment map
  glm::ivec2 env_size_{0};
  float env_rotation_ = 0.0f, env_intensity_ = 1.0f, env_integral_ = 0.0f;
  std::shared_ptr<const EnvImage> env_source_;  // the image the textures hold
  glm::vec3 env_color_{0.5f};
};

}  // namespace pt
