// The Renderer facade (render/renderer.h): a scene set at once, edits of values and moved
// shapes, settings, and one draw of a tile through the program cache, the scene's textures
// and the accumulator.
#include "render/renderer.h"

#include <algorithm>
#include <optional>

#include "gpu/gl_objects.h"
#include "render/camera.h"
#include "render/image_maps.h"
#include "render/light_select.h"
#include "render/packing.h"
#include "render/staged_scene.h"
#include "render/texture_units.h"

namespace pt {
namespace {

GlLimits checked_limits() {
  GlLimits l = GlLimits::query();
  l.require_units(int(kNumTextureUnits), "the integrator");
  l.require_draw_buffers(2, "the accumulator (radiance and statistics targets)");  // 4 with the auxiliaries
  return l;
}

GLuint make_vertex_array() {
  GLuint vao = 0;
  glGenVertexArrays(1, &vao);
  if (vao) gl_objects::created(gl_objects::kVertexArray);
  return vao;
}

}  // namespace

Renderer::Renderer() : limits_(checked_limits()), vao_(make_vertex_array()), display_(RenderSettings{}.tonemap) {
#ifndef __EMSCRIPTEN__
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  compute_supported_ = (major > 3 || (major == 3 && minor >= 1)) && accum_.format() == GL_RGBA32F;
#endif
  accum_.set_vertex_array(vao_);
  resize(1, 1);
}

Renderer::~Renderer() {
  if (vao_) {
    if (!gl_objects::stale(vao_made_in_)) glDeleteVertexArrays(1, &vao_);
    gl_objects::deleted(gl_objects::kVertexArray);
  }
}

// A scene's features with auto's choice of traversal (accel/accel_choice.h), from its
// packed BVH when there is one.
Features Renderer::scene_features(const Scene& scene, const PackedScene* packed) {
  Features f = Features::of(scene);
  f.flat = accel_costs(scene, packed).flat();
  return f;
}

Features Renderer::features_for(const Scene& scene, RenderMode mode) const { return with_settings(scene_features(scene, nullptr), mode); }

// The renderer's own settings on top of a scene's features: the one place they are set.
Features Renderer::with_settings(Features f, RenderMode mode) const {
  f.mode = mode;
  f.compute = using_compute();
  f.aux = settings_.aux;
  f.adaptive = settings_.adaptive;
  f.count_ops = settings_.count_ops;
  if (settings_.accel != Accel::Auto) f.flat = settings_.accel == Accel::Flat;  // else the scene's rule (scene_features)
  if (!settings_.gltf_ms) f.material_features &= ~feature_bit(MaterialFeature::GltfMs);  // the spec's single scattering
  return f;
}

bool Renderer::program_ready(const Scene& scene) { return program_ready(scene, settings_.mode); }

bool Renderer::program_ready(const Scene& scene, RenderMode mode) { return programs_.ready(features_for(scene, mode)); }

void Renderer::select_program() {
  ProgramCache::Entry& e = programs_.get(with_settings(features_, settings_.mode));
  integrator_ = &e.program;
  source_ = &e.source;
  tables_.attach(e.program);
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
  features_ = scene_features(scene, &p);
  // Image maps first: a scene beyond this GPU's texture limits throws before anything changes.
  const bool textured = features_.image_maps();
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
  scene_.set(scene, p, *staged, textured ? &maps : nullptr);
  seal_lo_ = p.seal_lo, seal_hi_ = p.seal_hi;
  bvh_stats_ = {p.prims.count() - p.unbounded, p.nodes.count(), p.bvh_depth, p.bvh_build_ms};
  scene_.set_environment(scene.environment, settings_.mode);
  camera_ = scene.camera;
  restart();
}

bool Renderer::update_geometry(const Scene& scene, const PackedScene& p, const std::vector<int>& prims, const std::vector<int>& nodes) {
  if (p.prims.count() != scene_.prims() || p.nodes.count() != scene_.nodes() || !update_values(scene)) return false;
  scene_.update_rows(p, prims, nodes);
  return true;
}

bool Renderer::update_values(const Scene& scene) {
  const Features f = Features::of(scene);  // the program must stay the same
  if (!have_scene_ || f.shapes != features_.shapes || f.materials != features_.materials || f.lights != features_.lights || f.punctual != features_.punctual ||
      f.env_map != features_.env_map || f.motion != features_.motion)
    return false;
  // Another environment map is an upload of it (set_environment), when it fits this GPU;
  // else set_scene says why.
  if (const auto& m = scene.environment.map; m && std::max(m->width, m->height) + 1 > limits_.max_texture_size) return false;
  const PackedScene v = pack_values(scene);
  if (!scene_.update_values(v, light_shapes(scene))) return false;
  seal_lo_ = v.seal_lo, seal_hi_ = v.seal_hi;
  scene_.set_environment(scene.environment, settings_.mode);
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
  a.denoise = b.denoise;
  a.denoise_estimate = b.denoise_estimate;
  a.coarse = b.coarse;  // what the display shows first, not the full-resolution estimate
  if (!(a == b)) restart();
  const bool new_mode = s.mode != settings_.mode || s.compute != settings_.compute || s.aux != settings_.aux || s.adaptive != settings_.adaptive ||
                        s.accel != settings_.accel || s.count_ops != settings_.count_ops;
  settings_ = s;
  accum_.set_aux(s.aux);
  accum_.set_adaptive(s.adaptive);
  accum_.set_count_ops(s.count_ops);
  for (Accumulator& c : coarse_) {  // the same program draws them: with adaptive sampling it reads
    c.set_aux(s.aux);               // tile counts, which a coarse level's single sweep keeps uniform
    c.set_adaptive(s.adaptive);     // (before uniform_spp every tile alike: render/adaptive.h)
  }
  if (new_mode && have_scene_) {
    select_program();
    scene_.update_sh(settings_.mode);
  }
}

void Renderer::resize(int width, int height) {
  if (width == accum_.width() && height == accum_.height()) return;
  limits_.require_texture(width, height, "a " + std::to_string(width) + "x" + std::to_string(height) + " render");
  if (width > limits_.max_viewport[0] || height > limits_.max_viewport[1])
    throw GlError("a " + std::to_string(width) + "x" + std::to_string(height) + " render exceeds GL_MAX_VIEWPORT_DIMS " +
                  std::to_string(limits_.max_viewport[0]) + "x" + std::to_string(limits_.max_viewport[1]));
  accum_.resize(width, height);
  for (int l = 0; l < CoarseLadder::kLevels; ++l)
    coarse_[l].resize(CoarseLadder::level_size(width, l), CoarseLadder::level_size(height, l));
}

const CoarseLadder& Renderer::ladder() const {
  if (ladder_epoch_ != accum_.epoch()) {  // any restart of the estimate (a resize, set_aux too)
    ladder_epoch_ = accum_.epoch();
    ladder_.restart();
  }
  return ladder_;
}

int Renderer::shown_divisor() const {
  const int l = coarse_on() ? ladder().shown(samples()) : -1;
  return l < 0 ? 1 : CoarseLadder::divisor(l);
}

void Renderer::coarse_step() {
  const int l = ladder_.drawing();
  Accumulator& c = coarse_[l];
  // One sample per pixel, one sweep per level, in tiles of the pacer's size in pixels.
  RenderSettings s = settings_;
  s.spp_per_pass = 1;
  s.sample_limit = 0;
  CoarseLadder::draw_size(settings_.band_rows, settings_.band_columns, width(), height(), c.width(), c.height(), s.band_rows,
                          s.band_columns);
  if (!c.mid_sweep()) c.restart();  // a level is one sweep: its mean starts from nothing
  const Accumulator::Tile t = c.begin_tile(s);
  draw_tile(c, t, CoarseLadder::divisor(l));
  ladder_.drew();
  if (c.end_tile(t) > 0) ladder_.level_done();
}

int Renderer::step() {
  last_draw_samples_ = 0;
  if (!integrator_ || converged()) return 0;
  if (coarse_on() && accum_.samples() == 0 && !accum_.mid_sweep() && ladder().drawing() >= 0) {
    coarse_step();
    return 0;
  }
  const Accumulator::Tile t = accum_.begin_tile(settings_);
  draw_tile(accum_, t, 1);
  const int added = accum_.end_tile(t);
  if (added > 0) error_.sweep_done(accum_);
  return added;
}

void Renderer::draw_tile(Accumulator& a, const Accumulator::Tile& t, int divisor) {
  const int w = width(), h = height();  // the full image's: its frame and aspect
  Program& p = *integrator_;
  p.use();
  const CameraBasis cb = camera_basis(camera_, float(w) / float(h));
  p.set("u_max_bounces", settings_.max_bounces);
  p.set("u_nee", settings_.nee ? 1 : 0);
  p.set("u_sampler", settings_.sampler);
  p.set("u_cam_pos", cb.position);
  p.set("u_cam_fwd", cb.forward);
  p.set("u_cam_right", cb.right);
  p.set("u_cam_up", cb.up);
  // Pixel px of a coarse level covers the full image's [px, px + 1) x divisor.
  p.set("u_size", glm::vec2(float(w), float(h)) / float(divisor));
  p.set("u_lens_radius", camera_.aperture);
  p.set("u_lights_uniform", camera_sealed_off(seal_lo_, seal_hi_, camera_.position, camera_.aperture) ? 1 : 0);
  p.set("u_focal_distance", camera_.focal_distance);
  // Moving spheres are bounded over [0, motion_bound].
  p.set("u_shutter", std::min(camera_.shutter, scene_.motion_bound()));
  scene_.bind(p, settings_.mode);
  tables_.bind();
  a.bind_inputs(p, t);
  if (using_compute()) {
#ifndef __EMSCRIPTEN__
    a.bind_images();
    p.set("u_origin", glm::ivec2(t.x0, t.y0));
    p.set("u_end", glm::ivec2(t.x1, t.y1));
    if (a.ordered_dispatch(t)) {  // tile by tile, the most samples first (render/adaptive.h)
      const TileCounts& c = *a.tile_counts();
      const int per_side = c.tile() / 8;
      p.set("u_ordered", 1);
      glDispatchCompute(GLuint(per_side * per_side * c.tiles_x()), GLuint(c.tiles_y()), 1);
    } else {
      if (a.adaptive()) p.set("u_ordered", 0);
      glDispatchCompute(GLuint((t.x1 - t.x0 + 7) / 8), GLuint((t.y1 - t.y0 + 7) / 8), 1);
    }
    PT_GL_CHECK("glDispatchCompute (integrator)");
    // What reads the images next: texelFetch (the next pass), blits and glReadPixels.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
#endif
  } else {
    glBindFramebuffer(GL_FRAMEBUFFER, a.target_fbo());
    glViewport(0, 0, a.width(), a.height());  // the target's size: gl_FragCoord stays in its pixels
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    if (t.whole) {
      glDisable(GL_SCISSOR_TEST);
    } else {
      glEnable(GL_SCISSOR_TEST);
      glScissor(t.x0, t.y0, t.x1 - t.x0, t.y1 - t.y0);
    }
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    PT_GL_CHECK("glDrawArrays (integrator)");
  }
  last_draw_samples_ = long(t.x1 - t.x0) * (t.y1 - t.y0) * t.spp;
}

void Renderer::display(int x, int y) const {
  if (const int d = shown_divisor(); d > 1) {
    const Texture& coarse = coarse_[ladder().shown(samples())].radiance();
    display_.draw(coarse, settings_.tonemap, settings_.exposure, x, y, vao_, d, width(), height());
    return;
  }
  display_.draw(shown(), settings_.tonemap, settings_.exposure, x, y, vao_);
}

const Texture& Renderer::shown() const {
  if (!settings_.aux || settings_.denoise <= 0.0f || samples() == 0) return accum_.radiance();
  if (sliced_) return denoised_samples() > 0 ? denoiser_.output() : accum_.radiance();
  // Filtered again at 1, 2, 4, ... samples of an image, not at every sweep: a run costs
  // about one sample of path tracing on a CPU rasteriser (docs/denoise.md).
  if (denoised_.epoch != accum_.epoch() || samples() >= 2 * denoised_.samples || denoiser_.output().width() != width() ||
      denoiser_.output().height() != height())
    denoised(settings_.denoise);
  return denoiser_.output();
}

const Texture& Renderer::denoised(float weight) const {
  if (denoised_.epoch != accum_.epoch() || denoised_.samples != samples() || denoised_.weight != weight ||
      denoised_.estimate != settings_.denoise_estimate ||
      denoiser_.output().width() != width() || denoiser_.output().height() != height()) {
    denoiser_.run(accum_, weight, vao_, settings_.denoise_estimate);
    denoised_ = {accum_.epoch(), samples(), weight, settings_.denoise_estimate};
    job_ = denoised_;  // a sliced run it interrupted is dropped; the next is due at twice these samples
  }
  return denoiser_.output();
}

int Renderer::denoised_samples() const {
  if (!settings_.aux || settings_.denoise <= 0.0f || samples() == 0) return 0;
  const bool current = denoised_.epoch == accum_.epoch() && denoiser_.output().width() == width() && denoiser_.output().height() == height();
  return current ? denoised_.samples : 0;
}

void Renderer::advance_denoiser(double units) {
  if (!sliced_ || !settings_.aux || settings_.denoise <= 0.0f || samples() == 0) return;
  const DenoiseInputs in = DenoiseInputs::of(accum_);
  const bool same = job_.epoch == accum_.epoch() && denoiser_.output().width() == width() && denoiser_.output().height() == height();
  if (!same || (!denoiser_.running() && samples() >= 2 * job_.samples)) {  // a restart (the run in progress dropped), or due
    denoiser_.start(in, settings_.denoise, settings_.denoise_estimate);
    job_ = {accum_.epoch(), samples(), settings_.denoise, settings_.denoise_estimate};
  }
  if (denoiser_.running() && denoiser_.advance(in, vao_, units)) denoised_ = job_;
}

std::vector<float> Renderer::read_denoised(float weight) const {
  denoised(weight);
  return denoiser_.read();
}

std::vector<double> Renderer::time_denoiser(float weight, int runs, const DenoiseParams* params) const {
  const DenoiseParams kept = denoiser_.params;
  if (params) denoiser_.params = *params;
  const std::vector<double> ms = denoiser_.time(accum_, weight, vao_, runs, settings_.denoise_estimate);
  denoiser_.params = kept;
  denoised_ = job_ = params ? Filtered{} : Filtered{accum_.epoch(), samples(), weight, settings_.denoise_estimate};
  return ms;
}

std::vector<float> Renderer::read_radiance() const { return accum_.read_radiance(); }
std::vector<float> Renderer::read_variance() const { return accum_.read_variance(); }

std::vector<uint8_t> Renderer::read_display() const {
  if (const int d = shown_divisor(); d > 1)
    return display_.read(coarse_[ladder().shown(samples())].radiance(), settings_.tonemap, settings_.exposure, vao_, d, width(), height());
  return display_.read(shown(), settings_.tonemap, settings_.exposure, vao_);
}

}  // namespace pt
