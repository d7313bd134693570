#include "cli/options.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "render/packing.h"
#include "render/scene_render.h"
#include "scene/env_map.h"
#include "scene/xml_loader.h"

namespace pt::cli {

const char* const kUsage =
    "usage: pathtracer render SCENE.xml [options] [--spp N] [--out FILE.png|.hdr|.pfm] [--exposure X|auto]\n"
    "       pathtracer watch SCENE.xml [options] [--spp N] [--out FILE.png|.hdr|.pfm]  (re-renders on every change)\n"
    "       pathtracer bench SCENE.xml [options] --seconds S (--reference REF.pfm|.hdr | --reference-value V)\n"
    "                        [--csv FILE] [--label NAME]\n"
    "       pathtracer plot OUT.svg (--x seconds|spp) A.csv [B.csv ...]\n"
    "       pathtracer slices SCENE.xml [UNITS]  (the page's loading: read and pack in slices of UNITS,\n"
    "                        default 8192; prints each stage's work, slices and longest slice; no GL)\n"
    "options:\n"
    "  --size WxH        image size (default 512x512)\n"
    "  --bounces N       scattering events per path, 1..64 (default 8)\n"
    "  --spp-per-pass N  samples per draw; default adapts to keep each draw near 40 ms\n"
    "  --no-nee          BSDF sampling only (no next-event estimation / MIS)\n"
    "  --sampler S       sobol (Owen-scrambled Sobol for the camera and first bounce, default),\n"
    "                    sobol-all (every bounce) or independent (PCG)\n"
    "  --tonemap NAME    none linear reinhard filmic srgb uncharted2 aces (default aces)\n"
    "  --mode M          path (path tracer, default), whitted (ray tracer: direct light, mirrors,\n"
    "                    refraction) or sh (environment irradiance from spherical harmonics)\n"
    "  --env FILE.hdr    an equirectangular HDR map replacing the scene's environment\n"
    "  --kernel K        compute (default where the context is GL ES 3.1+, else fragment) or fragment\n"
    "                    (the WebGL 2 pass the page runs); same estimate, see docs/benchmarks.md\n"
    "  --accel A         auto (default: flat for a scene of few primitives, else bvh; render and bench\n"
    "                    print the rule), bvh, or flat (every ray tests every primitive); same estimate\n"
    "  --gltf-ms on|off  the glTF BSDF's multiple-scattering energy compensation (default on; off:\n"
    "                    the specification's single-scattering model, as other renderers; docs/gltf.md)\n"
    "  --adaptive on|off per-tile sample counts from the variance (default off; docs/benchmarks.md,\n"
    "                    \"adaptive sampling\"); each pixel stays the mean of its own samples\n"
    "render: --spp N (default 64), or until --seconds S if that comes first (references);\n"
    "        --target-relmse X stops once the estimated relMSE (printed at the end) is at most X\n"
    "        (then --spp, if given, and --seconds still cap it)\n"
    "        --out .png is tone-mapped, .hdr/.pfm linear radiance (--out may repeat);\n"
    "        --exposure X multiplies before the tone map, 'auto' maps the log-average to 0.18\n"
    "        --denoise: the camera pass also writes first-hit albedo, normal and depth, and the\n"
    "        a-trous denoiser (docs/denoise.md) filters the image; --out stays the raw (unbiased) mean,\n"
    "        --out-denoised FILE (.png/.hdr/.pfm, may repeat; implies --denoise) writes the denoised one,\n"
    "        blended with the raw by --denoise-weight W (0..1; default auto: min(1, E / D), E the estimated\n"
    "        relMSE and D the filter's own change, docs/denoise.md);\n"
    "        --out-aux PREFIX writes PREFIX-albedo.pfm, PREFIX-normal.pfm, PREFIX-depth.pfm (implies --denoise);\n"
    "        --out-spp FILE.pfm: each pixel's sample count (with --adaptive on, its tile's)\n"
    "        --out-variance FILE.pfm: per pixel and channel, the estimated variance of its mean\n"
    "        (its samples' variance / (count - 1): the expected squared error if they are independent)\n"
    "        --denoise-params ITERATIONS,SIGMA_Z,SIGMA_N,SIGMA_L[,SIGMA_A,REG_RADIUS,REG_STRIDE,REG_REL,REG_SD,REG_RIDGE,REG_INPUT,MIN_SAMPLES]\n"
    "          for tuning (defaults: render/denoise.h)\n"
    "        --count-ops: count the traversal's box and primitive tests and print them per ray (a\n"
    "        program of its own, in place of the variance: no estimate, adaptive sampling or denoiser)\n"
    "watch:  re-loads SCENE.xml when it or a file it references changes and re-renders to --out,\n"
    "        replaced atomically at 1, 2, 4, ... spp; a broken edit prints file:line and keeps the last image\n"
    "bench:  renders for S seconds; at 1, 2, 4, ... spp records time, relMSE and RMSE\n"
    "        against the reference (same size) in CSV; prints samples/s and rays/s\n"
    "Environment: PT_EGL_SOFTWARE=1 forces Mesa's software renderer; PT_DUMP_PROGRAMS=DIR writes each\n"
    "linked program's source and driver binary to DIR (docs/benchmarks.md, \"What limits speed now\").\n";

void usage_error(const std::string& msg) {
  std::fprintf(stderr, "pathtracer: %s\n%s", msg.c_str(), kUsage);
  std::exit(2);
}

namespace {

int parse_int(const char* s, const char* what, int lo, int hi) {
  char* end = nullptr;
  const long v = std::strtol(s, &end, 10);
  if (!*s || *end || v < lo || v > hi) usage_error(std::string("bad ") + what + ": " + s);
  return int(v);
}

double parse_positive(const char* s, const char* what) {
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  if (!*s || *end || !(v > 0.0) || v > 1e9) usage_error(std::string("bad ") + what + ": " + s);
  return v;
}

}  // namespace

Options parse_options(int argc, char** argv, bool bench) {
  if (argc < 1) usage_error("a scene file is needed");
  Options o;
  o.scene = argv[0];
  o.settings.compute = true;  // natively the faster kernel where there is one
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    o.given.push_back(a);
    auto next = [&]() -> const char* {
      if (i + 1 >= argc) usage_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--size") {
      const char* v = next();
      if (std::sscanf(v, "%dx%d", &o.width, &o.height) != 2 || o.width < 1 || o.height < 1 || o.width > 16384 ||
          o.height > 16384)
        usage_error(std::string("bad --size: ") + v);
    } else if (a == "--bounces") {
      o.settings.max_bounces = parse_int(next(), "--bounces", 1, 64);
    } else if (a == "--spp-per-pass") {
      o.per_pass = parse_int(next(), "--spp-per-pass", 1, 4096);
    } else if (a == "--no-nee") {
      o.settings.nee = false;
    } else if (a == "--sampler") {
      const std::string v = next();
      if (v != "sobol" && v != "sobol-all" && v != "independent") usage_error("--sampler takes sobol, sobol-all or independent");
      o.settings.sampler = v == "sobol" ? 3 : v == "sobol-all" ? 1 << 20 : 0;
    } else if (a == "--tonemap") {
      const char* v = next();
      if (!tonemap_from_name(v, &o.settings.tonemap)) usage_error(std::string("unknown tone map: ") + v);
    } else if (a == "--mode") {
      const char* v = next();
      if (!render_mode_from_name(v, &o.settings.mode)) usage_error(std::string("unknown mode: ") + v);
    } else if (a == "--kernel") {
      const std::string v = next();
      if (v != "compute" && v != "fragment") usage_error("--kernel takes compute or fragment");
      o.settings.compute = v == "compute";
    } else if (a == "--accel") {
      const char* v = next();
      if (!accel_from_name(v, &o.settings.accel)) usage_error("--accel takes auto, bvh or flat");
    } else if (a == "--gltf-ms") {
      const std::string v = next();
      if (v != "on" && v != "off") usage_error("--gltf-ms takes on or off");
      o.settings.gltf_ms = v == "on";
    } else if (a == "--adaptive") {
      const std::string v = next();
      if (v != "on" && v != "off") usage_error("--adaptive takes on or off");
      o.settings.adaptive = v == "on";
    } else if (!bench && a == "--count-ops") {
      o.settings.count_ops = true;
    } else if (!bench && a == "--out-spp") {
      o.out_spp = next();
    } else if (!bench && a == "--out-variance") {
      o.out_variance = next();
    } else if (a == "--env") {
      o.env = next();
    } else if (!bench && a == "--spp") {
      o.spp = parse_int(next(), "--spp", 1, 1 << 24);
    } else if (!bench && a == "--target-relmse") {
      o.target_relmse = parse_positive(next(), "--target-relmse");
    } else if (!bench && a == "--out") {
      o.outs.push_back(next());
    } else if (!bench && (a == "--denoise" || a == "--out-denoised" || a == "--out-aux")) {
      o.settings.aux = true;
      if (a == "--out-denoised") o.outs_denoised.push_back(next());
      if (a == "--out-aux") o.out_aux = next();
    } else if (!bench && a == "--denoise-params") {
      const char* v = next();
      DenoiseParams& d = o.denoise_params;
      if (std::sscanf(v, "%d,%f,%f,%f,%f,%d,%d,%f,%f,%f,%d,%d", &d.iterations, &d.sigma_z, &d.sigma_n, &d.sigma_l, &d.sigma_a,
                      &d.reg_radius, &d.reg_stride, &d.reg_rel, &d.reg_sd, &d.reg_ridge, &d.reg_input, &d.min_samples) < 4 ||
          d.min_samples < 0 ||
          d.iterations < 0 || d.iterations > 12 || d.reg_radius < 0 || d.reg_radius > 12 || d.reg_stride < 1 || d.reg_stride > 8)
        usage_error(std::string("bad --denoise-params: ") + v);
      o.settings.aux = true;
    } else if (!bench && a == "--denoise-weight") {
      const std::string v = next();
      o.settings.aux = true;
      if (v != "auto") {
        char* end = nullptr;
        o.denoise_weight = std::strtof(v.c_str(), &end);
        if (v.empty() || *end || !(o.denoise_weight >= 0.0f && o.denoise_weight <= 1.0f)) usage_error("bad --denoise-weight: " + v);
      }
    } else if (!bench && a == "--exposure") {
      const char* v = next();
      o.auto_exposure = !std::strcmp(v, "auto");
      if (!o.auto_exposure) o.settings.exposure = float(parse_positive(v, "--exposure"));
    } else if (a == "--seconds") {
      o.seconds = parse_positive(next(), "--seconds");
    } else if (bench && a == "--reference") {
      o.reference = next();
    } else if (bench && a == "--reference-value") {
      o.reference_value = parse_positive(next(), "--reference-value");
    } else if (bench && a == "--csv") {
      o.csv = next();
    } else if (bench && a == "--label") {
      o.label = next();
    } else {
      usage_error("unknown option " + a);
    }
  }
  if (o.outs.empty()) o.outs.push_back("out.png");
  if (o.settings.count_ops && (o.settings.adaptive || o.settings.aux || o.target_relmse > 0))
    usage_error("--count-ops replaces the variance: not with --adaptive on, --target-relmse or the denoiser");
  return o;
}

RenderSettings settings_for(const Options& o, const Scene& scene) {
  auto given = [&](const char* flag) { return std::find(o.given.begin(), o.given.end(), flag) != o.given.end(); };
  RenderSettings s = o.settings;
  s.sample_limit = o.target_relmse > 0 && !given("--spp") ? 1 << 24 : o.spp;  // the target ends it
  // A command line render ends: a scene's "unlimited" (samples 0) keeps --spp's default.
  const bool scene_unlimited = scene.render.samples && *scene.render.samples <= 0;
  const UserSet user{given("--bounces"), given("--mode"), given("--tonemap"), given("--exposure"),
                     given("--spp") || scene_unlimited};
  return with_scene_render(s, scene.render, user);
}

std::string accel_line(const Renderer& r, const Scene& scene) {
  const Accel a = r.settings().accel;
  const AccelCosts c = accel_costs(scene);
  char why[160];
  if (a == Accel::Auto && c.bounded > kFlatMaxConsidered)
    std::snprintf(why, sizeof why, "auto: %ld primitives in the BVH, over %ld", c.bounded, kFlatMaxConsidered);
  else if (a == Accel::Auto)
    std::snprintf(why, sizeof why, "auto: %ld primitives in the BVH, its SAH cost %.2f; flat when at most %.2f x the cost", c.bounded, c.sah, kFlatPerSah);
  else
    std::snprintf(why, sizeof why, "--accel %s; %ld primitives in the BVH, its SAH cost %.2f", accel_name(a), c.bounded, c.sah);
  return std::string("acceleration: ") + (r.using_flat() ? "flat" : "bvh") + " (" + why + ")";
}

std::unique_ptr<ScenePipeline> read_scene(const Options& o) {
  auto p = std::make_unique<ScenePipeline>(o.scene);
  if (!o.env.empty()) p->on_read([env = o.env](Scene& s, const ScenePipeline::Times&) { set_env_map(s.environment, env); });
  p->read();
  return p;
}

}  // namespace pt::cli
