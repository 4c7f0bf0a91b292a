#include "algorithms/geometry/terrain_filter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "algorithms/core/error.h"
#include "algorithms/geometry/test_blocks.h"

namespace roofsweep {
namespace {

// 100 x 100 m at 0.5 m: a slope rising 5 % to the east and 2 % to the north.
GroundModel::Grid Slope() {
  return SampledGrid(0, 100, 0.5, 200, 200,
                     [](double x, double y) { return 50 + 0.05 * x + 0.02 * y; });
}

double X(const GroundModel::Grid& g, int c) { return g.x0 + (c + 0.5) * g.dx; }
double Y(const GroundModel::Grid& g, int r) { return g.y0 - (r + 0.5) * g.dy; }

TEST(TerrainFilter, BuildingsAndTreesGoAndTheSlopeStays) {
  const GroundModel::Grid terrain = Slope();
  GroundModel::Grid dsm = terrain;
  std::vector<bool> object(dsm.z.size(), false);
  for (int r = 0; r < dsm.rows; ++r)
    for (int c = 0; c < dsm.cols; ++c) {
      const double x = X(dsm, c), y = Y(dsm, r);
      float& z = dsm.z[r * dsm.cols + c];
      const float before = z;
      if (x > 20 && x < 42 && y > 30 && y < 42) z += 9;                    // a house 22 x 12 m
      if (std::hypot(x - 70, y - 70) < 5) z += 12;                         // a tree crown
      if (x > 55 && x < 80 && y > 40 && y < 58) z += 15 - 0.3 * (x - 55);  // a shed-roofed hall
      object[r * dsm.cols + c] = z != before;
    }
  dsm.z[150 * dsm.cols + 150] = NAN;  // a hole in the data
  const GroundModel::Grid out = TerrainFromSurfaceModel(dsm, 30);
  ASSERT_EQ(out.rows, dsm.rows);
  ASSERT_EQ(out.cols, dsm.cols);
  EXPECT_TRUE(std::isnan(out.z[150 * dsm.cols + 150]));
  // Exact more than half a window (30 cells) from the grid's edge, but
  // under the objects: there the lowest height of a window with the cell at
  // its lowest corner is the nearest ground beside the object, up the
  // slope (at most 0.054 x 6 m under the house). Nearer the edge,
  // the grid holds no whole window: the side where the slope rises comes
  // out lower (by at most the slope times half the window), and an object
  // there may be cut down only in part.
  double inner = 0, edge = 0, under = 0;
  for (int r = 0; r < out.rows; ++r)
    for (int c = 0; c < out.cols; ++c) {
      const size_t i = static_cast<size_t>(r) * out.cols + c;
      if (i == 150u * dsm.cols + 150) continue;
      ASSERT_TRUE(std::isfinite(out.z[i])) << r << " " << c;
      const double e = double(out.z[i]) - terrain.z[i];
      if (object[i]) {
        under = std::max(under, std::abs(e));
      } else if (std::min({r, c, out.rows - 1 - r, out.cols - 1 - c}) >= 30) {
        inner = std::max(inner, std::abs(e));
      } else {
        edge = std::max(edge, -e);
      }
    }
  EXPECT_LT(inner, 1e-3);
  EXPECT_LT(under, 0.7);
  EXPECT_LT(edge, 0.07 * 15 + 1e-3);
}

TEST(TerrainFilter, AnObjectWiderThanTheWindowStays) {
  GroundModel::Grid dsm = Slope();
  const GroundModel::Grid terrain = dsm;
  for (int r = 0; r < dsm.rows; ++r)
    for (int c = 0; c < dsm.cols; ++c)
      if (X(dsm, c) > 22 && X(dsm, c) < 58 && Y(dsm, r) > 22 && Y(dsm, r) < 58)
        dsm.z[r * dsm.cols + c] += 10;  // a hall of 36 x 36 m
  const GroundModel::Grid out = TerrainFromSurfaceModel(dsm, 30);
  const int r = 120, c = 80;  // (40.25, 39.75): the hall's middle
  // The hall stays, its top levelled a little by the flat window on the
  // slope (the lowest window corner, 18 m to the south-west: 1.3 m).
  EXPECT_GT(out.z[r * out.cols + c], terrain.z[r * out.cols + c] + 8.5);
  // ... but a window wider than the hall removes it.
  const GroundModel::Grid wide = TerrainFromSurfaceModel(dsm, 40);
  EXPECT_NEAR(wide.z[r * out.cols + c], terrain.z[r * out.cols + c], 1.0);
}

TEST(TerrainFilter, NoDataAndBadArguments) {
  GroundModel::Grid dsm = Slope();
  for (float& z : dsm.z) z = NAN;
  for (float z : TerrainFromSurfaceModel(dsm, 30).z) EXPECT_TRUE(std::isnan(z));
  EXPECT_THROW(TerrainFromSurfaceModel(dsm, 0), Error);
  dsm.z.pop_back();
  EXPECT_THROW(TerrainFromSurfaceModel(dsm, 30), Error);
}

}  // namespace
}  // namespace roofsweep
