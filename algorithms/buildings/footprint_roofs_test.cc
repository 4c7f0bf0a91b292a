#include "algorithms/buildings/footprint_roofs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "algorithms/buildings/convex_polygon2.h"

namespace roofsweep {
namespace {

double ZAt(const Eigen::Vector4d& p, const Eigen::Vector2d& q) {
  return -(p[0] * q.x() + p[1] * q.y() + p[3]) / p[2];
}

// A 10 x 6 m footprint turned by 30°, with a notch that does not change
// its hull's rectangle: the models' faces follow the rectangle's axes.
TEST(RoofModelsOver, FlatShedsAndGablesAlongTheFootprintsAxes) {
  const double a = 30 * M_PI / 180;
  const Eigen::Vector2d t(std::cos(a), std::sin(a)), n(-t.y(), t.x()), o(5, -3);
  auto at = [&](double u, double v) { return Eigen::Vector2d(o + u * t + v * n); };
  Footprint f;
  f.id = "F";
  f.outline = {at(0, 0), at(10, 0), at(10, 6), at(6, 6), at(5, 5.5), at(4, 6), at(0, 6)};
  RoofModelOptions opt;
  opt.shed_slopes_deg = {10};
  opt.gable_slopes_deg = {35};
  opt.hip_slopes_deg = {};
  const std::vector<RoofModel> models = RoofModelsOver(f, opt);
  ASSERT_EQ(models.size(), 1u + 4 + 2);
  EXPECT_EQ(models[0].name, "flat");
  ASSERT_EQ(models[0].faces.size(), 1u);
  EXPECT_NEAR(std::abs(SignedArea(models[0].faces[0].patch)), 60, 1e-9);
  const double k10 = std::tan(10 * M_PI / 180), k35 = std::tan(35 * M_PI / 180);
  int sheds = 0, gables = 0;
  for (size_t m = 1; m < models.size(); ++m) {
    const RoofModel& r = models[m];
    if (r.faces.size() == 1) {
      // A shed: eaves (z = 0) along one side, the opposite side as high as
      // the slope over the rectangle's depth across that side.
      ++sheds;
      const Eigen::Vector4d& p = r.faces[0].plane;
      double lo = 1e9, hi = -1e9;
      for (const auto& q : {at(0, 0), at(10, 0), at(10, 6), at(0, 6)})
        lo = std::min(lo, ZAt(p, q)), hi = std::max(hi, ZAt(p, q));
      EXPECT_NEAR(lo, 0, 1e-9) << r.name;
      EXPECT_TRUE(std::abs(hi - 10 * k10) < 1e-9 || std::abs(hi - 6 * k10) < 1e-9) << r.name << hi;
    } else {
      // A gable: two faces of half the footprint's hull each, meeting at
      // the ridge halfway across, eaves at 0.
      ++gables;
      ASSERT_EQ(r.faces.size(), 2u);
      // The rectangle's centre lies on either ridge: 3 m or 5 m from the
      // eaves.
      const double rise = ZAt(r.faces[0].plane, at(5, 3));
      EXPECT_TRUE(std::abs(rise - 3 * k35) < 1e-9 || std::abs(rise - 5 * k35) < 1e-9) << r.name;
      for (const RoofModelFace& face : r.faces) {
        EXPECT_NEAR(ZAt(face.plane, at(5, 3)), rise, 1e-9) << r.name;
        double area = std::abs(SignedArea(face.patch));
        EXPECT_GT(area, 25) << r.name;
        EXPECT_LT(area, 32) << r.name;
      }
    }
  }
  EXPECT_EQ(sheds, 4);
  EXPECT_EQ(gables, 2);
  // Raised to eaves at 7.5 m: every face moves up by 7.5 m, marked derived.
  const RoofPlaneHypothesis h = RoofModelFaceAt(f, models.back(), 1, 7.5);
  EXPECT_TRUE(h.derived);
  EXPECT_NEAR(ZAt(h.plane, at(5, 3)) - ZAt(models.back().faces[1].plane, at(5, 3)), 7.5, 1e-9);
  EXPECT_NE(h.id.find("over footprint F, face 2"), std::string::npos) << h.id;
  EXPECT_NEAR(h.longest_line_m, 10, 1e-9);
}

// A 10 x 6 m rectangle, hipped at 30°: two trapezoids along the long
// sides and two triangular hip ends, meeting at a ridge 3 tan 30° high
// that runs 4 m along the middle (the hips at 45° in plan).
TEST(RoofModelsOver, HippedRoofFacesMeetAlongTheRidgeAndTheHips) {
  Footprint f;
  f.id = "H";
  f.outline = {{0, 0}, {10, 0}, {10, 6}, {0, 6}};
  RoofModelOptions opt;
  opt.shed_slopes_deg = {};
  opt.gable_slopes_deg = {};
  opt.hip_slopes_deg = {30};
  const std::vector<RoofModel> models = RoofModelsOver(f, opt);
  ASSERT_EQ(models.size(), 2u);
  const RoofModel& hip = models[1];
  EXPECT_EQ(hip.name, "hipped 30°");
  ASSERT_EQ(hip.faces.size(), 4u);
  const double k = std::tan(30 * M_PI / 180);
  std::vector<double> areas;
  double total = 0;
  for (const RoofModelFace& face : hip.faces) {
    const double a = std::abs(SignedArea(face.patch));
    areas.push_back(a);
    total += a;
    // Every face reaches the ridge's ends (3, 3) and (7, 3) or one of them,
    // at the ridge's height, and no face's patch rises above it.
    for (const auto& q : face.patch) EXPECT_LE(ZAt(face.plane, q), 3 * k + 1e-9);
    const double z3 = ZAt(face.plane, {3, 3}), z7 = ZAt(face.plane, {7, 3});
    EXPECT_TRUE(std::abs(z3 - 3 * k) < 1e-9 || std::abs(z7 - 3 * k) < 1e-9);
    // Its eave lies on the footprint's outline, at height 0.
    double lowest = 1e9;
    for (const auto& q : face.patch) lowest = std::min(lowest, ZAt(face.plane, q));
    EXPECT_NEAR(lowest, 0, 1e-9);
  }
  std::sort(areas.begin(), areas.end());
  EXPECT_NEAR(areas[0], 9, 1e-9);  // hip ends: 6 x 3 / 2
  EXPECT_NEAR(areas[1], 9, 1e-9);
  EXPECT_NEAR(areas[2], 21, 1e-9);  // long faces: (10 + 4) / 2 x 3
  EXPECT_NEAR(areas[3], 21, 1e-9);
  EXPECT_NEAR(total, 60, 1e-9);
  // Over a square the ridge shrinks to a point: a pyramid of four
  // triangles.
  f.outline = {{0, 0}, {6, 0}, {6, 6}, {0, 6}};
  const std::vector<RoofModel> square = RoofModelsOver(f, opt);
  ASSERT_EQ(square.size(), 2u);
  for (const RoofModelFace& face : square[1].faces)
    EXPECT_NEAR(std::abs(SignedArea(face.patch)), 9, 1e-9);
}

// A footprint too narrow for two faces of min_face_m2 gets no gable.
TEST(RoofModelsOver, NoGableOverASliver) {
  Footprint f;
  f.id = "S";
  f.outline = {{0, 0}, {8, 0}, {8, 0.2}, {0, 0.2}};
  RoofModelOptions opt;
  opt.min_face_m2 = 1.0;
  int gables = 0;
  for (const RoofModel& m : RoofModelsOver(f, opt)) gables += m.faces.size() == 2;
  // Along the sliver its faces would be 8 x 0.1 m, across it 4 x 0.2 m.
  EXPECT_EQ(gables, 0);
}

}  // namespace
}  // namespace roofsweep
