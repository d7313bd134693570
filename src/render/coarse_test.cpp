// The coarse first image (render/coarse.h). The ladder's logic: 1/8, 1/4, 1/2, then full
// resolution after every restart; a coarse level is shown only while no full-resolution
// sweep is complete; coarse draws take about the pacer's pixels. On the GPU: with the
// ladder on, the full-resolution accumulation after N sweeps is byte-identical to the one
// without it (both kernels, in tiles); the image shown steps 8, 4, 2, 1, each coarse one
// covering the full frame (a sphere against the sky lands where the full image has it)
// with no black row; a camera move restarts the ladder.
#include <catch2/catch.hpp>

#include <cstring>

#include "gl_context.h"
#include "render/coarse.h"
#include "render/pacing.h"
#include "render/renderer.h"
#include "scene/xml_loader.h"

using namespace pt;

TEST_CASE("CoarseLadder steps 1/8, 1/4, 1/2 then full resolution after each restart", "[coarse]") {
  CoarseLadder l;
  l.restart();
  CHECK(l.drawing() == 0);
  CHECK(!l.started());
  CHECK(l.shown(0) == -1);  // nothing complete: the full-resolution mean (black) is shown
  l.drew();
  CHECK(l.started());
  CHECK(l.shown(0) == -1);  // a level in progress is not shown
  l.level_done();
  CHECK(l.drawing() == 1);
  CHECK(l.shown(0) == 0);
  l.level_done();
  CHECK(l.shown(0) == 1);
  l.level_done();
  CHECK(l.drawing() == -1);  // every level done: full-resolution sweeps
  CHECK(l.completed() == 3);
  CHECK(l.shown(0) == 2);    // the finest level until the first full sweep is complete
  CHECK(l.shown(1) == -1);   // then only the full-resolution mean
  CHECK(l.shown(0) == 2);
  l.restart();               // a camera move: from the coarsest level again
  CHECK(l.drawing() == 0);
  CHECK(l.completed() == 0);
  CHECK(l.shown(0) == -1);
  CHECK(CoarseLadder::divisor(0) == 8);
  CHECK(CoarseLadder::divisor(1) == 4);
  CHECK(CoarseLadder::divisor(2) == 2);
  CHECK(CoarseLadder::level_size(1280, 0) == 160);
  CHECK(CoarseLadder::level_size(800, 0) == 100);
  CHECK(CoarseLadder::level_size(801, 0) == 101);  // rounded up: the level covers the image
  CHECK(CoarseLadder::level_size(1, 0) == 1);
  CHECK(CoarseLadder::level_size(7, 2) == 4);
}

TEST_CASE("CoarseLadder::draw_size keeps the pacer's pixels per draw", "[coarse][pacing]") {
  int rows = -1, columns = -1;
  // The page's first draws: 32 rows of 1280 = 40960 pixels, more than the 160x100 level.
  CoarseLadder::draw_size(FramePacer::kFirstBandRows, 0, 1280, 800, 160, 100, rows, columns);
  CHECK(rows == 0);
  CHECK(columns == 0);
  // The same at 1/2 (640x400): 64 whole rows of 640.
  CoarseLadder::draw_size(32, 0, 1280, 800, 640, 400, rows, columns);
  CHECK(rows == 64);
  CHECK(columns == 0);
  // The whole image: the whole level.
  CoarseLadder::draw_size(0, 0, 1280, 800, 640, 400, rows, columns);
  CHECK(rows == 0);
  CHECK(columns == 0);
  // The smallest draw (4 rows x 128 columns = 512 pixels): 4 rows of 128 columns of a
  // level wider than that.
  CoarseLadder::draw_size(kMinBandRows, 128, 1280, 800, 640, 400, rows, columns);
  CHECK(rows == kMinBandRows);
  CHECK(columns == 128);
  // ... and whole rows of a level narrower than 128 pixels (5 rows of 100 fit in 512; the
  // row-pair grid makes them 4).
  CoarseLadder::draw_size(kMinBandRows, 128, 800, 1280, 100, 160, rows, columns);
  CHECK(rows == 4);
  CHECK(columns == 0);
  // A level thinner than kMinBandRows: the whole level.
  CoarseLadder::draw_size(kMinBandRows, 128, 1280, 16, 160, 2, rows, columns);
  CHECK(rows == 0);
  CHECK(columns == 0);
}

TEST_CASE("CoarseLadder::draw_size keeps every coarse draw on the row-pair grid", "[coarse][pacing]") {
  // Every level of odd-sized images, for every draw the pacer can ask for: a band's rows a
  // multiple of kBandRowsStep and a tile's columns a multiple of kTileColumnsStep (or the
  // whole level), as the pacer's own draws (render/draw_grid.h).
  for (const auto& [fw, fh] : {std::pair{962, 541}, std::pair{300, 203}, std::pair{1280, 800}})
    for (int level = 0; level < CoarseLadder::kLevels; ++level) {
      const int w = CoarseLadder::level_size(fw, level), h = CoarseLadder::level_size(fh, level);
      for (int band_rows = kMinBandRows; band_rows <= fh + kBandRowsStep; band_rows += kBandRowsStep)
        for (int band_columns : {0, 128, 130, 302, 640}) {
          if (band_columns > 0 && band_rows > kMinBandRows) continue;  // tiles only of the thinnest band
          int rows = -1, columns = -1;
          CoarseLadder::draw_size(band_rows, band_columns, fw, fh, w, h, rows, columns);
          INFO(fw << "x" << fh << " level " << level << " (" << w << "x" << h << "), pacer " << band_rows << " x " << band_columns
                  << " -> " << rows << " x " << columns);
          REQUIRE((rows == 0 || rows % kBandRowsStep == 0));
          REQUIRE((columns == 0 || columns % kTileColumnsStep == 0));
          REQUIRE((rows == 0 || rows < h));
          REQUIRE((columns == 0 || columns < w));
        }
    }
}

namespace {

// A black sphere off the middle of a white sky (constant radiance 1): a camera ray that
// leaves reads 1, one that meets the sphere 0.
constexpr const char* kSphereSky = R"(<SceneLevel>
  <Camera position="0 0 4" yaw="90" pitch="0"/>
  <Environment color="1 1 1"/>
  <Objects>
    <Sphere center="0.4 0.2 0" radius="1"><Attenuate color="0 0 0"><Diffuse/></Attenuate></Sphere>
  </Objects>
</SceneLevel>
)";

// The same with a grey sphere (albedo 0.5): noisy values, so that any sample more, less or
// elsewhere in the mean changes its bytes (the black sphere's 0 or 1 would hide them).
constexpr const char* kGreySphere = R"(<SceneLevel>
  <Camera position="0 0 4" yaw="90" pitch="0"/>
  <Environment color="1 1 1"/>
  <Objects>
    <Sphere center="0.4 0.2 0" radius="1"><Attenuate color="0.5 0.5 0.5"><Diffuse/></Attenuate></Sphere>
  </Objects>
</SceneLevel>
)";

bool sky(const std::vector<float>& px, size_t i) { return 0.2126f * px[i] + 0.7152f * px[i + 1] + 0.0722f * px[i + 2] > 0.5f; }

struct Run {
  std::vector<float> radiance, variance;
  std::vector<uint8_t> display;
  std::vector<int> divisors;  // shown_divisor() after each draw
};

// `sweeps` full-resolution sweeps in tiles of 5 rows x 24 columns (several per coarse
// level too), the ladder on or off.
Run render(Renderer& r, bool coarse, bool compute, int sweeps, bool adaptive = false) {
  RenderSettings s;
  s.adaptive = adaptive;
  s.spp_per_pass = 1;
  s.band_rows = 5;
  s.band_columns = 24;
  s.coarse = coarse;
  s.compute = compute;
  s.max_bounces = 3;
  r.set_settings(s);
  r.restart();
  Run out;
  for (int guard = 0; r.samples() < sweeps && guard < 100000; ++guard) {
    r.step();
    out.divisors.push_back(r.shown_divisor());
  }
  glFinish();
  out.radiance = r.read_radiance();
  out.variance = r.read_variance();
  out.display = r.read_display();
  return out;
}

}  // namespace

TEST_CASE("The coarse ladder leaves the full-resolution accumulation byte-identical", "[gpu][coarse]") {
  test_gl();
  const Scene scene = load_scene_text(kGreySphere, "sphere-sky.xml", false);
  Renderer r;
  r.resize(61, 43);  // not a multiple of 8: the levels' last pixels reach past the image
  r.set_scene(scene);
  for (const bool compute : {false, true})
    for (const bool adaptive : {false, true}) {
    if (compute && !r.compute_supported()) continue;
    INFO((compute ? "compute kernel" : "fragment pass") << (adaptive ? ", adaptive" : ""));
    // Adaptive sampling: past its uniform start (8 spp), so the tiles' counts differ.
    const int sweeps = adaptive ? 12 : 3;
    const Run off = render(r, false, compute, sweeps, adaptive);
    const Run on = render(r, true, compute, sweeps, adaptive);
    REQUIRE(off.radiance.size() == on.radiance.size());
    CHECK(std::memcmp(off.radiance.data(), on.radiance.data(), off.radiance.size() * sizeof(float)) == 0);
    CHECK(std::memcmp(off.variance.data(), on.variance.data(), off.variance.size() * sizeof(float)) == 0);
    CHECK(off.display == on.display);  // after a full sweep the display is the full mean
    // Without the ladder the display shows the full mean throughout; with it 8, 4, 2 (each
    // once a level is complete: the 8x6 1/8 level in the first draw), then 1 from the
    // first full sweep on.
    CHECK(std::all_of(off.divisors.begin(), off.divisors.end(), [](int d) { return d == 1; }));
    std::vector<int> steps;
    for (const int d : on.divisors)
      if (steps.empty() || steps.back() != d) steps.push_back(d);
    CHECK(steps == std::vector<int>{8, 4, 2, 1});
    CHECK(on.divisors.size() > off.divisors.size());  // the ladder's draws came first
  }
}

TEST_CASE("A coarse level covers the full frame, upscaled in blocks, and a camera move restarts it", "[gpu][coarse]") {
  test_gl();
  const Scene scene = load_scene_text(kSphereSky, "sphere-sky.xml", false);
  const int w = 96, h = 64;
  // With adaptive sampling the coarse levels' program reads tile counts too.
  const bool adaptive = GENERATE(false, true);
  INFO((adaptive ? "adaptive" : "uniform"));
  Renderer r;
  r.resize(w, h);
  r.set_scene(scene);
  RenderSettings s;
  s.adaptive = adaptive;
  s.coarse = true;
  s.max_bounces = 2;
  s.band_rows = 16;  // 16 x 96 pixels a draw: a 12 x 8 level in one draw
  s.tonemap = ToneMap::Linear;
  r.set_settings(s);
  r.step();  // the 1/8 level, whole
  REQUIRE(r.shown_divisor() == 8);
  CHECK(r.samples() == 0);  // nothing added to the full-resolution mean
  const std::vector<uint8_t> coarse = r.read_display();
  REQUIRE(coarse.size() == size_t(w) * h * 4);
  // Blocks of 8 x 8 equal pixels, and no black row (every row was drawn).
  int unequal = 0, black_rows = 0;
  for (int y = 0; y < h; ++y) {
    bool lit = false;
    for (int x = 0; x < w; ++x) {
      const size_t i = (size_t(y) * w + x) * 4, b = (size_t(y / 8 * 8) * w + x / 8 * 8) * 4;
      unequal += std::memcmp(&coarse[i], &coarse[b], 4) != 0;
      lit = lit || coarse[i] + coarse[i + 1] + coarse[i + 2] > 0;
    }
    black_rows += !lit;
  }
  CHECK(unequal == 0);
  CHECK(black_rows == 0);
  // The sphere where the full image has it: per 8 x 8 block, sky in the coarse image
  // where most of the block's pixels are sky in the full-resolution one (edges may differ).
  while (r.samples() < 4) r.step();
  const std::vector<float> full = r.read_radiance();
  int blocks = 0, mismatched = 0, sphere_blocks = 0;
  for (int by = 0; by < h / 8; ++by)
    for (int bx = 0; bx < w / 8; ++bx) {
      int sky_px = 0;
      for (int y = by * 8; y < by * 8 + 8; ++y)
        for (int x = bx * 8; x < bx * 8 + 8; ++x) sky_px += sky(full, (size_t(y) * w + x) * 4);
      if (sky_px > 8 && sky_px < 56) continue;  // an edge block
      const size_t i = (size_t(by * 8) * w + bx * 8) * 4;
      const bool coarse_sky = coarse[i] > 127;  // the sky reads 255, the sphere 0
      ++blocks;
      sphere_blocks += sky_px <= 8;
      mismatched += coarse_sky != (sky_px >= 56);
    }
  INFO(blocks << " blocks off the sphere's edge, " << sphere_blocks << " on the sphere");
  CHECK(sphere_blocks >= 10);
  CHECK(blocks - sphere_blocks >= 10);
  CHECK(mismatched == 0);
  CHECK(r.shown_divisor() == 1);
  // A camera move: the ladder starts again at 1/8; the full mean is restarted.
  Camera c = r.camera();
  c.position.x += 0.1f;
  r.set_camera(c);
  CHECK(r.samples() == 0);
  CHECK(r.ladder().drawing() == 0);
  CHECK(r.shown_divisor() == 1);  // nothing complete yet
  r.step();
  CHECK(r.shown_divisor() == 8);
  CHECK(r.mid_sweep());  // the ladder counts as a sweep in progress (the page's clock)
}
