#include "algorithms/eval/line_surface.h"

#include <gtest/gtest.h>

#include "algorithms/geometry/test_blocks.h"

namespace roofsweep::eval {
namespace {

// A 1 m surface model over x, y in [0, 40): ground at 0, a 10 m block over
// x, y in [10, 20).
GroundModel::Grid BoxSurface() {
  return SampledGrid(0, 40, 1, 40, 40, [](double x, double y) {
    return x >= 10 && x < 20 && y >= 10 && y < 20 ? 10.0 : 0.0;
  });
}

TEST(LinesOnSurface, EdgesOnTheStepAgreeAndLinesInTheAirDoNot) {
  const GroundModel::Grid g = BoxSurface();
  const std::vector<Segment3> lines = {
      {{10, 11, 10}, {10, 19, 10}},  // 0: the block's west eave, on the step
      {{10, 11, 0}, {10, 19, 0}},    // 1: the foot of that wall
      {{30, 5, 10}, {30, 35, 10}},   // 2: 10 m up over open ground: a mismatch
      {{12, 15, 10}, {28, 15, 10}},  // 3: from the roof out into the air
      {{50, 5, 0}, {60, 5, 0}},      // 4: beyond the surface model
  };
  const std::vector<int> views = {2, 3, 2, 2, 3};
  const SurfaceAgreement a = LinesOnSurface(lines, views, g);
  // Two-view lines 0, 2, 3 (4 has no surface under it); line 1 has three.
  EXPECT_EQ(a.lines[0], 3);
  EXPECT_EQ(a.lines[1], 1);
  EXPECT_NEAR(a.length_m[0], 8 + 30 + 16, 1e-9);
  EXPECT_NEAR(a.length_m[1], 8, 1e-9);
  // Line 3 agrees over the roof and up to the window (1.5 m) past the eave
  // at x = 20: 12..21.5, in pieces of 0.5 m.
  EXPECT_NEAR(a.agreeing_m[0], 8 + 0 + 9.5, 1e-9);
  EXPECT_NEAR(a.agreeing_m[1], 8, 1e-9);
  // A tighter window stops line 3 at the eave.
  SurfaceAgreementOptions tight;
  tight.window_m = 0.2;
  EXPECT_NEAR(LinesOnSurface({lines[3]}, {2}, g, tight).agreeing_m[0], 8, 1e-9);
}

}  // namespace
}  // namespace roofsweep::eval
