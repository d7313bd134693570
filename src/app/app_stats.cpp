// The App's test hooks and link: the stats and load status as JSON (web/index.html:
// ptStats(), ptLoadStatus()) and the current view as URL parameters.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/app.h"

namespace pt {

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
  return q;
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
  j += ",\"bandRows\":" + std::to_string(settings_.band_rows);
  j += ",\"bandColumns\":" + std::to_string(settings_.band_columns);
  j += ",\"width\":" + std::to_string(renderer_->width());
  j += ",\"height\":" + std::to_string(renderer_->height());
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
  j += ",\"selected\":" + std::to_string(selected_);
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

std::string App::load_status_json() const {
  return "{\"samples\":" + std::to_string(renderer_->samples()) + ",\"scene\":" + json_string(scene_.path) +
         ",\"error\":" + (error_ ? json_string(*error_) : std::string("null")) + ",\"loads\":" + std::to_string(loads_) + "," +
         load_fields() + "}";
}

}  // namespace pt
