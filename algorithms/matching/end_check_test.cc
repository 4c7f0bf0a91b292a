// CutUnconfirmedEnds on a synthetic terraced row: two houses whose eaves
// are collinear in plan, the second a step lower.
#include "algorithms/matching/end_check.h"

#include <gtest/gtest.h>

#include "algorithms/geometry/test_blocks.h"
#include "algorithms/matching/epipolar.h"

namespace roofsweep {
namespace {

// View 0 straight above the eaves (y = -6), views 1 and 2 40 m to either
// side: from view 0 a height step along the eave does not move it in the
// image; in views 1 and 2 a step of 1 m moves it by about 5 px. Views 1
// and 2 stand at x = side_x.
Block RowBlock(double side_x) {
  return NadirTestBlock({{0, -6, 100}, {side_x, -46, 100}, {side_x, 34, 100}});
}

Segment2D Projected(const Block& b, int v, const Eigen::Vector3d& A, const Eigen::Vector3d& B) {
  Segment2D s;
  s.p0 = *Project(b.cameras[0], b.views[v].pose, A);
  s.p1 = *Project(b.cameras[0], b.views[v].pose, B);
  return s;
}

struct Row {
  Block block;
  std::vector<ViewFeatures> views;
  Line3D line;  // the first house's eave, carried over the row by view 0
};

// The first house's eave runs from x = -8 to 0 at 10 m, its neighbour's
// from 0 to 8 at 10 m - step. View 0 sees one segment over both; views 1
// and 2 see the two pieces (segments 0 and 1).
Row MakeRow(double step, double side_x = 0) {
  Row r;
  r.block = RowBlock(side_x);
  const Eigen::Vector3d a(-8, -6, 10), m(0, -6, 10), m2(0, -6, 10 - step), b2(8, -6, 10 - step);
  const cv::Mat blank(1000, 1000, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  for (int v = 0; v < 3; ++v) {
    Segments2D segs;
    if (v == 0) {
      segs.push_back(Projected(r.block, v, a, b2));
    } else {
      segs.push_back(Projected(r.block, v, a, m));
      segs.push_back(Projected(r.block, v, m2, b2));
    }
    r.views.push_back(PrepareView(r.block, v, blank, segs, MatchOptions{}));
  }
  r.line.segment = {a, Eigen::Vector3d(8, -6, 10)};
  r.line.observations = {{0, 0}, {1, 0}, {2, 0}};
  return r;
}

TEST(CutUnconfirmedEnds, AnEaveDoesNotRunOnOverTheLowerNeighbour) {
  Row r = MakeRow(1.0);
  // The step separates the pieces by more than the verification allows.
  const MatchOptions o;
  const Segment2D p1 = r.views[1].ideal[0], q1 = r.views[1].ideal[1];
  const Eigen::Vector2d n = Eigen::Vector2d(-p1.Direction().y(), p1.Direction().x());
  EXPECT_GT(std::abs((q1.p0 - p1.p0).dot(n)), o.verify_distance);

  const double cut = CutUnconfirmedEnds(r.views, o, &r.line);
  EXPECT_NEAR(cut, 8.0, 0.05);
  const Segment3 eave{{-8, -6, 10}, {0, -6, 10}};
  EXPECT_LT((r.line.segment.a - eave.a).norm(), 0.05);
  EXPECT_LT((r.line.segment.b - eave.b).norm(), 0.05);
}

TEST(CutUnconfirmedEnds, AnEndTheOtherViewsConfirmStays) {
  // No step: the neighbour's eave is the same line, and views 1 and 2 hold
  // it as a segment of their own.
  Row r = MakeRow(0.0);
  const Segment3 before = r.line.segment;
  EXPECT_EQ(CutUnconfirmedEnds(r.views, MatchOptions{}, &r.line), 0.0);
  EXPECT_EQ(r.line.segment.a, before.a);
  EXPECT_EQ(r.line.segment.b, before.b);
}

TEST(CutUnconfirmedEnds, ALineTwoViewsHoldEndToEndIsNotTouched) {
  Row r = MakeRow(1.0);
  // Views 0 and 1 both hold the first house's eave, view 2 part of it.
  r.line.segment = {{-8, -6, 10}, {0, -6, 10}};
  r.views[0].ideal[0] = Projected(r.block, 0, r.line.segment.a, r.line.segment.b);
  r.views[2].ideal[0] = Projected(r.block, 2, {-4, -6, 10}, r.line.segment.b);
  EXPECT_EQ(CutUnconfirmedEnds(r.views, MatchOptions{}, &r.line), 0.0);
}

TEST(CutUnconfirmedEnds, AnEndNoOtherViewSeesStays) {
  // Views 1 and 2 moved 44.5 m west: the first house ends 6 px from the
  // east border of their images, the neighbour lies beyond it (less than
  // verify_min_length inside). Nothing refutes view 0.
  Row r = MakeRow(1.0, -44.5);
  for (int v : {1, 2}) {
    const Segment2D& s = r.views[v].ideal[0];
    EXPECT_TRUE(r.views[v].Inside(s.p0) && r.views[v].Inside(s.p1));
    EXPECT_FALSE(r.views[v].Inside(r.views[v].ideal[1].p1));
  }
  EXPECT_EQ(CutUnconfirmedEnds(r.views, MatchOptions{}, &r.line), 0.0);
  // The same with the views above the row, seeing the neighbour, cuts it.
  Row seen = MakeRow(1.0, 0);
  EXPECT_GT(CutUnconfirmedEnds(seen.views, MatchOptions{}, &seen.line), 7.9);
}

}  // namespace
}  // namespace roofsweep
