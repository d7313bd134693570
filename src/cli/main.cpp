// The native command line: render, bench, plot, watch and slices, headless through EGL.
// Every command gets its scene through the one scene pipeline (render/pipeline.h).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cli/options.h"
#include "core/image.h"
#include "core/metrics.h"
#include "render/pacing.h"
#include "gpu/gl.h"
#include "platform/egl.h"
#include "render/denoise.h"
#include "render/pipeline.h"

namespace pt::cli {
namespace {

bool ends_with(const std::string& s, const char* suffix) {
  const size_t n = std::strlen(suffix);
  return s.size() >= n && s.compare(s.size() - n, n, suffix) == 0;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

bool write_image(const std::string& out, int w, int h, const std::vector<float>& radiance, const std::vector<uint8_t>& png) {
  if (ends_with(out, ".png")) return write_png(out, w, h, png);
  if (ends_with(out, ".hdr")) return write_hdr(out, w, h, radiance);
  return write_pfm(out, w, h, radiance);
}

// --denoise: the denoiser's cost (the median of 3 runs, waited for, after one that builds
// its programs), its images and the auxiliaries. false when a file cannot be written.
bool denoise_outputs(const Options& o, Renderer& r, const ErrorEstimate& est) {
  r.denoiser().params = o.denoise_params;
  // The automatic weight, measured from the estimate by the timed runs (Denoiser::run);
  // --denoise-weight W then replaces it (and is reported beside it).
  RenderSettings s = r.settings();
  s.denoise = 1.0f;  // read_display shows the denoised image (weight 0: the raw one, the same bits)
  s.denoise_estimate = est.known ? est.rel_mse : -1.0;
  r.set_settings(s);
  const std::vector<double> ms = r.time_denoiser(1.0f);
  const float automatic = r.denoiser().weight();
  if (o.denoise_weight >= 0.0f) {
    s.denoise = o.denoise_weight;
    s.denoise_estimate = -1.0;
    r.set_settings(s);
  }
  std::printf("denoised: blend weight %.4f (from the estimated relMSE: %.4f), %d iterations in %.2f ms (median of 3, %.2f..%.2f)\n",
              double(o.denoise_weight >= 0.0f ? o.denoise_weight : automatic), double(automatic), r.denoiser().params.iterations, ms[1], ms[0], ms[2]);
  const std::vector<float> img = r.read_denoised(s.denoise);
  for (const std::string& out : o.outs_denoised) {
    if (!write_image(out, o.width, o.height, img, ends_with(out, ".png") ? r.read_display() : std::vector<uint8_t>())) {
      std::fprintf(stderr, "pathtracer: cannot write %s\n", out.c_str());
      return false;
    }
    std::printf("wrote %s (denoised)\n", out.c_str());
  }
  if (!o.out_aux.empty()) {
    const std::vector<float> a0 = r.accumulator().read_aux(0), a1 = r.accumulator().read_aux(1);
    std::vector<float> depth(a0.size());
    for (size_t i = 0; i < a0.size(); i += 4) depth[i] = depth[i + 1] = depth[i + 2] = a0[i + 3];
    const std::pair<std::string, const std::vector<float>*> files[3] = {{"-albedo.pfm", &a0}, {"-normal.pfm", &a1}, {"-depth.pfm", &depth}};
    for (const auto& [suffix, px] : files) {
      if (!write_pfm(o.out_aux + suffix, o.width, o.height, *px)) {
        std::fprintf(stderr, "pathtracer: cannot write %s%s\n", o.out_aux.c_str(), suffix.c_str());
        return false;
      }
      std::printf("wrote %s%s\n", o.out_aux.c_str(), suffix.c_str());
    }
  }
  return true;
}

}  // namespace

int run_render(const Options& o) {
  for (const std::vector<std::string>* outs : {&o.outs, &o.outs_denoised})
    for (const std::string& out : *outs)
      if (!ends_with(out, ".png") && !ends_with(out, ".hdr") && !ends_with(out, ".pfm"))
        usage_error("--out and --out-denoised must end in .png, .hdr or .pfm");
  const auto tl = std::chrono::steady_clock::now();
  const std::unique_ptr<ScenePipeline> pipe = read_scene(o);  // before GL: bad input fails fast
  const Scene& scene = pipe->scene();
  for (const std::string& w : scene.warnings) std::fprintf(stderr, "pathtracer: warning: %s\n", w.c_str());
  const double load_ms = seconds_since(tl) * 1e3;
  HeadlessGl gl;
  std::printf("GL: %s\n", gl.description().c_str());
  Renderer r;
  r.resize(o.width, o.height);
  RenderSettings settings = settings_for(o, scene);
  settings.spp_per_pass = o.per_pass > 0 ? o.per_pass : 1;
  r.set_settings(settings);
  const auto ts = std::chrono::steady_clock::now();
  pipe->attach(r);
  pipe->finish();  // packed, staged, compiled and set
  glFinish();
  const double set_ms = seconds_since(ts) * 1e3 - r.compile_ms();
  std::printf("scene: %s (%zu objects, %zu materials, %zu lights), loaded in %.0f ms\n", o.scene.c_str(), scene.shapes.size(),
              scene.materials.size(), scene.lights.size(), load_ms);
  std::printf("mode: %s, %s kernel\n", kRenderModeNames[int(settings.mode)], r.using_compute() ? "compute" : "fragment");
  const Renderer::BvhStats& bs = r.bvh_stats();
  std::printf("BVH: %d primitives, %d nodes, depth %d, built in %.0f ms; packed and uploaded in %.0f ms in all\n", bs.primitives,
              bs.nodes, bs.depth, bs.build_ms, set_ms);
  std::printf("%s\n", accel_line(r, scene).c_str());
  std::printf("shader: %zu bytes, compiled and linked in %.1f ms\n", r.integrator_source().text.size(), r.compile_ms());

  DrawPacer pacer(40.0);
  r.warm_up();  // outside the clock: the driver's first-use work
  const auto t0 = std::chrono::steady_clock::now();
  int checked = 0;  // the samples when the estimate was last read (--target-relmse)
  bool reached = false;
  while (!r.converged() && !reached && (o.seconds <= 0 || seconds_since(t0) < o.seconds)) {
    const auto tp = std::chrono::steady_clock::now();
    const int rows = settings.band_rows > 0 ? settings.band_rows : o.height;
    const int spp = settings.spp_per_pass;
    const bool swept = r.step() > 0;
    glFinish();
    // The estimate reads three images back: read it each time the samples grew by 1/16,
    // in sweeps of at most that many, so the render stops within about 6% of the samples
    // that reach the target.
    const int n = r.samples();
    if (o.target_relmse > 0 && swept && n >= checked + std::max(1, checked / 16)) {
      checked = n;
      const ErrorEstimate e = r.estimate_error();
      reached = e.known && e.rel_mse <= o.target_relmse;
    }
    if (o.per_pass == 0) {
      pacer.record(seconds_since(tp) * 1000.0, rows, spp);
      pacer.apply(o.height, settings);
      if (o.target_relmse > 0) settings.spp_per_pass = std::min(settings.spp_per_pass, std::max(1, r.samples() / 16));
      r.set_settings(settings);
    }
  }
  const double secs = seconds_since(t0);
  const std::vector<float> radiance = r.read_radiance();
  const ImageStats st = image_stats(radiance);
  const Renderer::Counters counters = r.counters();
  std::printf("rendered %d spp at %dx%d, %d bounces, in %.3f s: %.2f spp/s, %.1f Mpaths/s, %.1f Mrays/s\n", r.samples(),
              o.width, o.height, settings.max_bounces, secs, r.samples() / secs,
              double(r.samples()) * o.width * o.height / secs * 1e-6, counters.rays / secs * 1e-6);
  std::printf("mean radiance: %.6f %.6f %.6f; non-finite samples: %.0f, pixels: %ld\n", st.mean.x, st.mean.y, st.mean.z,
              counters.bad_samples, st.bad);
  if (settings.count_ops)
    std::printf("traversal per ray: %.3f box tests, %.3f primitive tests (%.4g rays)\n", counters.box_tests / counters.rays,
                counters.prim_tests / counters.rays, counters.rays);
  const ErrorEstimate est = r.estimate_error();
  if (reached) std::printf("target relMSE %.4g reached\n", o.target_relmse);
  if (settings.count_ops)
    std::printf("estimated relMSE: not kept (--count-ops holds the counts in its place)\n");
  else if (est.known)
    std::printf("estimated relMSE: %.4g (the worst %dx%d tile: %.4g; from the per-pixel variance alone: %.4g)\n", est.rel_mse, est.tile,
                est.tile, *std::max_element(est.tiles.begin(), est.tiles.end()), est.rel_mse_iid);
  else
    std::printf("estimated relMSE: unknown (fewer than 2 samples per pixel)\n");
  if (o.auto_exposure) {
    settings.exposure = float(auto_exposure(radiance));
    r.set_settings(settings);
    std::printf("auto exposure: %.4f\n", settings.exposure);
  }
  for (const std::string& out : o.outs) {
    if (!write_image(out, o.width, o.height, radiance, ends_with(out, ".png") ? r.read_display() : std::vector<uint8_t>())) {
      std::fprintf(stderr, "pathtracer: cannot write %s\n", out.c_str());
      return 1;
    }
    std::printf("wrote %s\n", out.c_str());
  }
  if (const TileCounts* c = r.accumulator().tile_counts()) {
    const auto [lo, hi] = std::minmax_element(c->counts().begin(), c->counts().end());
    std::printf("adaptive sampling: %.2f spp on average (%.0f pixel-samples), per %dx%d tile from %d to %d spp\n",
                c->total() / (double(o.width) * o.height), c->total(), c->tile(), c->tile(), *lo, *hi);
  }
  if (!o.out_spp.empty()) {
    std::vector<float> spp(size_t(o.width) * o.height * 4, float(r.samples()));
    const TileCounts* c = r.accumulator().tile_counts();
    for (int y = 0; y < o.height && c; ++y)
      for (int x = 0; x < o.width; ++x)
        for (int k = 0; k < 3; ++k) spp[(size_t(y) * o.width + x) * 4 + k] = float(c->at(x, y));
    if (!write_pfm(o.out_spp, o.width, o.height, spp)) {
      std::fprintf(stderr, "pathtracer: cannot write %s\n", o.out_spp.c_str());
      return 1;
    }
    std::printf("wrote %s (samples per pixel)\n", o.out_spp.c_str());
  }
  if (!o.out_variance.empty()) {
    std::vector<float> v = r.read_variance();  // about the mean, / samples
    const TileCounts* c = r.accumulator().tile_counts();
    for (int y = 0; y < o.height; ++y)
      for (int x = 0; x < o.width; ++x) {
        const int n = c ? c->at(x, y) : r.samples();
        for (int k = 0; k < 3; ++k) {
          float& px = v[(size_t(y) * o.width + x) * 4 + k];
          px = n > 1 ? std::max(px, 0.0f) / float(n - 1) : 0.0f;
        }
      }
    if (!write_pfm(o.out_variance, o.width, o.height, v)) {
      std::fprintf(stderr, "pathtracer: cannot write %s\n", o.out_variance.c_str());
      return 1;
    }
    std::printf("wrote %s (variance of each pixel's mean)\n", o.out_variance.c_str());
  }
  if (settings.aux && !denoise_outputs(o, r, est)) return 1;
  return st.bad == 0 && counters.bad_samples == 0 ? 0 : 3;
}

// The page's preparation of a scene, natively and without GL: the scene pipeline
// (render/pipeline.h) reading its meshes (SceneLoad), then packing it and building the BVH
// (PackJob), each stage in slices of `units` as the page runs them; per stage, the work's
// time, the slices and the longest slice (the steps between stages, such as starting the
// packing, are not slices and not listed).
int run_slices(int argc, char** argv) {
  if (argc < 1 || argc > 2) usage_error("slices takes SCENE.xml [UNITS]");
  const std::string path = argv[0];
  const long units = argc > 1 ? std::max(1L, std::atol(argv[1])) : ScenePipeline::kWorkUnits;
  struct Stage {
    double ms = 0.0, longest = 0.0;
    long slices = 0;
  };
  std::vector<std::pair<std::string, Stage>> stages;
  auto record = [&](const std::string& name, double ms) {
    if (stages.empty() || stages.back().first != name) stages.push_back({name, {}});
    Stage& st = stages.back().second;
    st.ms += ms;
    st.longest = std::max(st.longest, ms);
    ++st.slices;
  };
  const auto t0 = std::chrono::steady_clock::now();
  ScenePipeline pipe(path);  // no renderer: it reads and packs
  record("parsing the XML", seconds_since(t0) * 1e3);
  while (pipe.preparing()) {
    const std::string stage = pipe.stage();
    const bool sliced = pipe.sliced();
    const auto t = std::chrono::steady_clock::now();
    pipe.step(units);
    if (sliced) record(stage, seconds_since(t) * 1e3);
  }
  std::printf("%s in slices of %ld units:\n", path.c_str(), units);
  for (const auto& [name, st] : stages)
    std::printf("  %-28s %8.1f ms in %6ld slices, the longest %6.1f ms\n", name.c_str(), st.ms, st.slices, st.longest);
  std::printf("  all: %.1f ms\n", seconds_since(t0) * 1e3);
  return 0;
}

}  // namespace pt::cli

int main(int argc, char** argv) {
  using namespace pt::cli;
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  try {
    if (!std::strcmp(argv[1], "render")) return run_render(parse_options(argc - 2, argv + 2, false));
    if (!std::strcmp(argv[1], "watch")) return run_watch(parse_options(argc - 2, argv + 2, false));
    if (!std::strcmp(argv[1], "bench")) return run_bench(parse_options(argc - 2, argv + 2, true));
    if (!std::strcmp(argv[1], "plot")) return run_plot(argc - 2, argv + 2);
    if (!std::strcmp(argv[1], "slices")) return run_slices(argc - 2, argv + 2);
    usage_error(std::string("unknown command ") + argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pathtracer: %s\n", e.what());
    return 1;
  }
}
