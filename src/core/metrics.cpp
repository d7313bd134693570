#include "core/metrics.h"

#include <cmath>

namespace pt {

ErrorMetrics image_error(const std::vector<float>& image, const std::vector<float>& reference) {
  const bool constant = reference.size() == 4;
  double rel = 0, sq = 0;
  size_t n = 0;
  for (size_t i = 0; i + 3 < image.size(); i += 4)
    for (size_t c = 0; c < 3; ++c) {
      const double r = constant ? reference[c] : reference[i + c];
      const double d = double(image[i + c]) - r;
      rel += d * d / (r * r + 0.01);
      sq += d * d;
      ++n;
    }
  if (n == 0) return {};
  return {rel / double(n), std::sqrt(sq / double(n))};
}

}  // namespace pt
