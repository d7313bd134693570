// The scene's textures and uniforms (render/scene_textures.h).
#include "render/scene_textures.h"

#include <algorithm>
#include <array>
#include <limits>

#include "render/environment.h"
#include "render/packing.h"
#include "render/staged_scene.h"
#include "render/texture_units.h"

namespace pt {
namespace {

// The sizes were checked against the GPU's limits in Renderer::set_scene, before any
// state changed (uv records take 2 texels per shape where shape records take 4: covered by
// the shapes' check).
Texture upload(const RecordBuffer& b) {
  const std::vector<float> t = b.texels();
  return Texture(kDataWidth, b.rows(), GL_RGBA32F, t.data());
}

// The rows of a record texture that hold the given records, from the buffer again.
void upload_rows(Texture& t, const RecordBuffer& b, const std::vector<int>& recs) {
  std::vector<int> rows;
  for (int r : recs) rows.push_back(r * b.texels_per_record() / kDataWidth);
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  glBindTexture(GL_TEXTURE_2D, t.id());
  std::vector<float> row(size_t(kDataWidth) * 4);
  for (int r : rows) {
    const size_t begin = size_t(r) * kDataWidth * 4, end = std::min(b.raw().size(), begin + row.size());
    std::fill(std::copy(b.raw().begin() + std::ptrdiff_t(begin), b.raw().begin() + std::ptrdiff_t(end), row.begin()), row.end(), 0.0f);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, r, kDataWidth, 1, GL_RGBA, GL_FLOAT, row.data());
  }
  PT_GL_CHECK("glTexSubImage2D");
}

}  // namespace

void bind_flat_order(Program& p, const FlatOrder& o) {
  // Always, an empty order too: its ends then say no group has a primitive, rather than
  // leaving another scene's in a program they share. (Not reachable through the loader,
  // which refuses a zero-area triangle, the one shape a packing can drop.)
  std::array<int, kFlatOrderMax> order{};  // whole ivec4s
  std::copy(o.prims.begin(), o.prims.end(), order.begin());
  glUniform4iv(p.loc("u_flat_order"), GLsizei(std::max<size_t>(1, (o.prims.size() + 3) / 4)), order.data());
  glUniform1iv(p.loc("u_flat_end"), GLsizei(o.end.size()), o.end.data());
  PT_GL_CHECK("u_flat_order");
}

void SceneTextures::set(const Scene& scene, const PackedScene& p, StagedScene& staged, const MapArray* maps) {
  staged.upload(std::numeric_limits<int>::max());  // nothing left when staged ahead
  shape_tex_ = std::move(staged.shapes);
  material_tex_ = std::move(staged.materials);
  light_tex_ = std::move(staged.lights);
  node_tex_ = std::move(staged.nodes);
  prim_tex_ = std::move(staged.prims);
  vertex_tex_ = std::move(staged.vertices);
  if (maps) {
    maps_ = TextureArray(maps->width, maps->height, maps->layers, maps->texels.data());
    uv_tex_ = upload(pack_uvs(scene));
    texinfo_tex_ = upload(pack_texinfos(scene));
  } else {
    maps_ = TextureArray();
    uv_tex_ = Texture();
    texinfo_tex_ = Texture();
  }
  num_lights_ = p.lights.count();
  num_shapes_ = p.shapes.count();
  num_prims_ = p.prims.count();
  light_shapes_ = p.light_shape;
  flat_order_ = flat_order(scene, p);
  num_unbounded_ = p.unbounded;
  num_nodes_ = p.nodes.count();
  motion_bound_ = p.motion_bound;
  dot_weight_ = scene.dot_weight;
}

bool SceneTextures::update_values(const PackedScene& p, const std::vector<int>& light_shapes) {
  // The same shapes must be lights, in the same order (each light record names its shape).
  if (p.lights.count() != num_lights_ || p.shapes.count() != num_shapes_ || light_shapes != light_shapes_) return false;
  shape_tex_ = upload(p.shapes);
  material_tex_ = upload(p.materials);
  light_tex_ = upload(p.lights);
  return true;
}

void SceneTextures::update_rows(const PackedScene& p, const std::vector<int>& prims, const std::vector<int>& nodes) {
  upload_rows(prim_tex_, p.prims, prims);
  upload_rows(node_tex_, p.nodes, nodes);
}

void SceneTextures::set_environment(const Environment& env, RenderMode mode) {
  if (env.map != env_.map || env.color != env_.color || env.rotation != env_.rotation || env.intensity != env_.intensity)
    sh_valid_ = false;
  env_ = env;
  env_color_ = env.color;
  if (env.map) {
    // Re-upload only for a different image: rotation and intensity are uniforms.
    if (env_source_ != env.map) {
      const EnvDistribution d = build_env_distribution(*env.map);
      env_tex_ = Texture(env.map->width, env.map->height, GL_RGBA32F, env.map->rgba.data());
      env_cdf_tex_ = Texture(env.map->width + 1, env.map->height + 1, GL_RGBA32F, d.cdf_texels.data());
      env_size_ = glm::ivec2(env.map->width, env.map->height);
      env_integral_ = d.integral;
      env_source_ = env.map;
    }
    env_rotation_ = glm::radians(env.rotation);
    env_intensity_ = env.intensity;
  } else {
    // No map: its textures and the image go (the long-use test watches for what stays).
    env_tex_ = Texture();
    env_cdf_tex_ = Texture();
    env_source_.reset();
  }
  update_sh(mode);
}

void SceneTextures::update_sh(RenderMode mode) {
  if (mode != RenderMode::SphericalHarmonics || sh_valid_) return;
  sh_ = project_sh(env_);
  sh_valid_ = true;
}

void SceneTextures::bind(Program& p, RenderMode mode) const {
  p.set("u_shape_data", int(kShapeUnit));
  p.set("u_material_data", int(kMaterialUnit));
  p.set("u_light_data", int(kLightUnit));
  p.set("u_node_data", int(kNodeUnit));
  p.set("u_prim_data", int(kPrimUnit));
  p.set("u_vertex_data", int(kVertexUnit));
  p.set("u_num_prims", num_prims_);
  p.set("u_num_unbounded", num_unbounded_);
  bind_flat_order(p, flat_order_);
  p.set("u_num_nodes", num_nodes_);
  p.set("u_num_lights", num_lights_);
  p.set("u_dot_weight", dot_weight_ ? 1 : 0);
  p.set("u_env_color", env_color_);
  if (mode == RenderMode::SphericalHarmonics) glUniform3fv(p.loc("u_sh"), 9, &sh_[0].x);
  if (env_tex_.id()) {
    env_tex_.bind(kEnvUnit);
    env_cdf_tex_.bind(kEnvCdfUnit);
    p.set("u_env_map", int(kEnvUnit));
    p.set("u_env_cdf", int(kEnvCdfUnit));
    p.set("u_env_size", env_size_);
    p.set("u_env_rotation", env_rotation_);
    p.set("u_env_intensity", env_intensity_);
    p.set("u_env_integral", env_integral_);
  }
  if (maps_.id()) {
    maps_.bind(kMapsUnit);
    uv_tex_.bind(kUvUnit);
    texinfo_tex_.bind(kTexinfoUnit);
    p.set("u_maps", int(kMapsUnit));
    p.set("u_uv_data", int(kUvUnit));
    p.set("u_texinfo_data", int(kTexinfoUnit));
  }
  shape_tex_.bind(kShapeUnit);
  material_tex_.bind(kMaterialUnit);
  light_tex_.bind(kLightUnit);
  node_tex_.bind(kNodeUnit);
  prim_tex_.bind(kPrimUnit);
  vertex_tex_.bind(kVertexUnit);
}

}  // namespace pt
