// `pathtracer watch SCENE.xml`: the scene author's reload loop, headless. Re-loads and
// re-renders whenever the scene file or a file it references (Scene::files, collected by
// the loader) changes; polls modification times (no inotify: works on every file system
// and editor, and an editor's save-by-rename is just another change). There is no window
// here, so the image goes to a file, replaced atomically (temporary file + rename) at 1,
// 2, 4, ... samples and at least once a second: a viewer that reloads the file sees the
// render refine. A broken edit prints `file:line: message` and keeps the last good scene
// (and its image); the next good edit resumes.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <thread>

#include "cli/options.h"
#include "core/image.h"
#include "gpu/gl.h"
#include "platform/egl.h"
#include "render/pacing.h"
#include "render/pipeline.h"

namespace pt::cli {
namespace {

volatile std::sig_atomic_t g_stop = 0;
void on_signal(int) { g_stop = 1; }

constexpr double kPollMs = 200.0;   // how often the files are looked at
constexpr double kDrawMs = 40.0;    // one draw's target time
constexpr double kWriteMs = 1000.0; // the image is written at least this often while refining

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// What identifies a version of a file: its modification time and size (missing: -1).
struct Stamp {
  long long mtime = -1;
  long long size = -1;
  bool operator==(const Stamp&) const = default;
};

Stamp stamp_of(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto t = fs::last_write_time(path, ec);
  if (ec) return {};
  const auto size = fs::file_size(path, ec);
  return {(long long)t.time_since_epoch().count(), ec ? -1 : (long long)size};
}

using Stamps = std::map<std::string, Stamp>;

Stamps stamps_of(const std::vector<std::string>& files) {
  Stamps s;
  for (const std::string& f : files) s[f] = stamp_of(f);
  return s;
}

bool ends_with(const std::string& s, const char* suffix) {
  const std::string x = suffix;
  return s.size() >= x.size() && s.compare(s.size() - x.size(), x.size(), x) == 0;
}

}  // namespace

int run_watch(const Options& o) {
  const std::string& out = o.outs.front();
  if (!ends_with(out, ".png") && !ends_with(out, ".hdr") && !ends_with(out, ".pfm"))
    usage_error("--out must end in .png, .hdr or .pfm");
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  HeadlessGl gl;
  std::printf("GL: %s\nwatching %s (Ctrl+C stops)\n", gl.description().c_str(), o.scene.c_str());
  std::fflush(stdout);
  Renderer r;
  r.resize(o.width, o.height);
  RenderSettings settings = o.settings;
  settings.sample_limit = o.spp;
  r.set_settings(settings);

  bool have_scene = false;
  int generation = 0;
  std::vector<std::string> watched = {o.scene};
  Stamps seen;  // empty: the first poll loads
  DrawPacer pacer(kDrawMs);
  int next_write_at = 1;
  auto last_write = Clock::now(), last_poll = Clock::now() - std::chrono::hours(1);
  const auto started = Clock::now();

  while (!g_stop && (o.seconds <= 0 || ms_since(started) < o.seconds * 1000.0)) {
    if (ms_since(last_poll) >= kPollMs) {
      last_poll = Clock::now();
      const Stamps now = stamps_of(watched);
      if (now != seen) {
        try {
          const std::unique_ptr<ScenePipeline> pipe = read_scene(o);
          RenderSettings wanted = settings_for(o, pipe->scene());  // an edit of <Render> applies
          wanted.spp_per_pass = settings.spp_per_pass;        // the pacer's draw size stays
          wanted.band_rows = settings.band_rows;
          settings = wanted;
          r.set_settings(settings);
          pipe->attach(r);
          pipe->finish();  // throws (and changes nothing) if the program does not build
          watched = pipe->scene().files;
          have_scene = true;
          ++generation;
          next_write_at = 1;
          std::printf("loaded %s (generation %d, %zu files watched)\n", o.scene.c_str(), generation, watched.size());
        } catch (const std::exception& e) {
          // The last good scene keeps rendering; its files stay watched, with the scene file.
          std::fprintf(stderr, "pathtracer: %s\n", e.what());
          bool has_scene_file = false;
          for (const std::string& f : watched) has_scene_file |= f == o.scene;
          if (!has_scene_file) watched.push_back(o.scene);
        }
        std::fflush(stdout);
        std::fflush(stderr);
        seen = stamps_of(watched);  // stamps read after loading: an edit during the load is seen next time
      }
    }
    if (!have_scene || r.converged()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(int(kPollMs / 2)));
      continue;
    }
    // Render for about one poll interval, then write when a checkpoint is reached.
    const auto t0 = Clock::now();
    while (!r.converged() && ms_since(t0) < kPollMs) {
      const auto tp = Clock::now();
      const int rows = settings.band_rows > 0 ? settings.band_rows : o.height;
      const int spp = settings.spp_per_pass;
      r.step();
      glFinish();
      pacer.record(ms_since(tp), rows, spp);
      pacer.apply(o.height, settings);
      r.set_settings(settings);
    }
    const int n = r.samples();
    if (n == 0 || r.mid_sweep()) continue;
    if (n < next_write_at && !r.converged() && ms_since(last_write) < kWriteMs) continue;
    while (next_write_at <= n) next_write_at *= 2;
    const std::vector<float> radiance = r.read_radiance();
    const ImageStats st = image_stats(radiance);
    bool ok = false;
    if (ends_with(out, ".png")) {
      if (o.auto_exposure) {
        settings.exposure = float(auto_exposure(radiance));
        r.set_settings(settings);
      }
      ok = write_png(out, o.width, o.height, r.read_display());
    }
    if (ends_with(out, ".hdr")) ok = write_hdr(out, o.width, o.height, radiance);
    if (ends_with(out, ".pfm")) ok = write_pfm(out, o.width, o.height, radiance);
    last_write = Clock::now();
    if (!ok) std::fprintf(stderr, "pathtracer: cannot write %s\n", out.c_str());
    else
      std::printf("wrote %s: %d spp (generation %d), mean radiance: %.6f %.6f %.6f\n", out.c_str(), n, generation,
                  st.mean.x, st.mean.y, st.mean.z);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace pt::cli
