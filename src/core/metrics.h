// Error metrics of an image against a reference, over RGB of RGBA pixels.
#pragma once
#include <vector>

namespace pt {

struct ErrorMetrics {
  double rel_mse = 0;  // mean of (x - r)^2 / (r^2 + 0.01) over pixels and channels
  double rmse = 0;     // sqrt of the mean of (x - r)^2
};

// `reference` may hold one pixel (a constant image, e.g. an analytic answer).
ErrorMetrics image_error(const std::vector<float>& image, const std::vector<float>& reference);

}  // namespace pt
