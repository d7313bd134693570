// The coarse ladder's draw size (render/coarse.h).
#include "render/coarse.h"

#include <algorithm>

#include "render/pacing.h"

namespace pt {

void CoarseLadder::draw_size(int band_rows, int band_columns, int full_w, int full_h, int w, int h, int& rows, int& columns) {
  const double r = band_rows > 0 ? std::min(band_rows, full_h) : full_h;
  const double c = band_columns > 0 ? std::min(band_columns, full_w) : full_w;
  const double pixels = r * c;
  const int fit = int(pixels / std::max(1, w));  // whole rows of the level in the pacer's pixels
  if (fit >= h) {
    rows = columns = 0;
    return;
  }
  // On the row-pair grid (render/draw_grid.h), as the pacer's own draws.
  const int whole_rows = grid_floor(fit, kBandRowsStep);
  if (whole_rows >= kMinBandRows) {
    rows = whole_rows;
    columns = 0;
    return;
  }
  const int band = std::min(kMinBandRows, h);
  rows = band >= h ? 0 : band;
  const int cols = std::max(kTileColumnsStep, grid_floor(int(pixels / band), kTileColumnsStep));
  columns = cols >= w ? 0 : cols;
}

}  // namespace pt
