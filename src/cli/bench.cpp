// `bench`: speed against error. Renders for a fixed time and records, at 1, 2, 4, ...
// samples per pixel, the render time (draws only, finished with glFinish; readbacks and
// metrics are outside the clock, except the error estimate's snapshot at each power of
// two, which is part of rendering), relMSE and RMSE against a reference, the estimated
// relMSE without one (render/error_estimator.h), and the rays cast (counted in the shader). `plot` draws CSVs as log-log curves in an SVG.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "cli/options.h"
#include "core/file_io.h"
#include "core/image.h"
#include "core/image_decode.h"
#include "core/metrics.h"
#include "core/svg_plot.h"
#include "render/pacing.h"
#include "gpu/gl.h"
#include "platform/egl.h"
#include "render/pipeline.h"

namespace pt::cli {

int run_bench(const Options& o) {
  if (o.reference.empty() == (o.reference_value < 0)) usage_error("bench needs one of --reference or --reference-value");
  const double duration = o.seconds > 0 ? o.seconds : 10.0;
  const std::unique_ptr<ScenePipeline> pipe = read_scene(o);
  const Scene& scene = pipe->scene();
  std::vector<float> ref(4, float(o.reference_value));
  if (!o.reference.empty()) {
    FloatImage img = load_float_image(o.reference);  // an error names the file and where it broke
    const int w = img.width, h = img.height;
    ref = std::move(img.rgba);
    if (w != o.width || h != o.height)
      throw std::runtime_error(o.reference + ": reference is " + std::to_string(w) + "x" + std::to_string(h) + ", not " +
                               std::to_string(o.width) + "x" + std::to_string(o.height));
  }
  HeadlessGl gl;
  std::printf("GL: %s\n", gl.description().c_str());
  Renderer r;
  r.resize(o.width, o.height);
  RenderSettings settings = settings_for(o, scene);
  settings.sample_limit = 0;
  r.set_settings(settings);
  pipe->attach(r);
  pipe->finish();
  std::printf("%s, %s kernel\n", accel_line(r, scene).c_str(), r.using_compute() ? "compute" : "fragment");
  std::printf("shader: %zu bytes, compiled and linked in %.1f ms\n", r.integrator_source().text.size(), r.compile_ms());
  r.warm_up();  // outside the clock: the driver's first-use work

  struct Row {
    int spp;
    double seconds;
    ErrorMetrics e;
    double rays;
    ErrorEstimate est;
  };
  std::vector<Row> rows;
  RenderSettings pace;  // the adaptive draw size; checkpoints cap the samples per sweep
  pace.spp_per_pass = o.per_pass > 0 ? o.per_pass : 1;
  DrawPacer pacer(40.0);
  int next = 1;
  double secs = 0;
  glFinish();
  while (secs < duration) {
    if (!r.mid_sweep()) {
      settings.spp_per_pass = std::min(pace.spp_per_pass, next - r.samples());
      settings.band_rows = pace.band_rows;
      r.set_settings(settings);
    }
    const auto t0 = std::chrono::steady_clock::now();
    const int band = settings.band_rows > 0 ? settings.band_rows : o.height;
    const int spp_now = settings.spp_per_pass;
    r.step();
    glFinish();
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    secs += dt;
    if (o.per_pass == 0) {
      pacer.record(dt * 1000.0, band, spp_now);
      pacer.apply(o.height, pace);
    }
    if (r.mid_sweep()) continue;
    if (r.samples() == next || secs >= duration) {
      const std::vector<float> mean = r.read_radiance();
      rows.push_back({r.samples(), secs, image_error(mean, ref), r.counters().rays, r.estimate_error()});
      if (r.samples() == next) next *= 2;
    }
  }
  const Row& last = rows.back();
  if (const TileCounts* c = r.accumulator().tile_counts())
    std::printf("adaptive sampling: %.2f spp on average (%.0f pixel-samples)\n", c->total() / (double(o.width) * o.height), c->total());
  std::printf("%s: %d spp in %.3f s at %dx%d: %.2f spp/s, %.1f Mrays/s; relMSE %.4g (estimated %.4g), RMSE %.4g\n",
              o.label.empty() ? o.scene.c_str() : o.label.c_str(), last.spp, last.seconds, o.width, o.height,
              last.spp / last.seconds, last.rays / last.seconds * 1e-6, last.e.rel_mse, last.est.rel_mse, last.e.rmse);
  std::ostringstream csv;
  csv << "label,spp,seconds,rel_mse,rmse,rays,est_rel_mse,est_rel_mse_iid,est_exponent\n";
  csv.precision(9);
  for (const Row& row : rows) {
    csv << (o.label.empty() ? o.scene : o.label) << "," << row.spp << "," << row.seconds << "," << row.e.rel_mse << ","
        << row.e.rmse << "," << row.rays << ",";
    // The estimate (core/metrics.h), from the per-pixel variance alone, and the exponent
    // of its decay; empty below 2 spp: no estimate yet.
    if (row.est.known) csv << row.est.rel_mse << "," << row.est.rel_mse_iid << "," << row.est.exponent;
    else csv << ",,";
    csv << "\n";
  }
  if (!o.csv.empty()) {
    const std::string text = csv.str();
    if (!write_file_atomic(o.csv, text.data(), text.size())) throw std::runtime_error("cannot write " + o.csv);
    std::printf("wrote %s\n", o.csv.c_str());
  } else {
    std::fputs(csv.str().c_str(), stdout);
  }
  return 0;
}

int run_plot(int argc, char** argv) {
  if (argc < 2) usage_error("plot needs OUT.svg and CSV files");
  const std::string out = argv[0];
  std::string x = "seconds", title = "relMSE against time";
  std::map<std::string, PlotSeries> by_label;
  std::vector<std::string> order;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--x") && i + 1 < argc) {
      x = argv[++i];
      if (x != "seconds" && x != "spp") usage_error("--x takes seconds or spp");
      continue;
    }
    if (!std::strcmp(argv[i], "--title") && i + 1 < argc) {
      title = argv[++i];
      continue;
    }
    const auto text = read_file(argv[i]);
    if (!text) throw std::runtime_error(std::string(argv[i]) + ": cannot read");
    std::istringstream in(*text);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::istringstream l(line);
      std::string label, f[5];
      std::getline(l, label, ',');
      for (std::string& s : f) std::getline(l, s, ',');
      if (!by_label.count(label)) order.push_back(label);
      PlotSeries& s = by_label[label];
      s.label = label;
      s.x.push_back(std::stod(x == "spp" ? f[0] : f[1]));
      s.y.push_back(std::stod(f[2]));
    }
  }
  std::vector<PlotSeries> series;
  for (const std::string& l : order) series.push_back(by_label[l]);
  const std::string svg = svg_loglog_plot(series, title, x == "spp" ? "samples per pixel" : "seconds", "relMSE");
  if (!write_file_atomic(out, svg.data(), svg.size())) throw std::runtime_error("cannot write " + out);
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

}  // namespace pt::cli
