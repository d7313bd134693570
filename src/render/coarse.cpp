// The coarse ladder's draw size (render/coarse.h).
#include "render/coarse.h"

#include <algorithm>

#include "render/pacing.h"

namespace pt {

void CoarseLadder::draw_size(int band_rows, int band_columns, int full_w, int full_h, int w, int h, int& rows, int& columns) {
  const double r = band_rows > 0 ? std::min(band_rows, full_h) : full_h;
  const double c = band_columns > 0 ? std::min(band_columns, full_w) : full_w;
  const double pixels = r * c;
  const int whole_rows = int(pixels / std::max(1, w));
  if (whole_rows >= std::min(kMinBandRows, h)) {
    rows = whole_rows >= h ? 0 : whole_rows;
    columns = 0;
    return;
  }
  rows = std::min(kMinBandRows, h);
  const int cols = std::max(1, int(pixels / rows));
  columns = cols >= w ? 0 : cols;
}

}  // namespace pt
