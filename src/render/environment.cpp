#include "render/environment.h"

#include <cmath>

namespace pt {

EnvDistribution build_env_distribution(const EnvImage& map) {
  EnvDistribution d;
  const int w = map.width, h = map.height, tw = w + 1;
  d.width = w;
  d.height = h;
  d.cdf_texels.assign(size_t(tw) * size_t(h + 1) * 4, 0.0f);
  auto at = [&](int x, int y) -> float& { return d.cdf_texels[(size_t(y) * tw + size_t(x)) * 4]; };
  std::vector<double> row_sums(size_t(h), 0.0);
  for (int y = 0; y < h; ++y) {
    const double sin_theta = std::sin(3.14159265358979323846 * (y + 0.5) / h);
    double sum = 0.0;
    std::vector<double> cdf(size_t(w) + 1, 0.0);
    for (int x = 0; x < w; ++x) {
      const float* p = &map.rgba[(size_t(y) * w + size_t(x)) * 4];
      sum += (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) * sin_theta;
      cdf[size_t(x) + 1] = sum;
    }
    row_sums[size_t(y)] = sum / w;
    for (int x = 0; x <= w; ++x) at(x, y) = float(sum > 0.0 ? cdf[size_t(x)] / sum : double(x) / w);
    at(w, y) = 1.0f;
  }
  double total = 0.0;
  for (int y = 0; y < h; ++y) {
    at(y, h) = float(total);
    total += row_sums[size_t(y)];
  }
  for (int y = 0; y < h; ++y) at(y, h) = total > 0.0 ? at(y, h) / float(total) : float(y) / h;
  at(h, h) = 1.0f;
  d.integral = float(total / h);
  return d;
}

}  // namespace pt
