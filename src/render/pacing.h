// Draw pacing: keep every draw under a target time, long enough to amortise its fixed
// cost, short enough that no GPU watchdog fires and a page stays responsive. The cost of
// one sample of one image row varies across the image (sky rows are cheap, rows of glass
// are not), so the pacer keeps the worst recent cost per row-sample and sizes the next
// draw by prediction: whole sweeps with several samples when they fit, else one sample in
// bands of rows.
#pragma once
#include <algorithm>

#include "render/renderer.h"

namespace pt {

class DrawPacer {
 public:
  explicit DrawPacer(double target_ms) : target_ms_(target_ms) {}

  // The last draw took `ms` for `rows` rows at `spp` samples per pixel.
  void record(double ms, int rows, int spp) {
    const double cost = ms / double(std::max(1, rows) * std::max(1, spp));
    cost_ = std::max(cost, cost_ * 0.9);  // the worst recent cost, slowly forgotten
  }

  // Sets spp_per_pass and band_rows for the next draws (spp applies from the next sweep).
  void apply(int image_rows, RenderSettings& s) const {
    constexpr int kMinRows = 4, kMaxSpp = 256;
    if (cost_ <= 0.0) return;  // nothing measured yet: keep what the caller chose
    const double budget = target_ms_ / cost_;  // row-samples per draw
    if (budget >= 2.0 * image_rows) {
      s.spp_per_pass = std::clamp(int(budget / image_rows), 1, kMaxSpp);
      s.band_rows = 0;
    } else {
      s.spp_per_pass = 1;
      const int rows = std::clamp(int(budget), std::min(kMinRows, image_rows), image_rows);
      s.band_rows = rows >= image_rows ? 0 : rows;
    }
  }

 private:
  double target_ms_;
  double cost_ = 0.0;  // ms per row-sample
};

}  // namespace pt
