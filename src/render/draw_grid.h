// The grid that every partial draw keeps (the pacer's bands and tiles, render/pacing.h; the
// denoiser's slices, render/denoise.h): a band's rows are a multiple of kBandRowsStep, a
// tile's columns a multiple of kTileColumnsStep, so that every draw starts on an even row
// and column. Rasterisers shade 2x2 quads, and SwiftShader's cluster c shades the row pairs
// y / 2 = c mod 16 of a draw (its QuadRasterizer), one task per cluster on its worker
// threads. A band of 5 rows from row 0 shades the pair of rows 4-5, and the next band the
// same pair again, each with half its lanes masked (6 rows of work for 5); every later band
// then starts on an odd row, so a band of 4 rows shades 3 pairs (6 rows of work for 4), and
// 3 pairs give one of 2 threads twice the other's work. 4 rows: 2 pairs, one per thread.
// Measured in the page: docs/benchmarks.md, "Draws on the row-pair grid".
#pragma once

namespace pt {

inline constexpr int kBandRowsStep = 4;
inline constexpr int kTileColumnsStep = 2;

// n rounded down (grid_floor) or up (grid_ceil) to a multiple of `step`, for n >= 0.
constexpr int grid_floor(int n, int step) { return n / step * step; }
constexpr int grid_ceil(int n, int step) { return (n + step - 1) / step * step; }
static_assert(grid_floor(7, kBandRowsStep) == 4 && grid_ceil(5, kTileColumnsStep) == 6 && grid_ceil(4, kBandRowsStep) == 4);

}  // namespace pt
