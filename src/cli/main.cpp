// The native command line: `pathtracer render SCENE.xml [options]` renders headless
// through EGL and writes a tone-mapped PNG or a linear Radiance HDR.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/image.h"
#include "gpu/gl.h"
#include "platform/egl.h"
#include "render/renderer.h"
#include "scene/xml_loader.h"

namespace {

const char* kUsage =
    "usage: pathtracer render SCENE.xml [--spp N] [--size WxH] [--out FILE.png|FILE.hdr]\n"
    "                         [--bounces N] [--spp-per-pass N] [--tonemap NAME] [--exposure X]\n"
    "                         [--no-nee]\n"
    "  --spp N           samples per pixel (default 64)\n"
    "  --size WxH        image size (default 512x512)\n"
    "  --out FILE        .png (tone-mapped) or .hdr (linear radiance); default out.png\n"
    "  --bounces N       scattering events per path, 1..64 (default 8)\n"
    "  --spp-per-pass N  samples per draw; default adapts to keep each draw near 40 ms\n"
    "  --tonemap NAME    none linear reinhard filmic srgb uncharted2 aces (default aces)\n"
    "  --exposure X      multiplier before the tone map (default 1); 'auto' maps the\n"
    "                    log-average luminance to 0.18\n"
    "  --no-nee          BSDF sampling only (no next-event estimation / MIS)\n"
    "Environment: PT_EGL_SOFTWARE=1 forces Mesa's software renderer.\n";

[[noreturn]] void usage_error(const std::string& msg) {
  std::fprintf(stderr, "pathtracer: %s\n%s", msg.c_str(), kUsage);
  std::exit(2);
}

int parse_int(const char* s, const char* what, int lo, int hi) {
  char* end = nullptr;
  const long v = std::strtol(s, &end, 10);
  if (!*s || *end || v < lo || v > hi) usage_error(std::string("bad ") + what + ": " + s);
  return int(v);
}

bool ends_with(const std::string& s, const char* suffix) {
  const size_t n = std::strlen(suffix);
  return s.size() >= n && s.compare(s.size() - n, n, suffix) == 0;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int render(int argc, char** argv) {
  if (argc < 1) usage_error("render needs a scene file");
  const std::string scene_path = argv[0];
  int spp = 64, width = 512, height = 512, per_pass = 0;
  std::string out = "out.png";
  bool auto_exposure = false;
  pt::RenderSettings settings;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> const char* {
      if (i + 1 >= argc) usage_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--spp") {
      spp = parse_int(next(), "--spp", 1, 1 << 24);
    } else if (a == "--size") {
      const char* v = next();
      if (std::sscanf(v, "%dx%d", &width, &height) != 2 || width < 1 || height < 1 || width > 16384 || height > 16384)
        usage_error(std::string("bad --size: ") + v);
    } else if (a == "--out") {
      out = next();
    } else if (a == "--bounces") {
      settings.max_bounces = parse_int(next(), "--bounces", 1, 64);
    } else if (a == "--spp-per-pass") {
      per_pass = parse_int(next(), "--spp-per-pass", 1, 4096);
    } else if (a == "--tonemap") {
      const char* v = next();
      if (!pt::tonemap_from_name(v, &settings.tonemap)) usage_error(std::string("unknown tone map: ") + v);
    } else if (a == "--exposure") {
      const char* v = next();
      auto_exposure = !std::strcmp(v, "auto");
      if (!auto_exposure) {
        char* end = nullptr;
        settings.exposure = std::strtof(v, &end);
        if (*end || !(settings.exposure > 0.0f)) usage_error(std::string("bad --exposure: ") + v);
      }
    } else if (a == "--no-nee") {
      settings.nee = false;
    } else {
      usage_error("unknown option " + a);
    }
  }
  if (!ends_with(out, ".png") && !ends_with(out, ".hdr")) usage_error("--out must end in .png or .hdr");

  const pt::Scene scene = pt::load_scene_file(scene_path);  // before GL: bad input fails fast
  pt::HeadlessGl gl;
  std::printf("GL: %s\n", gl.description().c_str());
  pt::Renderer r;
  r.resize(width, height);
  settings.sample_limit = spp;
  settings.spp_per_pass = per_pass > 0 ? per_pass : 1;
  r.set_settings(settings);
  r.set_scene(scene);
  std::printf("scene: %s (%zu objects, %zu materials, %zu lights)\n", scene_path.c_str(), scene.shapes.size(),
              scene.materials.size(), scene.lights.size());
  std::printf("shader: %zu bytes, compiled and linked in %.1f ms\n", r.integrator_source().text.size(), r.compile_ms());

  glFinish();
  const auto t0 = std::chrono::steady_clock::now();
  while (!r.converged()) {
    const auto tp = std::chrono::steady_clock::now();
    r.step();
    glFinish();
    // Adapt the draw size so that one draw stays near 40 ms (no watchdog, few syncs).
    if (per_pass == 0) {
      const double ms = seconds_since(tp) * 1000.0;
      if (ms < 20.0 && settings.spp_per_pass < 256) settings.spp_per_pass *= 2;
      if (ms > 80.0 && settings.spp_per_pass > 1) settings.spp_per_pass /= 2;
      r.set_settings(settings);
    }
  }
  const double secs = seconds_since(t0);
  const std::vector<float> radiance = r.read_radiance();
  const pt::ImageStats st = pt::image_stats(radiance);
  const pt::Renderer::Counters counters = r.counters();
  std::printf("rendered %d spp at %dx%d, %d bounces, in %.3f s: %.2f spp/s, %.1f Mpaths/s, %.1f Mrays/s\n", r.samples(),
              width, height, settings.max_bounces, secs, r.samples() / secs, double(r.samples()) * width * height / secs * 1e-6,
              counters.rays / secs * 1e-6);
  std::printf("mean radiance: %.6f %.6f %.6f; non-finite samples: %.0f, pixels: %ld\n", st.mean.x, st.mean.y, st.mean.z,
              counters.bad_samples, st.bad);
  if (auto_exposure) {
    settings.exposure = float(pt::auto_exposure(radiance));
    r.set_settings(settings);
    std::printf("auto exposure: %.4f\n", settings.exposure);
  }
  const bool ok = ends_with(out, ".png") ? pt::write_png(out, width, height, r.read_display())
                                         : pt::write_hdr(out, width, height, radiance);
  if (!ok) {
    std::fprintf(stderr, "pathtracer: cannot write %s\n", out.c_str());
    return 1;
  }
  std::printf("wrote %s\n", out.c_str());
  return st.bad == 0 && counters.bad_samples == 0 ? 0 : 3;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  try {
    if (!std::strcmp(argv[1], "render")) return render(argc - 2, argv + 2);
    usage_error(std::string("unknown command ") + argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pathtracer: %s\n", e.what());
    return 1;
  }
}
