// make_wood_texture: writes the wood floor of seed scene 3, the project's own procedural
// work (CC0): assets/textures/wood_diffuse.png (sRGB colour), wood_specular.png (sRGB,
// varnish reflectance) and wood_normal.png (tangent space, OpenGL convention: green = +v).
// Deterministic (integer hashes, no clock, no RNG state): the same files on every run.
// Every map tiles seamlessly (all noise is periodic over the image).
//
//   build/native/make_wood_texture assets/textures      (size 512 by default, or a 2nd argument)
//
// Planks run along u, kPlanks of them across v, each cut once at a per-plank position; the
// grain is rings of a log (distance to a per-plank axis, warped by periodic value noise);
// the height field (grooves between planks, a faint grain relief) gives the normal map.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/image.h"

namespace {

constexpr int kPlanks = 4;
constexpr double kPi = 3.14159265358979323846;

uint32_t hash(uint32_t x) {  // PCG-style integer hash
  x = x * 747796405u + 2891336453u;
  x = ((x >> ((x >> 28u) + 4u)) ^ x) * 277803737u;
  return (x >> 22u) ^ x;
}
double rand01(uint32_t a, uint32_t b, uint32_t c) { return hash(a + hash(b + hash(c))) / 4294967296.0; }

// Value noise on a periodic lattice of `cells` per unit: tiles with period 1 in x and y.
double noise(double x, double y, int cells, uint32_t seed) {
  const double fx = x * cells, fy = y * cells;
  const int ix = int(std::floor(fx)), iy = int(std::floor(fy));
  const double tx = fx - ix, ty = fy - iy;
  auto at = [&](int i, int j) { return rand01(uint32_t((i % cells + cells) % cells), uint32_t((j % cells + cells) % cells), seed); };
  const double sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
  return (1 - sy) * ((1 - sx) * at(ix, iy) + sx * at(ix + 1, iy)) + sy * ((1 - sx) * at(ix, iy + 1) + sx * at(ix + 1, iy + 1));
}
double fbm(double x, double y, int cells, uint32_t seed) {
  double s = 0, a = 0.5;
  for (int o = 0; o < 4; ++o, cells *= 2, a *= 0.5) s += a * noise(x, y, cells, seed + uint32_t(o));
  return s;
}

uint8_t code(double srgb) { return uint8_t(std::lround(std::fmin(1.0, std::fmax(0.0, srgb)) * 255.0)); }
double linear_to_srgb(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055; }

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: make_wood_texture OUT_DIR [SIZE]\n");
    return 2;
  }
  const std::string dir = argv[1];
  const int n = argc > 2 ? std::atoi(argv[2]) : 512;
  std::vector<double> height(size_t(n) * n);
  std::vector<uint8_t> diffuse(size_t(n) * n * 4), specular(size_t(n) * n * 4), normal(size_t(n) * n * 4);
  const double groove = 1.5 / n;  // half-width of the gap between planks, in uv
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double u = (x + 0.5) / n, v = (y + 0.5) / n;
      const int plank = int(v * kPlanks);
      const double pv = v * kPlanks - plank;  // 0..1 across the plank
      const double cut = rand01(uint32_t(plank), 7u, 1u);  // where this plank's two boards meet
      const int board = (u - cut + 1.0) - std::floor(u - cut + 1.0) < 0.5 ? 0 : 1;
      const uint32_t id = uint32_t(plank * 2 + board);
      // Rings: distance from a log axis below the board, warped by noise along the grain.
      const double warp = fbm(u, v, 4, 11u + id) * 0.35 + 0.08 * std::sin(2 * kPi * (u * 2 + rand01(id, 3u, 3u)));
      const double r = (pv + 0.6 + rand01(id, 5u, 5u)) * 9.0 + warp * 7.0;
      const double ring = std::pow(0.5 + 0.5 * std::cos(2 * kPi * r), 3.0);
      const double fine = fbm(u, v * 8.0, 8, 29u + id);  // streaks along the board (along u)
      const double tone = 0.85 + 0.3 * rand01(id, 9u, 9u);
      double dist_u = std::fabs(u - cut - std::floor(u - cut + 0.5));             // to the boards' joint
      dist_u = std::fmin(dist_u, std::fabs(u - cut - 0.5 - std::floor(u - cut)));  // the other joint
      const double dist_v = std::fmin(pv, 1.0 - pv) / kPlanks;
      const bool gap = dist_v < groove || dist_u < groove;
      const double shade = tone * (1.0 - 0.3 * ring - 0.25 * fine);
      double c[3] = {0.66 * shade, 0.44 * shade, 0.25 * shade};  // sRGB
      if (gap) c[0] = 0.18, c[1] = 0.11, c[2] = 0.06;
      uint8_t* d = &diffuse[(size_t(y) * n + x) * 4];
      for (int k = 0; k < 3; ++k) d[k] = code(c[k]);
      d[3] = 255;
      // Varnish: a reflectance of about 0.06 on the boards, little in the gaps.
      const double s = gap ? 0.01 : 0.05 + 0.02 * fine;
      uint8_t* sp = &specular[(size_t(y) * n + x) * 4];
      sp[0] = sp[1] = sp[2] = code(linear_to_srgb(s));
      sp[3] = 255;
      height[size_t(y) * n + x] = (gap ? -1.0 : 0.0) + 0.15 * ring;  // in units of a texel
    }
  // Normal from the height field's central differences (periodic): n = (-dh/du, -dh/dv, 1).
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      auto h = [&](int i, int j) { return height[size_t((j + n) % n) * n + size_t((i + n) % n)]; };
      const double gx = 0.5 * (h(x + 1, y) - h(x - 1, y)), gy = 0.5 * (h(x, y + 1) - h(x, y - 1));
      const double len = std::sqrt(gx * gx + gy * gy + 1.0);
      const double v3[3] = {-gx / len, -gy / len, 1.0 / len};
      uint8_t* p = &normal[(size_t(y) * n + x) * 4];
      // The loader's decoding: code c -> (c - 128) / 127, so 128 is exactly 0.
      for (int k = 0; k < 3; ++k) p[k] = uint8_t(std::lround(std::fmin(255.0, std::fmax(1.0, 128.0 + 127.0 * v3[k]))));
      p[3] = 255;
    }
  // write_png takes rows bottom to top: row y = 0 is v = 0, the bottom of the image.
  bool ok = pt::write_png(dir + "/wood_diffuse.png", n, n, diffuse);
  ok = pt::write_png(dir + "/wood_specular.png", n, n, specular) && ok;
  ok = pt::write_png(dir + "/wood_normal.png", n, n, normal) && ok;
  if (!ok) {
    std::fprintf(stderr, "make_wood_texture: cannot write into %s\n", dir.c_str());
    return 1;
  }
  std::printf("wrote %s/wood_{diffuse,specular,normal}.png (%dx%d)\n", dir.c_str(), n, n);
  return 0;
}
