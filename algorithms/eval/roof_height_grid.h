#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "algorithms/buildings/city_model.h"

namespace roofsweep::eval {

// The roof surface seen from above on a regular plan-view grid: each cell
// holds the z of the highest roof polygon over its centre, like the label
// image the ISPRS evaluation builds ("each pixel is assigned to the highest
// roof plane at that position"). Cells no roof covers are NaN.
struct RoofHeightGrid {
  Eigen::Vector2d origin{0, 0};  // xy of the grid's lower-left corner
  double cell = 0.25;            // m
  int cols = 0, rows = 0;        // row r covers y in origin.y + [r, r+1) * cell
  std::vector<float> z;          // rows * cols, row-major

  float At(int col, int row) const { return z[static_cast<size_t>(row) * cols + col]; }
};

// The grid over both models' bounds, its origin aligned to multiples of
// the cell so that the sampling does not depend on which model reaches
// furthest; nullopt when either model is empty. Throws roofsweep::Error
// beyond 4e8 cells.
struct GridSpan {
  Eigen::Vector2d origin{0, 0};
  int cols = 0, rows = 0;
};
std::optional<GridSpan> SpanGrid(const CityModel& a, const CityModel& b, double cell);

// Rasterises the non-vertical roof polygons of `model` onto the grid spanned
// by `origin`, `cell` and the size. Roof polygons steeper than
// `vertical_roof_deg` are skipped (they have no plan area).
RoofHeightGrid RasteriseRoofs(const CityModel& model, const Eigen::Vector2d& origin, double cell,
                              int cols, int rows, double vertical_roof_deg);

struct HeightComparison {
  long long cells_both = 0;       // cells covered by both models
  long long cells_result = 0;     // covered by the result only
  long long cells_reference = 0;  // covered by the reference only
  double rms = 0;                 // of z_result - z_reference over cells_both
  double mean = 0;                // the same, signed (bias)
};

HeightComparison CompareHeights(const RoofHeightGrid& result, const RoofHeightGrid& reference);

}  // namespace roofsweep::eval
