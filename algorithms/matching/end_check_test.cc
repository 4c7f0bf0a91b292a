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

// A ridge along the flight line, from x = -8 to 0 at 10 m. Views 0 and 1
// fly along it (both at y = -6, the ridge's plane): in them the ridge and
// whatever lies in line with it beyond the gable are one image edge, at any
// depth, and both hold a segment on to x = 8. Views 2 and 3, 40 m to either
// side, hold the ridge alone. Returns the line as matching carried it on.
struct Ridge {
  Block block;
  std::vector<ViewFeatures> views;
  Line3D line;
};
Ridge MakeRidge(double held_across_to_x) {
  Ridge r;
  r.block = NadirTestBlock({{-20, -6, 100}, {20, -6, 100}, {0, -46, 100}, {0, 34, 100}});
  const Eigen::Vector3d a(-8, -6, 10), beyond(8, -6, 10), across(held_across_to_x, -6, 10);
  const cv::Mat blank(1000, 1000, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  for (int v = 0; v < 4; ++v)
    r.views.push_back(PrepareView(
        r.block, v, blank, {Projected(r.block, v, a, v < 2 ? beyond : across)}, MatchOptions{}));
  r.line.segment = {a, beyond};
  r.line.observations = {{0, 0}, {1, 0}, {2, 0}, {3, 0}};
  return r;
}

TEST(CutUnconfirmedEnds, TwoViewsAlongTheEpipolarLinesDoNotFixAnEnd) {
  Ridge r = MakeRidge(0.0);
  // Views 0 and 1 see the ridge along their epipolar lines; a pair across
  // the strips sees it steeply.
  const MatchOptions o;
  const PairGeometry along = MakePairGeometry(r.views[0], r.views[1]);
  EXPECT_LT(EpipolarAngle(along.e_i, r.views[0].ideal[0]), 1.0);
  const PairGeometry across = MakePairGeometry(r.views[0], r.views[2]);
  EXPECT_GT(EpipolarAngle(across.e_i, r.views[0].ideal[0]), o.min_epipolar_angle);

  // Views 2 and 3 see the part beyond the gable and hold none of it.
  EXPECT_NEAR(CutUnconfirmedEnds(r.views, o, &r.line), 8.0, 0.05);
  EXPECT_LT((r.line.segment.a - Eigen::Vector3d(-8, -6, 10)).norm(), 0.05);
  EXPECT_LT((r.line.segment.b - Eigen::Vector3d(0, -6, 10)).norm(), 0.05);
}

TEST(CutUnconfirmedEnds, ARidgeTheViewsAcrossHoldEndToEndIsNotTouched) {
  Ridge r = MakeRidge(8.0);
  EXPECT_EQ(CutUnconfirmedEnds(r.views, MatchOptions{}, &r.line), 0.0);
}

}  // namespace
}  // namespace roofsweep
