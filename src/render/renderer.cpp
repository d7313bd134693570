#include "render/renderer.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "render/camera.h"
#include "render/environment.h"
#include "render/image_maps.h"
#include "render/packing.h"
#include "render/staged_scene.h"

namespace pt {
namespace {

enum Unit {
  kAccumUnit = 0, kShapeUnit = 1, kMaterialUnit = 2, kLightUnit = 3, kStatsUnit = 4, kEnvUnit = 5, kEnvCdfUnit = 6,
  kNodeUnit = 7, kPrimUnit = 8, kVertexUnit = 9, kMapsUnit = 10, kUvUnit = 11
};

// The sizes were checked against limits_ in set_scene, before any state changed (uv
// records take 2 texels per shape where shape records take 4: covered by the shapes' check).
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

Renderer::Renderer() : limits_(GlLimits::query()) {
  limits_.require_units(int(kUvUnit) + 1, "the integrator");
  limits_.require_draw_buffers(2, "the accumulator (radiance and statistics targets)");
  glGenVertexArrays(1, &vao_);
  display_[int(settings_.tonemap)] = Program(fullscreen_vertex(), generate_display(settings_.tonemap));
  // Float render targets need EXT_color_buffer_float on WebGL 2 / GLES 3.0. Without it we
  // try half floats (the running mean keeps ~3 significant digits), and otherwise stop
  // with a message: an 8-bit accumulator cannot hold a converging HDR estimate.
  for (GLenum fmt : {GLenum(GL_RGBA32F), GLenum(GL_RGBA16F)}) {
    Texture t(4, 4, fmt, nullptr);
    Framebuffer f(t);
    if (f.complete()) {
      accum_format_ = fmt;
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
#ifndef __EMSCRIPTEN__
      GLint major = 0, minor = 0;
      glGetIntegerv(GL_MAJOR_VERSION, &major);
      glGetIntegerv(GL_MINOR_VERSION, &minor);
      compute_supported_ = (major > 3 || (major == 3 && minor >= 1)) && fmt == GL_RGBA32F;
#endif
      resize(1, 1);
      return;
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  throw GlError("this GPU cannot render to floating-point textures (EXT_color_buffer_float is missing)");
}

Renderer::~Renderer() {
  if (vao_) glDeleteVertexArrays(1, &vao_);
}

// Starts (or finds) the program for f; true once it is built (a build in progress does
// not block where KHR_parallel_shader_compile exists).
bool Renderer::program_ready_for(const Features& f) {
  auto& slot = cache_[f.key()];
  if (!slot) {
    auto c = std::make_unique<CachedProgram>();
    c->source = generate_integrator(f);
#ifndef __EMSCRIPTEN__
    if (f.compute) c->program = Program::start_compute(c->source);
    else
#endif
      c->program = Program::start(fullscreen_vertex(), c->source);
    slot = std::move(c);
  }
  return slot->program.completed();
}

bool Renderer::program_ready(const Scene& scene) { return program_ready(scene, settings_.mode); }

bool Renderer::program_ready(const Scene& scene, RenderMode mode) {
  Features f = Features::of(scene);
  f.mode = mode;
  f.compute = using_compute();
  return program_ready_for(f);
}

void Renderer::select_program() {
  Features f = features_;
  f.mode = settings_.mode;
  f.compute = using_compute();
  program_ready_for(f);
  auto& slot = cache_[f.key()];
  try {
    slot->program.finish();
  } catch (...) {
    cache_.erase(f.key());  // a failed build is not cached: the next try reports it again
    throw;
  }
  integrator_ = &slot->program;
  source_ = &slot->source;
}

void Renderer::update_sh() {
  if (settings_.mode != RenderMode::SphericalHarmonics || sh_valid_) return;
  sh_ = project_sh(env_);
  sh_valid_ = true;
}

void Renderer::set_scene(const Scene& scene) { set_scene(scene, pack_scene(scene)); }

void Renderer::set_scene(const Scene& scene, const PackedScene& p, StagedScene* staged, const RenderSettings* settings) {
  // Everything that can fail (packing, limits, image maps, compiling) happens before any
  // state changes: a scene that cannot be rendered leaves the previous one and its samples.
  // The record textures: staged ahead (a page), else staged here in one go; the
  // constructor checks them against the limits.
  std::optional<StagedScene> own;
  if (!staged || !staged->done()) staged = &own.emplace(limits_, p);
  if (scene.environment.map)
    limits_.require_texture(scene.environment.map->width + 1, scene.environment.map->height + 1, "the environment map");
  const Features old = features_;
  features_ = Features::of(scene);
  // Image maps first: a scene beyond this GPU's texture limits throws before anything changes.
  const bool textured = features_.has(MaterialKind::Textured);
  MapArray maps;
  const RenderSettings old_settings = settings_;
  try {
    if (textured) maps = build_map_array(scene, TextureArray::max_size(), TextureArray::max_layers());
    if (settings) settings_ = *settings;
    select_program();
  } catch (...) {
    features_ = old;  // nothing changed
    settings_ = old_settings;
    throw;
  }
  have_scene_ = true;
  staged->upload(std::numeric_limits<int>::max());  // nothing left when staged ahead
  shape_tex_ = std::move(staged->shapes);
  material_tex_ = std::move(staged->materials);
  light_tex_ = std::move(staged->lights);
  node_tex_ = std::move(staged->nodes);
  prim_tex_ = std::move(staged->prims);
  vertex_tex_ = std::move(staged->vertices);
  if (textured) {
    maps_ = TextureArray(maps.width, maps.height, maps.layers, maps.texels.data());
    uv_tex_ = upload(pack_uvs(scene));
  } else {
    maps_ = TextureArray();
    uv_tex_ = Texture();
  }
  num_lights_ = p.lights.count();
  num_shapes_ = p.shapes.count();
  num_prims_ = p.prims.count();
  light_shapes_.clear();
  for (int i = 0; i < num_lights_; ++i) light_shapes_.push_back(int(p.lights.get(i, light_rec::shape)));
  num_unbounded_ = p.unbounded;
  num_nodes_ = p.nodes.count();
  motion_bound_ = p.motion_bound;
  bvh_stats_ = {p.prims.count() - p.unbounded, p.nodes.count(), p.bvh_depth, p.bvh_build_ms};
  dot_weight_ = scene.dot_weight;
  set_environment(scene.environment);
  camera_ = scene.camera;
  restart();
}

void Renderer::set_environment(const Environment& env) {
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
  }
  update_sh();
}

bool Renderer::update_geometry(const Scene& scene, const PackedScene& p, const std::vector<int>& prims, const std::vector<int>& nodes) {
  if (p.prims.count() != num_prims_ || p.nodes.count() != num_nodes_ || !update_values(scene)) return false;
  upload_rows(prim_tex_, p.prims, prims);
  upload_rows(node_tex_, p.nodes, nodes);
  return true;
}

bool Renderer::update_values(const Scene& scene) {
  const Features f = Features::of(scene);  // the program must stay the same
  if (!have_scene_ || f.shapes != features_.shapes || f.materials != features_.materials || f.lights != features_.lights ||
      f.env_map != features_.env_map || f.motion != features_.motion)
    return false;
  // Another environment map is an upload of it (set_environment), when it fits this GPU;
  // else set_scene says why.
  if (const auto& m = scene.environment.map; m && std::max(m->width, m->height) + 1 > limits_.max_texture_size) return false;
  PackedScene p = pack_values(scene);
  if (p.lights.count() != num_lights_ || p.shapes.count() != num_shapes_) return false;
  // The same shapes must be lights, in the same order (each light record names its shape).
  for (int i = 0; i < num_lights_; ++i)
    if (int(p.lights.get(i, light_rec::shape)) != light_shapes_[size_t(i)]) return false;
  shape_tex_ = upload(p.shapes);
  material_tex_ = upload(p.materials);
  light_tex_ = upload(p.lights);
  set_environment(scene.environment);
  restart();
  return true;
}

void Renderer::set_camera(const Camera& camera) {
  camera_ = camera;
  restart();
}

void Renderer::set_settings(const RenderSettings& s) {
  RenderSettings a = s, b = settings_;
  a.tonemap = b.tonemap;  // display-only fields do not invalidate the estimate
  a.exposure = b.exposure;
  a.sample_limit = b.sample_limit;
  a.spp_per_pass = b.spp_per_pass;
  a.band_rows = b.band_rows;
  a.band_columns = b.band_columns;
  if (!(a == b)) restart();
  const bool new_mode = s.mode != settings_.mode || s.compute != settings_.compute;
  settings_ = s;
  if (new_mode && have_scene_) {
    select_program();
    update_sh();
  }
}

void Renderer::resize(int width, int height) {
  if (width == width_ && height == height_) return;
  limits_.require_texture(width, height, "a " + std::to_string(width) + "x" + std::to_string(height) + " render");
  if (width > limits_.max_viewport[0] || height > limits_.max_viewport[1])
    throw GlError("a " + std::to_string(width) + "x" + std::to_string(height) + " render exceeds GL_MAX_VIEWPORT_DIMS " +
                  std::to_string(limits_.max_viewport[0]) + "x" + std::to_string(limits_.max_viewport[1]));
  width_ = width;
  height_ = height;
  for (int i = 0; i < 2; ++i) {
    accum_[i] = Texture(width, height, accum_format_, nullptr);
    stats_[i] = Texture(width, height, accum_format_, nullptr);
    fbo_[i] = Framebuffer(accum_[i], stats_[i]);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  restart();
}

int Renderer::step() {
  last_draw_samples_ = 0;
  if (!integrator_ || converged()) return 0;
  if (next_row_ == 0 && next_column_ == 0) {  // a sweep starts: its sample count is fixed until it ends
    sweep_spp_ = settings_.spp_per_pass < 1 ? 1 : settings_.spp_per_pass;
    if (settings_.sample_limit > 0 && samples_ + sweep_spp_ > settings_.sample_limit)
      sweep_spp_ = settings_.sample_limit - samples_;
  }
  const int spp = sweep_spp_;
  if (next_column_ == 0) {  // a band starts: its rows hold until its last tile is drawn
    const int rows = settings_.band_rows > 0 ? std::min(settings_.band_rows, height_) : height_;
    band_end_ = std::min(height_, next_row_ + rows);
  }
  const int columns = settings_.band_columns > 0 ? std::min(settings_.band_columns, width_) : width_;
  const int x0 = next_column_, x1 = std::min(width_, x0 + columns);
  const int y0 = next_row_, y1 = band_end_;
  const bool whole = x0 == 0 && y0 == 0 && x1 == width_ && y1 == height_;
  if (needs_clear_) {  // rows not yet swept show black, not another scene's image
    const float zero[4] = {0, 0, 0, 0};
    for (Framebuffer& f : fbo_) {
      glBindFramebuffer(GL_FRAMEBUFFER, f.id());
      glClearBufferfv(GL_COLOR, 0, zero);
      glClearBufferfv(GL_COLOR, 1, zero);
      PT_GL_CHECK("glClearBufferfv");
    }
    needs_clear_ = false;
  }
  Program& p = *integrator_;
  p.use();
  const CameraBasis cb = camera_basis(camera_, float(width_) / float(height_));
  p.set("u_accum", int(kAccumUnit));
  p.set("u_stats_in", int(kStatsUnit));
  p.set("u_shape_data", int(kShapeUnit));
  p.set("u_material_data", int(kMaterialUnit));
  p.set("u_light_data", int(kLightUnit));
  p.set("u_node_data", int(kNodeUnit));
  p.set("u_prim_data", int(kPrimUnit));
  p.set("u_vertex_data", int(kVertexUnit));
  p.set("u_num_unbounded", num_unbounded_);
  p.set("u_num_nodes", num_nodes_);
  p.set("u_num_lights", num_lights_);
  p.set("u_max_bounces", settings_.max_bounces);
  p.set("u_nee", settings_.nee ? 1 : 0);
  p.set("u_sampler", settings_.sampler);
  p.set("u_dot_weight", dot_weight_ ? 1 : 0);
  p.set("u_spp", spp);
  p.set("u_sample_base", samples_);
  p.set("u_blend", float(spp) / float(samples_ + spp));
  p.set("u_cam_pos", cb.position);
  p.set("u_cam_fwd", cb.forward);
  p.set("u_cam_right", cb.right);
  p.set("u_cam_up", cb.up);
  p.set("u_size", glm::vec2(float(width_), float(height_)));
  p.set("u_lens_radius", camera_.aperture);
  p.set("u_focal_distance", camera_.focal_distance);
  p.set("u_shutter", std::min(camera_.shutter, motion_bound_));  // moving spheres are bounded over [0, motion_bound_]
  p.set("u_env_color", env_color_);
  if (settings_.mode == RenderMode::SphericalHarmonics) glUniform3fv(p.loc("u_sh"), 9, &sh_[0].x);
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
    p.set("u_maps", int(kMapsUnit));
    p.set("u_uv_data", int(kUvUnit));
  }
  accum_[cur_].bind(kAccumUnit);
  stats_[cur_].bind(kStatsUnit);
  shape_tex_.bind(kShapeUnit);
  material_tex_.bind(kMaterialUnit);
  light_tex_.bind(kLightUnit);
  node_tex_.bind(kNodeUnit);
  prim_tex_.bind(kPrimUnit);
  vertex_tex_.bind(kVertexUnit);
  if (using_compute()) {
#ifndef __EMSCRIPTEN__
    glBindImageTexture(0, accum_[1 - cur_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, stats_[1 - cur_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    p.set("u_origin", glm::ivec2(x0, y0));
    p.set("u_end", glm::ivec2(x1, y1));
    glDispatchCompute(GLuint((x1 - x0 + 7) / 8), GLuint((y1 - y0 + 7) / 8), 1);
    PT_GL_CHECK("glDispatchCompute (integrator)");
    // What reads the images next: texelFetch (the next pass), blits and glReadPixels.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
#endif
  } else {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_[1 - cur_].id());
    glViewport(0, 0, width_, height_);  // full size: gl_FragCoord stays in image pixels
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    if (whole) {
      glDisable(GL_SCISSOR_TEST);
    } else {
      glEnable(GL_SCISSOR_TEST);
      glScissor(x0, y0, x1 - x0, y1 - y0);
    }
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    PT_GL_CHECK("glDrawArrays (integrator)");
  }
  if (whole) {
    cur_ = 1 - cur_;
  } else {
    // Copy the tile back into the texture it read: the pair agrees again on these pixels,
    // so later tiles and sweeps read consistent data without a swap.
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_[1 - cur_].id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_[cur_].id());
    for (int a = 0; a < 2; ++a) {
      const GLenum bufs[2] = {a == 0 ? GLenum(GL_COLOR_ATTACHMENT0) : GLenum(GL_NONE),
                              a == 1 ? GLenum(GL_COLOR_ATTACHMENT1) : GLenum(GL_NONE)};
      glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + a));
      glDrawBuffers(2, bufs);
      glBlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      PT_GL_CHECK("glBlitFramebuffer (tile copy-back)");
    }
    const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, both);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  last_draw_samples_ = long(x1 - x0) * (y1 - y0) * spp;
  if (x1 < width_) {
    next_column_ = x1;
    return 0;
  }
  next_column_ = 0;
  next_row_ = y1 == height_ ? 0 : y1;
  if (next_row_ != 0) return 0;
  samples_ += spp;
  return spp;
}

void Renderer::display(int x, int y) const {
  Program& p = display_[int(settings_.tonemap)];
  if (!p.id()) p = Program(fullscreen_vertex(), generate_display(settings_.tonemap));
  p.use();
  p.set("u_accum", int(kAccumUnit));
  p.set("u_exposure", settings_.exposure);
  p.set("u_offset", glm::ivec2(x, y));
  accum_[cur_].bind(kAccumUnit);
  glViewport(x, y, width_, height_);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  PT_GL_CHECK("glDrawArrays (display)");
}

std::vector<float> Renderer::read_radiance() const {
  std::vector<float> out(size_t(width_) * height_ * 4);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_[cur_].id());
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, out.data());
  PT_GL_CHECK("glReadPixels (radiance)");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return out;
}

Renderer::Counters Renderer::counters() const {
  std::vector<float> px(size_t(width_) * height_ * 4);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_[cur_].id());
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, px.data());
  PT_GL_CHECK("glReadPixels (counters)");
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  Counters c;
  if (samples_ == 0) return c;
  for (size_t i = 0; i < px.size(); i += 4) {
    c.bad_samples += px[i];
    c.rays += px[i + 1];
  }
  return c;
}

std::vector<uint8_t> Renderer::read_display() const {
  Texture t(width_, height_, GL_RGBA8, nullptr);
  Framebuffer f(t);
  glBindFramebuffer(GL_FRAMEBUFFER, f.id());
  display(0, 0);
  std::vector<uint8_t> out(size_t(width_) * height_ * 4);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  PT_GL_CHECK("glReadPixels (display)");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return out;
}

}  // namespace pt
