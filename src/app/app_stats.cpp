// The App's test hooks and link: the stats and load status as JSON (web/index.html:
// ptStats(), ptLoadStatus()) and the current view as URL parameters; the estimated error
// (when it is read, the target's stop, the trend).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "app/app.h"
#include "gpu/gl_objects.h"

#ifdef __EMSCRIPTEN__
#include <malloc.h>
#endif

namespace pt {
namespace {

// The estimate's cadence (App::update_error): at 2, 4, 8, ... samples and at least every
// kEstimateEveryMs while samples grow, never twice within kEstimateMinMs, and never more
// often than keeps its cost (read-backs and the sums on the CPU) under 1/kEstimateShare
// of the time: in SwiftShader at 960x640 one estimate costs tens of ms (docs/benchmarks.md).
constexpr double kEstimateEveryMs = 1000.0, kEstimateMinMs = 250.0, kEstimateShare = 20.0;
constexpr size_t kTrendPoints = 8;  // the trend is fitted to the last this many estimates

}  // namespace

// Also used by app_interaction.cpp.
std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string App::view_query() const {
  const Camera& c = renderer_->camera();
  std::string scene = scene_.path;
  if (scene.rfind(options_.scene_root + "/", 0) == 0) scene = scene.substr(options_.scene_root.size() + 1);
  char cam[160];
  std::snprintf(cam, sizeof cam, "%.4g,%.4g,%.4g,%.4g,%.4g", double(c.position.x), double(c.position.y), double(c.position.z),
                double(c.yaw), double(c.pitch));
  std::string q = "scene=" + scene + "&cam=" + cam + "&bounces=" + std::to_string(settings_.max_bounces) +
                  "&tonemap=" + kToneMapNames[int(settings_.tonemap)];
  if (!auto_exposure_) {
    char e[32];
    std::snprintf(e, sizeof e, "%.4g", double(settings_.exposure));
    q += std::string("&exposure=") + e;
  }
  if (target_relmse_ > 0.0f) {
    char t[32];
    std::snprintf(t, sizeof t, "%.4g", double(target_relmse_));
    q += std::string("&target=") + t;
  }
  // The panel's two toggles, where they differ from the defaults (the URL's adaptive=, denoise=).
  if (settings_.adaptive != kAdaptiveByDefault) q += std::string("&adaptive=") + (settings_.adaptive ? "on" : "off");
  if (!denoise_) q += "&denoise=off";
  return q;
}

RenderSettings App::render_settings() const {
  RenderSettings s = settings_;
  // A due estimate needs a whole sweep: the draws stop at the end of the one in progress
  // (the limit is one sample past the count; a sweep adds at least one).
  const int n = renderer_->samples();
  const int stop = target_stop_at_ > 0 ? target_stop_at_ : estimate_due_ && renderer_->mid_sweep() ? n + 1 : 0;
  if (stop > 0 && (s.sample_limit <= 0 || stop < s.sample_limit)) s.sample_limit = stop;
  // s.aux is on in settings_ itself (App's constructor says why).
  // The blend's weight is measured by the filter from the estimate (Denoiser::run), the
  // last one scaled to the current samples as the error falls, 1/n.
  s.denoise = denoise_ ? 1.0f : 0.0f;
  s.denoise_estimate = error_history_.empty() || n <= 0 ? -1.0 : error_history_.back().rel_mse * error_history_.back().samples / n;
  return s;
}

float App::denoise_blend() const { return renderer_ && renderer_->denoised_samples() > 0 ? renderer_->denoiser().weight() : 1.0f; }

double App::time_denoise(bool regression) {
  if (!renderer_ || renderer_->samples() == 0) return -1.0;
  DenoiseParams p = renderer_->denoiser().params;
  p.min_samples = regression ? 0 : std::numeric_limits<int>::max();
  const std::vector<double> ms = renderer_->time_denoiser(1.0f, 3, &p);
  return ms[ms.size() / 2];
}

void App::update_error(double now_ms) {
  const int n = renderer_->samples();
  if (restart_ms_ != error_restart_ms_ || n < estimated_samples_) {  // a restart: a new image
    error_restart_ms_ = restart_ms_;
    error_history_.clear();
    target_stop_at_ = 0;
    estimate_due_ = false;
    next_estimate_at_ = 2;
    estimated_samples_ = 0;
  }
  const double since = now_ms - last_estimate_ms_;
  if (!estimate_due_ && target_stop_at_ == 0 && n >= 2 && n > estimated_samples_ && since >= kEstimateMinMs &&
      since >= kEstimateShare * estimate_ms_ && (n >= next_estimate_at_ || since >= kEstimateEveryMs))
    estimate_due_ = true;
  if (!estimate_due_ || renderer_->mid_sweep()) {
    renderer_->set_settings(render_settings());
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const ErrorEstimate e = renderer_->estimate_error();
  estimate_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  ++estimates_;
  estimate_due_ = false;
  last_estimate_ms_ = now_ms;
  estimated_samples_ = n;
  while (next_estimate_at_ <= n) next_estimate_at_ *= 2;
  if (e.known && std::isfinite(e.rel_mse)) {
    error_history_.push_back({std::max(0.0, now_ms - restart_ms_) * 1e-3, e.rel_mse, n});
    if (target_relmse_ > 0.0f && e.rel_mse <= double(target_relmse_)) target_stop_at_ = n;
  }
  renderer_->set_settings(render_settings());  // lifts the sweep's stop, or keeps the target's
}

// Least squares over the last kTrendPoints estimates in log-log; false below 3 of them.
bool App::error_trend(double& a, double& b) const {
  const size_t first = error_history_.size() > kTrendPoints ? error_history_.size() - kTrendPoints : 0;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int k = 0;
  for (size_t i = first; i < error_history_.size(); ++i) {
    const ErrorPoint& p = error_history_[i];
    if (p.seconds <= 0.0 || p.rel_mse <= 0.0) continue;
    const double x = std::log10(p.seconds), y = std::log10(p.rel_mse);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
    ++k;
  }
  const double d = k * sxx - sx * sx;
  if (k < 3 || d <= 1e-12) return false;
  b = (k * sxy - sx * sy) / d;
  a = (sy - b * sx) / k;
  return true;
}

// The estimate's fields of the stats (cheap: what update_error kept).
std::string App::error_fields() const {
  const bool known = !error_history_.empty();
  std::string j = "\"relMSE\":" + (known ? json_number(error_history_.back().rel_mse) : std::string("null"));
  j += ",\"relMSESamples\":" + std::to_string(known ? error_history_.back().samples : 0);
  j += ",\"targetRelMSE\":" + json_number(target_relmse_);
  j += ",\"targetReachedAt\":" + std::to_string(target_stop_at_);
  j += ",\"denoise\":" + json_number(denoise_ ? denoise_blend() : 0.0);
  j += ",\"denoisedSamples\":" + std::to_string(renderer_->denoised_samples());  // of the filtered image shown; 0: raw
  j += std::string(",\"adaptive\":") + (settings_.adaptive ? "true" : "false");
  // The coarse first image (render/coarse.h): the divisor of the image shown (1: full
  // resolution) and the coarse levels complete since the restart.
  j += ",\"epoch\":" + std::to_string(renderer_->accumulator().epoch());  // counts restarts
  j += ",\"shownDivisor\":" + std::to_string(renderer_->shown_divisor());
  j += ",\"coarseLevels\":" + std::to_string(renderer_->ladder().completed());
  j += ",\"estimates\":" + std::to_string(estimates_) + ",\"estimateMs\":" + json_number(estimate_ms_);
  j += ",\"errorHistory\":[";
  for (size_t i = 0; i < error_history_.size(); ++i)
    j += std::string(i ? "," : "") + "[" + json_number(error_history_[i].seconds) + "," + json_number(error_history_[i].rel_mse) + "," +
         std::to_string(error_history_[i].samples) + "]";
  return j + "]";
}

std::string App::stats_json() const {
  // The mean is computed on demand: a read-back stalls the GPU pipeline.
  const std::vector<float> px = renderer_->read_radiance();
  double sum[3] = {0, 0, 0};
  for (size_t i = 0; i + 3 < px.size(); i += 4)
    for (int k = 0; k < 3; ++k) sum[k] += px[i + k];
  const double n = std::max<double>(1.0, double(px.size() / 4));
  std::string j = "{";
  j += "\"samples\":" + std::to_string(renderer_->samples());
  j += ",\"sampleLimit\":" + std::to_string(settings_.sample_limit);
  j += ",\"view\":" + json_string(view_query());
  j += ",\"samplesPerSecond\":" + json_number(samples_per_second_);
  j += ",\"passesPerFrame\":" + std::to_string(pacer_.passes_per_frame());
  j += ",\"slowFrameMs\":" + json_number(FramePacer::kSlowDrawFrameMs);
  j += ",\"bandRows\":" + std::to_string(settings_.band_rows);
  j += ",\"bandColumns\":" + std::to_string(settings_.band_columns);
  j += ",\"width\":" + std::to_string(renderer_->width());
  j += ",\"height\":" + std::to_string(renderer_->height());
  // The traversal the program has (flat: no BVH) and the setting that chose it (accel=).
  j += std::string(",\"accel\":\"") + (renderer_->using_flat() ? "flat" : "bvh") + "\",\"accelSetting\":\"" + accel_name(settings_.accel) + "\"";
  j += std::string(",\"accumFormat\":") + (renderer_->accum_format() == GL_RGBA32F ? "\"rgba32f\"" : "\"rgba16f\"");
  j += ",\"mean\":[" + json_number(sum[0] / n) + "," + json_number(sum[1] / n) + "," + json_number(sum[2] / n) + "]";
  j += ",\"scene\":" + json_string(scene_.path);
  j += ",\"error\":" + (error_ ? json_string(*error_) : std::string("null"));
  j += ",\"renderer\":" + json_string(options_.gl_renderer);
  j += ",\"loads\":" + std::to_string(loads_);
  j += ",\"compiling\":" + std::string(loading_ && !preparing() ? "true" : "false");
  j += "," + load_fields();
  j += ",\"programsCompiled\":" + std::to_string(renderer_->programs_compiled());
  j += ",\"contextRestores\":" + std::to_string(context_restores_);
  j += ",\"renderScale\":" + json_number(render_scale_);
  j += ",\"files\":" + scene_files_json();
  j += "," + error_fields();
  j += ",\"selected\":" + std::to_string(selected_);
  // What the long-use test watches (tests/browser/endurance_test.mjs): live GL objects of
  // the wrappers, and the bytes of the wasm heap in use (dlmalloc's count; the heap's
  // size only grows, so it says nothing about leaks).
  j += ",\"glObjects\":{";
  for (int k = 0; k < gl_objects::kKinds; ++k)
    j += std::string(k ? "," : "") + "\"" + gl_objects::kNames[size_t(k)] + "\":" + std::to_string(gl_objects::live()[size_t(k)]);
  j += "}";
  // Programs started and not finished (each described): none once the page idles.
  j += ",\"pendingPrograms\":[";
  const std::vector<std::string> pending = renderer_->pending_programs();
  for (size_t i = 0; i < pending.size(); ++i) j += (i ? "," : "") + json_string(pending[i]);
  j += "]";
#ifdef __EMSCRIPTEN__
  j += ",\"heapUsed\":" + std::to_string(mallinfo().uordblks);
#endif
  if (selected_ >= 0) {
    const Shape& sh = scene_.shapes[size_t(selected_)];
    j += ",\"selectedKind\":" + json_string(info(sh.kind()).xml) + ",\"selectedLine\":" + std::to_string(sh.line);
  }
  return j + "}";
}

// The scene on its way (null when none) and the last one's preparation.
std::string App::load_fields() const {
  std::string j = "\"loading\":";
  if (loading_) {
    j += "{\"scene\":" + json_string(loading_->pipe->path()) + ",\"stage\":" + json_string(load_stage()) +
         ",\"progress\":" + json_number(load_progress()) + "}";
  } else {
    j += "null";
  }
  const Renderer::BvhStats& b = renderer_->bvh_stats();
  j += ",\"lastLoad\":{\"ms\":" + json_number(last_load_ms_) + ",\"readWorkMs\":" + json_number(last_read_ms_) +
       ",\"readSlices\":" + std::to_string(last_read_slices_) + ",\"packWorkMs\":" + json_number(last_pack_work_ms_) +
       ",\"slices\":" + std::to_string(last_slices_) + ",\"longestSliceMs\":" + json_number(last_longest_slice_ms_) +
       ",\"longestSliceStage\":" + json_string(last_longest_slice_stage_) +
       ",\"bvhBuildMs\":" + json_number(b.build_ms) + ",\"primitives\":" + std::to_string(b.primitives) + "}";
  return j;
}

double App::draw_pixels() const {
  return double(settings_.band_rows > 0 ? settings_.band_rows : renderer_->height()) *
         (settings_.band_columns > 0 ? settings_.band_columns : renderer_->width());
}

std::string App::load_status_json() const {
  return "{\"samples\":" + std::to_string(renderer_->samples()) + ",\"paths\":" + json_number(renderer_->paths()) +
         ",\"presents\":" + std::to_string(presents_) + ",\"compileMs\":" + json_number(renderer_->compile_ms()) + ",\"scene\":" + json_string(scene_.path) +
         ",\"accel\":" + (renderer_->using_flat() ? "\"flat\"" : "\"bvh\"") + ",\"drawPixels\":" + json_number(draw_pixels()) +
         ",\"error\":" + (error_ ? json_string(*error_) : std::string("null")) + ",\"loads\":" + std::to_string(loads_) + "," +
         load_fields() + "," + error_fields() + "}";
}

}  // namespace pt
