// The denoiser (render/denoise.h): on synthetic inputs in the accumulator's layout, it
// keeps a constant image bit for bit, does not blur across a depth step between two planes
// nor across an albedo edge on one plane, reproduces a linear ramp of radiance up to the
// image's borders (the regression pass), and lowers the variance of a noisy flat region by
// a stated factor; on a render, the
// auxiliaries leave the raw image byte-identical in both kernels and the filter only reads
// the accumulation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <random>

#include "gl_context.h"
#include "render/denoise.h"
#include "render/draw_grid.h"
#include "scene_builders.h"

using namespace pt;

namespace {

// The four input images of a w x h test, RGBA each, rows bottom to top.
struct Synthetic {
  int w, h, samples = 64;  // above the gate (DenoiseParams::min_samples): every pass runs
  std::vector<float> radiance, stats, aux0, aux1;
  Synthetic(int w_, int h_) : w(w_), h(h_), radiance(size_t(w_) * h_ * 4), stats(radiance.size()), aux0(radiance.size()), aux1(radiance.size()) {}
  // Pixel (x, y): mean grey radiance `L`, the variance of that mean `var_mean`, albedo,
  // depth and a normal facing the camera.
  void set(int x, int y, float L, float var_mean, float albedo, float depth) {
    const size_t i = (size_t(y) * w + x) * 4;
    const float v = var_mean * float(samples - 1);  // the samples' variance, as accumulated
    for (int k = 0; k < 3; ++k) radiance[i + k] = L, aux0[i + k] = albedo;
    radiance[i + 3] = v;
    stats[i + 2] = stats[i + 3] = v;
    aux0[i + 3] = depth;
    aux1[i + 2] = 1.0f;
  }
  float at(const std::vector<float>& img, int x, int y) const { return img[(size_t(y) * w + x) * 4 + 1]; }
  // The denoised image with blend weight `weight`.
  // With `estimate` >= 0 the weight is measured (Denoiser::run), and left in *measured.
  std::vector<float> denoise(float weight = 1.0f, DenoiseParams params = {}, double estimate = -1.0, float* measured = nullptr) const {
    Texture r(w, h, GL_RGBA32F, radiance.data()), s(w, h, GL_RGBA32F, stats.data()), a0(w, h, GL_RGBA32F, aux0.data()),
        a1(w, h, GL_RGBA32F, aux1.data());
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    Denoiser d;
    d.params = params;
    d.run(DenoiseInputs{&r, &s, &a0, &a1, samples, GL_RGBA32F}, weight, vao, estimate);
    if (measured) *measured = d.weight();
    std::vector<float> out = d.read();
    glDeleteVertexArrays(1, &vao);
    return out;
  }
  // The same in slices (Denoiser::start, advance) of `units` each; `advances` counts them.
  std::vector<float> denoise_sliced(double units, int& advances, float weight = 1.0f) const {
    Texture r(w, h, GL_RGBA32F, radiance.data()), s(w, h, GL_RGBA32F, stats.data()), a0(w, h, GL_RGBA32F, aux0.data()),
        a1(w, h, GL_RGBA32F, aux1.data());
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    Denoiser d;
    const DenoiseInputs in{&r, &s, &a0, &a1, samples, GL_RGBA32F};
    d.start(in, weight);
    for (advances = 1; !d.advance(in, vao, units); ++advances) {
      INFO("after slice " << advances << ": row " << d.next_row());
      REQUIRE(d.next_row() % kBandRowsStep == 0);  // every slice starts on the row-pair grid (render/draw_grid.h)
    }
    std::vector<float> out = d.read();
    glDeleteVertexArrays(1, &vao);
    return out;
  }
};

bool same_rgb(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); i += 4)
    if (std::memcmp(&a[i], &b[i], 3 * sizeof(float)) != 0) return false;
  return true;
}

// The noisy step: left half radiance 0.6 at depth 1, right half 0.4 at `right_depth`, the
// same albedo and normal, Gaussian noise of standard deviation 0.1 (the reported one).
Synthetic noisy_step(float right_depth) {
  Synthetic s(64, 32);
  std::mt19937 rng(7);
  std::normal_distribution<float> noise(0.0f, 0.1f);
  for (int y = 0; y < s.h; ++y)
    for (int x = 0; x < s.w; ++x) s.set(x, y, (x < 32 ? 0.6f : 0.4f) + noise(rng), 0.01f, 0.5f, x < 32 ? 1.0f : right_depth);
  return s;
}

// A noisy ramp at `samples` spp with an albedo edge and a depth slope: both the albedo term
// and the regression change it.
Synthetic noisy_ramp(int samples, unsigned seed, int w = 48, int h = 32) {
  Synthetic s(w, h);
  s.samples = samples;
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, 0.05f);
  for (int y = 0; y < s.h; ++y)
    for (int x = 0; x < s.w; ++x)
      s.set(x, y, 0.2f + 0.48f / float(w) * float(x) + noise(rng), 0.0025f, x < w / 2 ? 0.5f : 0.6f, 1.0f + 0.02f * float(x));
  return s;
}

double column_mean(const Synthetic& s, const std::vector<float>& img, int x) {
  double m = 0;
  for (int y = 0; y < s.h; ++y) m += s.at(img, x, y);
  return m / s.h;
}

}  // namespace

TEST_CASE("denoiser: a constant image comes back bit for bit, and weight 0 is the raw image", "[gpu][denoise]") {
  test_gl();
  Synthetic s(40, 30);
  for (int y = 0; y < s.h; ++y)
    for (int x = 0; x < s.w; ++x) s.set(x, y, 0.3f, 0.02f, 0.7f, 1.0f + 0.05f * x);  // a slanted plane
  CHECK(same_rgb(s.denoise(), s.radiance));
  Synthetic n = noisy_step(1.0f);
  CHECK(same_rgb(n.denoise(0.0f), n.radiance));
  CHECK_FALSE(same_rgb(n.denoise(1.0f), n.radiance));
}

TEST_CASE("denoiser: no blur across a depth step between two planes", "[gpu][denoise]") {
  test_gl();
  // Radiance 0.6 | 0.4, noise 0.1: the luminance weight alone lets the step through
  // (a difference of 2 standard deviations, sigma_l 4), so only the depth stops it.
  const Synthetic step = noisy_step(2.0f), flat = noisy_step(1.0f);
  const std::vector<float> a = step.denoise(), b = flat.denoise();
  // The two columns either side of the step: the noise's standard error over a column
  // before filtering is 0.1 / sqrt(32) = 0.018; filtered within the plane, less.
  for (int x : {30, 31, 32, 33}) {
    const double truth = x < 32 ? 0.6 : 0.4;
    INFO("column " << x << ": with the depth step " << column_mean(step, a, x) << ", on one plane " << column_mean(flat, b, x));
    CHECK(std::abs(column_mean(step, a, x) - truth) < 0.03);
  }
  // Without the depth step the same filter does blur it (the test can see a blur).
  CHECK(column_mean(flat, b, 31) - column_mean(flat, b, 32) < 0.12);
}

TEST_CASE("denoiser: no blur across an albedo edge on one plane (a light's rim)", "[gpu][denoise]") {
  test_gl();
  // One plane, one normal, one depth: left albedo 0.5 and radiance 0.6, right albedo 0.6
  // and radiance 0.48 (demodulated 1.2 | 0.8), noise 0.1: the luminance weight lets the
  // step through (as above), the geometry cannot see it, only the albedo term stops it.
  auto make = [](float right_albedo) {
    Synthetic s(64, 32);
    std::mt19937 rng(11);
    std::normal_distribution<float> noise(0.0f, 0.1f);
    for (int y = 0; y < s.h; ++y)
      for (int x = 0; x < s.w; ++x)
        s.set(x, y, (x < 32 ? 0.6f : 0.8f * right_albedo) + noise(rng), 0.01f, x < 32 ? 0.5f : right_albedo, 1.0f);
    return s;
  };
  const Synthetic s = make(0.6f);
  const std::vector<float> a = s.denoise();
  for (int x : {30, 31, 32, 33}) {
    const double truth = x < 32 ? 0.6 : 0.48;
    INFO("column " << x << ": " << column_mean(s, a, x));
    CHECK(std::abs(column_mean(s, a, x) - truth) < 0.03);
  }
  // Without the albedo term the same filter does blur it (the test can see a blur).
  DenoiseParams off;
  off.sigma_a = 0.0f;  // off
  const std::vector<float> b = s.denoise(1.0f, off);
  INFO("without the albedo term: columns 31, 32 " << column_mean(s, b, 31) << ", " << column_mean(s, b, 32));
  CHECK(column_mean(s, b, 31) - column_mean(s, b, 32) < 0.08);
}

TEST_CASE("denoiser: a light seen directly and its rim stay raw and do not bleed into the plane around them", "[gpu][denoise]") {
  test_gl();
  // A ceiling (albedo 0.73, radiance 0.3, noisy) with a light in it (radiance 17, albedo 1
  // by the auxiliaries' convention) on the same plane and normal, and a rim column whose
  // pixels are 10% to 90% light (an edge at a slant; the auxiliaries' light part). A rim
  // pixel's albedo lies between the two, and its demodulated value is not linear in it.
  auto make = [](int samples, bool marked) {
    Synthetic s(64, 32);
    s.samples = samples;
    std::mt19937 rng(3);
    std::normal_distribution<float> noise(0.0f, 0.05f);
    for (int y = 0; y < s.h; ++y)
      for (int x = 0; x < s.w; ++x) {
        const float part = x < 30 ? 0.0f : x == 30 ? 0.1f + 0.8f * float(y * 3 % 8) / 7.0f : 1.0f;  // of the samples on the light
        const float L = part * 17.0f + (1.0f - part) * (0.3f + noise(rng));
        s.set(x, y, L, part > 0.0f ? 1.0f : 0.0004f, part + (1.0f - part) * 0.73f, 1.0f);
        if (marked) s.aux1[(size_t(y) * s.w + x) * 4 + 3] = part;
      }
    return s;
  };
  for (int n : {1, 64}) {  // below and above the gate (DenoiseParams::min_samples)
    INFO(n << " spp");
    const Synthetic s = make(n, true);
    const std::vector<float> a = s.denoise();
    for (int x = 30; x < 64; ++x)
      for (int y = 0; y < s.h; ++y) {
        const size_t i = (size_t(y) * s.w + x) * 4;
        INFO("pixel " << x << ", " << y);
        REQUIRE(std::memcmp(&a[i], &s.radiance[i], 3 * sizeof(float)) == 0);
      }
    for (int x : {26, 27, 28, 29}) {
      INFO("ceiling column " << x << ": " << column_mean(s, a, x));
      CHECK(std::abs(column_mean(s, a, x) - 0.3) < 0.03);
    }
    // Unmarked (every part 0), the same filter carries the light into the ceiling or mixes
    // the rim's pixels: the test can see both.
    const Synthetic u = make(n, false);
    const std::vector<float> b = u.denoise();
    double rim_change = 0;
    for (int y = 0; y < u.h; ++y) rim_change = std::max(rim_change, double(std::abs(u.at(b, 30, y) - u.at(u.radiance, 30, y))));
    INFO("unmarked: column 29 " << column_mean(u, b, 29) << ", the largest change of a rim pixel " << rim_change);
    CHECK((std::abs(column_mean(u, b, 29) - 0.3) > 0.03 || rim_change > 0.5));
  }
}

TEST_CASE("denoiser: a linear ramp of radiance on a plane comes back to the borders (the regression)", "[gpu][denoise]") {
  test_gl();
  // Noise-free radiance 0.2 + 0.01 x + 0.005 y on a slanted plane, reported with a variance
  // (so the a-trous filter does blur): a weighted local first-order regression reproduces a
  // linear function exactly, also where its window is one-sided; a weighted mean is biased
  // there (towards the image's inside).
  Synthetic s(48, 32);
  auto ramp = [](int x, int y) { return 0.2f + 0.01f * float(x) + 0.005f * float(y); };
  for (int y = 0; y < s.h; ++y)
    for (int x = 0; x < s.w; ++x) s.set(x, y, ramp(x, y), 0.01f, 0.5f, 1.0f + 0.02f * float(x));
  auto worst = [&](const std::vector<float>& img) {
    double e = 0;
    for (int y = 0; y < s.h; ++y)
      for (int x = 0; x < s.w; ++x) e = std::max(e, double(std::abs(s.at(img, x, y) - ramp(x, y))));
    return e;
  };
  DenoiseParams unfiltered;
  unfiltered.reg_input = 0;  // the regression fits the prepare pass's output
  const double regression = worst(s.denoise(1.0f, unfiltered));
  DenoiseParams atrous;
  atrous.reg_radius = 0;  // the a-trous iterations alone
  const double mean = worst(s.denoise(1.0f, atrous));
  // The shipped configuration fits a-trous iteration 1's output, itself a 5x5 weighted
  // mean (one-sided within 2 pixels of the border): not exact there, but far closer.
  const double shipped = worst(s.denoise());
  INFO("largest error: the regression of the unfiltered image " << regression << ", a-trous alone " << mean << ", shipped "
                                                                  << shipped);
  CHECK(regression < 1e-4);
  CHECK(mean > 0.01);
  CHECK(shipped < 0.1 * mean);
  // A window whose taps lie on one line (an image one pixel high: no vertical offsets) is
  // singular; the ridge on the slopes keeps the fit finite, and the ramp along the line
  // is still fitted.
  Synthetic line(48, 1);
  for (int x = 0; x < line.w; ++x) line.set(x, 0, ramp(x, 0), 0.01f, 0.5f, 1.0f);
  const std::vector<float> l = line.denoise(1.0f, unfiltered);
  double e = 0;
  for (int x = 0; x < line.w; ++x) e = std::max(e, std::isfinite(line.at(l, x, 0)) ? double(std::abs(line.at(l, x, 0) - ramp(x, 0))) : 1e30);
  INFO("one row: largest error " << e);
  CHECK(e < 1e-4);
}

TEST_CASE("denoiser: below min_samples the output is the a-trous passes' alone bit for bit, from it not", "[gpu][denoise]") {
  test_gl();
  // A noisy ramp with an albedo edge: both the albedo term and the regression change it.
  auto make = [](int samples) { return noisy_ramp(samples, 5); };
  DenoiseParams atrous;  // main's filter: no albedo term, no regression
  atrous.sigma_a = 0.0f;
  atrous.reg_radius = 0;
  const int n_min = DenoiseParams{}.min_samples;
  REQUIRE(n_min > 1);
  for (int n : {1, n_min / 4, n_min - 1}) {
    const Synthetic s = make(n);
    INFO(n << " spp");
    CHECK(same_rgb(s.denoise(), s.denoise(1.0f, atrous)));
  }
  for (int n : {n_min, 4 * n_min}) {
    const Synthetic s = make(n);
    INFO(n << " spp");
    CHECK_FALSE(same_rgb(s.denoise(), s.denoise(1.0f, atrous)));
    // Either component alone changes it too (each is gated, not only one).
    DenoiseParams albedo_only = atrous;
    albedo_only.sigma_a = DenoiseParams{}.sigma_a;
    DenoiseParams regression_only = atrous;
    regression_only.reg_radius = DenoiseParams{}.reg_radius;
    CHECK_FALSE(same_rgb(s.denoise(1.0f, albedo_only), s.denoise(1.0f, atrous)));
    CHECK_FALSE(same_rgb(s.denoise(1.0f, regression_only), s.denoise(1.0f, atrous)));
  }
}

TEST_CASE("denoiser: a noisy flat region's variance falls at least 25-fold", "[gpu][denoise]") {
  test_gl();
  Synthetic s(64, 64);
  std::mt19937 rng(3);
  std::normal_distribution<float> noise(0.0f, 0.1f);
  for (int y = 0; y < s.h; ++y)
    for (int x = 0; x < s.w; ++x) s.set(x, y, 0.5f + noise(rng), 0.01f, 0.8f, 2.0f);
  const std::vector<float> out = s.denoise();
  auto variance = [&](const std::vector<float>& img) {  // over the inner 32x32 (no border)
    double m = 0, m2 = 0;
    for (int y = 16; y < 48; ++y)
      for (int x = 16; x < 48; ++x) m += s.at(img, x, y), m2 += double(s.at(img, x, y)) * s.at(img, x, y);
    m /= 1024.0;
    return m2 / 1024.0 - m * m;
  };
  const double before = variance(s.radiance), after = variance(out);
  INFO("variance before " << before << ", after " << after << ": " << before / after << "x lower");
  CHECK(before / after > 25.0);
}

TEST_CASE("denoiser: the measured blend weight is min(1, E / D), D the filter's own change, and fades with E", "[gpu][denoise]") {
  test_gl();
  // A noisy ramp with an albedo edge at 64 spp (both passes above the gate run), 130x70
  // pixels: not a whole number of the change pass's blocks.
  const Synthetic s = noisy_ramp(64, 9, 130, 70);
  const std::vector<float> full = s.denoise(1.0f);  // weight 1, none measured
  double d = 0;  // the change of the weight-1 image, relative, per channel, as the pass sums it
  for (size_t i = 0; i < full.size(); i += 4)
    for (int c = 0; c < 3; ++c) {
      const double raw = s.radiance[i + c], dc = double(full[i + c]) - raw;
      d += dc * dc / (raw * raw + 0.01);
    }
  d /= double(s.w) * s.h * 3;
  REQUIRE(d > 0);
  for (double e : {4.0 * d, 0.5 * d, 0.1 * d, 1e-6 * d}) {
    INFO("E = " << e / d << " D");
    float w = -1.0f;
    const std::vector<float> out = s.denoise(1.0f, {}, e, &w);
    CHECK(w == Approx(std::min(1.0, e / d)).epsilon(1e-3));
    double worst = 0;  // out is raw + w (full - raw)
    for (size_t i = 0; i < out.size(); i += 4)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(out[i + c]) - (s.radiance[i + c] + double(w) * (full[i + c] - s.radiance[i + c]))));
    CHECK(worst < 1e-5);
  }
  // The cap: a given weight of 0.5 and E above D measure 0.5.
  float w = -1.0f;
  s.denoise(0.5f, {}, 4.0 * d, &w);
  CHECK(w == 0.5f);
  // In slices (the page), weight() stays the last complete run's, the image output() holds,
  // until the next run is complete.
  Texture r(s.w, s.h, GL_RGBA32F, s.radiance.data()), st(s.w, s.h, GL_RGBA32F, s.stats.data()),
      a0(s.w, s.h, GL_RGBA32F, s.aux0.data()), a1(s.w, s.h, GL_RGBA32F, s.aux1.data());
  GLuint vao = 0;
  glGenVertexArrays(1, &vao);
  const DenoiseInputs in{&r, &st, &a0, &a1, s.samples, GL_RGBA32F};
  Denoiser dn;
  dn.run(in, 1.0f, vao, 0.5 * d);
  const float first = dn.weight();
  CHECK(first == Approx(0.5).epsilon(1e-3));
  dn.start(in, 1.0f, 0.1 * d);
  CHECK_FALSE(dn.advance(in, vao, 100.0));
  CHECK(dn.weight() == first);
  while (!dn.advance(in, vao, 1e4)) {}
  CHECK(dn.weight() == Approx(0.1).epsilon(1e-3));
  glDeleteVertexArrays(1, &vao);
}

TEST_CASE("denoiser: the auxiliaries leave the raw image byte-identical; the filter only reads it", "[gpu][denoise]") {
  test_gl();
  Material wall;  // Lambertian, emitting: a noisy image with a known albedo everywhere
  wall.tint = glm::vec3(0.6f);
  wall.emission = glm::vec3(1.0f);
  const Scene scene = closed_room(wall);
  for (bool compute : {false, true}) {
    std::vector<float> raw[2];
    for (int aux = 0; aux < 2; ++aux) {
      Renderer r;
      r.resize(32, 24);
      RenderSettings st;
      st.compute = compute;
      st.aux = aux == 1;
      st.sample_limit = 6;
      st.spp_per_pass = 2;
      st.band_rows = 7;  // tiles: the copy-back covers the auxiliaries too
      st.band_columns = 13;
      r.set_settings(st);
      r.set_scene(scene);
      while (!r.converged()) r.step();
      raw[aux] = r.read_radiance();
      if (aux) {
        const std::vector<float> albedo = r.accumulator().read_aux(0), normal = r.accumulator().read_aux(1);
        double mean_albedo = 0, mean_normal = 0;
        for (size_t i = 0; i < albedo.size(); i += 4)
          mean_albedo += albedo[i + 1], mean_normal += std::sqrt(normal[i] * normal[i] + normal[i + 1] * normal[i + 1] + normal[i + 2] * normal[i + 2]);
        CHECK(mean_albedo / double(albedo.size() / 4) == Approx(0.6).epsilon(1e-5));  // every first hit a wall
        CHECK(mean_normal / double(albedo.size() / 4) > 0.98);  // unit normals, averaged only at edges
        const std::vector<float> denoised = r.read_denoised(1.0f);
        CHECK(r.read_radiance() == raw[aux]);  // the accumulation is untouched
        CHECK_FALSE(same_rgb(denoised, raw[aux]));
        CHECK(same_rgb(r.read_denoised(0.0f), raw[aux]));
      }
    }
    INFO((compute ? "compute" : "fragment") << " kernel");
    CHECK(raw[0] == raw[1]);
  }
}

TEST_CASE("denoiser: the auxiliaries mark a light the camera sees, not its image in a mirror", "[gpu][denoise]") {
  test_gl();
  // A light (Emit) left of centre and a sphere right of it that is a mirror or diffuse, in
  // a grey room. Both spheres cover the same pixels either way, so the marked part of the
  // image (auxiliary 1's w, camera_aux.glsl) is the same: the mirror's image of the light is
  // not marked (left raw, glass's per-sample choices would keep their fireflies).
  auto marked = [](bool mirror, std::vector<float>* aux) {
    Material wall;
    wall.tint = glm::vec3(0.5f);
    Scene scene = closed_room(wall);
    Material light = Emit{};
    light.emission = glm::vec3(5.0f);
    Material ball = mirror ? Material(Reflect{}) : Material{};
    add_sphere(scene, {-0.35f, 0.0f, -0.6f}, 0.2f, add_material(scene, light));
    add_sphere(scene, {0.35f, 0.0f, -0.6f}, 0.3f, add_material(scene, ball));
    Renderer r;
    r.resize(48, 32);
    RenderSettings st;
    st.aux = true;
    st.sample_limit = 4;
    r.set_settings(st);
    r.set_scene(scene);
    while (!r.converged()) r.step();
    *aux = r.accumulator().read_aux(1);
    double sum = 0;
    for (size_t i = 3; i < aux->size(); i += 4) sum += (*aux)[i];
    return sum;
  };
  std::vector<float> a, b;
  const double with_mirror = marked(true, &a), with_diffuse = marked(false, &b);
  CHECK(with_mirror > 20.0);  // the light covers about 30 of the 1536 pixels
  CHECK(with_mirror == with_diffuse);
  // The light's centre pixel is all light; the walls are not.
  const int w = 48;
  auto at = [&](int x, int y) { return a[(size_t(y) * w + x) * 4 + 3]; };
  int full = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < w; ++x) full += at(x, y) == 1.0f;
  CHECK(full > 5);
  CHECK(at(2, 2) == 0.0f);
  CHECK(at(45, 29) == 0.0f);
}

TEST_CASE("denoiser: in slices of a few rows, the same image as one run, bit for bit, below and above the gate", "[gpu][denoise]") {
  test_gl();
  for (int n : {4, 64}) {
    const Synthetic s = noisy_ramp(n, 11);
    INFO(n << " spp");
    int advances = 0;
    // 100 units: 2 rows of an a-trous iteration at 48 pixels a row, 1 of the regression;
    // slices keep the row-pair grid, so each is the grid's least, kBandRowsStep rows.
    const std::vector<float> sliced = s.denoise_sliced(100.0, advances, 0.7f);
    CHECK(advances >= 5 * 32 / kBandRowsStep);  // 5 iterations of 8 slices
    CHECK(same_rgb(sliced, s.denoise(0.7f)));
  }
}

TEST_CASE("denoiser in the renderer, sliced (the page's): raw until a run is complete, then what one run shows; a restart shows raw again", "[gpu][denoise]") {
  test_gl();
  Material wall;
  wall.tint = glm::vec3(0.6f);
  wall.emission = glm::vec3(1.0f);
  const Scene scene = closed_room(wall);
  RenderSettings st;
  st.aux = true;
  st.denoise = 1.0f;
  st.sample_limit = 4;
  auto make = [&](bool sliced) {
    auto r = std::make_unique<Renderer>();
    r->resize(40, 30);
    r->set_settings(st);
    r->set_sliced_denoise(sliced);
    r->set_scene(scene);
    while (!r->converged()) r->step();
    return r;
  };
  const auto whole = make(false), sliced = make(true);
  RenderSettings raw_st = st;
  raw_st.denoise = 0.0f;
  const auto raw = make(false);
  raw->set_settings(raw_st);  // the same samples shown unfiltered
  REQUIRE(sliced->denoised_samples() == 0);
  CHECK(sliced->read_display() == raw->read_display());
  int frames = 0;
  while (sliced->denoised_samples() == 0 && frames < 10000) {
    sliced->advance_denoiser(200.0);  // 5 rows of an a-trous iteration: 4, on the row-pair grid
    ++frames;
    if (sliced->denoised_samples() == 0) CHECK(sliced->read_display() == raw->read_display());
  }
  INFO(frames << " frames");
  CHECK(frames > 5 * 30 / 4);
  CHECK(sliced->denoised_samples() == 4);
  CHECK(sliced->read_display() == whole->read_display());
  CHECK(sliced->read_display() != raw->read_display());
  // A restart: the filtered image is of the last one, so the raw mean is shown again.
  Camera c = sliced->camera();
  c.position += glm::vec3(0.01f, 0.0f, 0.0f);
  sliced->set_camera(c);
  sliced->step();
  CHECK(sliced->denoised_samples() == 0);
}
