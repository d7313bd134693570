// The compute kernel (native GL ES 3.1+) against the fragment pass the page runs: the
// same generated code behind a different entry point, so the same scene, settings and
// sample indices must give the same image and the same ray count, for whole sweeps and
// for sweeps drawn in bands and tiles (the tile bounds are the kernel's own: u_origin, u_end).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "gl_context.h"
#include "scene/xml_loader.h"
#include "scene_builders.h"
#include "test_paths.h"

using namespace pt;

namespace {

struct KernelRun {
  std::vector<float> rgba;
  Renderer::Counters counters;
  bool compute;
};

KernelRun run_kernel(const Scene& scene, bool compute, int band_rows, int band_columns, RenderMode mode) {
  test_gl();
  Renderer r;
  r.resize(37, 29);  // not a multiple of the 8x8 groups: the edge groups are cut
  RenderSettings st;
  st.mode = mode;
  st.compute = compute;
  st.sample_limit = 6;
  st.spp_per_pass = 2;
  st.band_rows = band_rows;
  st.band_columns = band_columns;
  r.set_settings(st);
  r.set_scene(scene);
  while (!r.converged()) r.step();
  return {r.read_radiance(), r.counters(), r.using_compute()};
}

}  // namespace

TEST_CASE("compute kernel: the same image and ray count as the fragment pass", "[gpu][compute]") {
  test_gl();
  {
    Renderer probe;  // llvmpipe and every desktop GPU driver give GL ES 3.1+ through EGL
    REQUIRE(probe.compute_supported());
  }
  const char* scenes[] = {"scenes/reference/scene0.xml", "scenes/reference/scene2.xml", "scenes/cornell-box.xml",
                          "scenes/textures.xml", "scenes/gltf-instances.xml", "scenes/seed/07-mesh-on-perlin.xml"};
  for (const char* name : scenes) {
    const Scene scene = load_scene_file(repo_path(name));
    for (RenderMode mode : {RenderMode::PathTracer, RenderMode::Whitted}) {
      const KernelRun frag = run_kernel(scene, false, 0, 0, mode);
      REQUIRE_FALSE(frag.compute);
      // Whole sweeps, bands of 5 rows, tiles of 5 rows by 11 columns (neither divides
      // the 37x29 image, and a tile is not a multiple of the 8x8 groups either).
      for (auto [band, columns] : {std::pair{0, 0}, std::pair{5, 0}, std::pair{5, 11}}) {
        const KernelRun comp = run_kernel(scene, true, band, columns, mode);
        REQUIRE(comp.compute);
        double max_diff = 0.0, max_value = 0.0;
        for (size_t i = 0; i < frag.rgba.size(); ++i) {
          max_diff = std::max(max_diff, double(std::abs(frag.rgba[i] - comp.rgba[i])));
          max_value = std::max(max_value, double(std::abs(frag.rgba[i])));
        }
        std::printf("%-40s %-8s tiles %dx%d: max |compute - fragment| %.3g (max value %.3g), rays %.0f vs %.0f\n", name,
                    kRenderModeNames[int(mode)], band, columns, max_diff, max_value, comp.counters.rays, frag.counters.rays);
        INFO(name << " mode " << kRenderModeNames[int(mode)] << " tiles " << band << "x" << columns);
        CHECK(max_value > 0.0);
        CHECK(comp.counters.rays == frag.counters.rays);
        CHECK(comp.counters.bad_samples == 0);
        CHECK(max_diff == 0.0);
      }
    }
  }
}
