// Junction completion on a synthetic one-strip block: a gable whose eave
// and ridge run along the flight line, with the verges as anchors.
#include "algorithms/matching/junction_completion.h"

#include <gtest/gtest.h>

#include "algorithms/geometry/test_blocks.h"
#include "algorithms/matching/epipolar.h"

namespace roofsweep {
namespace {

// Three nadir views in one strip along x, 100 m above z = 0 (10 cm GSD):
// every epipolar line runs along x.
Block StripBlock() { return NadirTestBlock({{-30, 0, 100}, {0, 0, 100}, {30, 0, 100}}); }

const Eigen::Vector3d kEaveA(-8, -6, 10), kEaveB(8, -6, 10);
const Eigen::Vector3d kRidgeA(-8, 0, 14), kRidgeB(8, 0, 14);

// Segment ids in every view: 0 eave, 1 ridge, 2 and 3 the verges, 4 a
// course between the verges' middles.
enum { kEave, kRidge, kVerge1, kVerge2, kCourse };
std::vector<Segment3> Edges() {
  return {{kEaveA, kEaveB},
          {kRidgeA, kRidgeB},
          {kEaveA, kRidgeA},
          {kEaveB, kRidgeB},
          {(kEaveA + kRidgeA) / 2, (kEaveB + kRidgeB) / 2}};
}

struct Scene {
  Block block = StripBlock();
  std::vector<ViewFeatures> views;
  std::vector<Line3D> verges;
};

// `edit(view, segments)` may change what a view detected.
Scene MakeScene(const std::function<void(int, Segments2D*)>& edit = nullptr) {
  Scene s;
  const cv::Mat blank(1000, 1000, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  for (int v = 0; v < 3; ++v) {
    Segments2D segs;
    for (const Segment3& e : Edges()) {
      Segment2D p;
      p.p0 = *Project(s.block.cameras[0], s.block.views[v].pose, e.a);
      p.p1 = *Project(s.block.cameras[0], s.block.views[v].pose, e.b);
      segs.push_back(p);
    }
    if (edit) edit(v, &segs);
    s.views.push_back(PrepareView(s.block, v, blank, segs, MatchOptions{}));
  }
  for (int id : {kVerge1, kVerge2}) {
    Line3D l;
    l.segment = Edges()[id];
    l.observations = {{0, id}, {1, id}, {2, id}};
    s.verges.push_back(l);
  }
  return s;
}

double Distance(const Segment3& a, const Segment3& b) {
  return std::max((a.a - b.a).norm(), (a.b - b.b).norm());
}

TEST(JunctionCompletion, EaveAndRidgeAlongTheFlightLineFromTheVerges) {
  const Scene s = MakeScene();
  // Stereo has nothing to say about them.
  const PairGeometry g = MakePairGeometry(s.views[0], s.views[1]);
  EXPECT_LT(EpipolarAngle(g.e_i, s.views[0].ideal[kEave]), 1.0);
  EXPECT_LT(EpipolarAngle(g.e_i, s.views[0].ideal[kRidge]), 1.0);

  const MatchOptions o;
  const JunctionCompletion jc =
      CompleteAtJunctions(s.views, s.verges, SceneHeightRange(s.block, 3.0), o);
  ASSERT_EQ(jc.lines.size(), 2u);
  const Segment3 eave{kEaveA, kEaveB}, ridge{kRidgeA, kRidgeB};
  int found = 0;
  for (const Line3D& l : jc.lines) {
    EXPECT_TRUE(l.from_junctions);
    EXPECT_EQ(l.Views(), 3);
    EXPECT_LT(l.rms_px, 1e-6);
    const int id = l.observations[0].second;
    ASSERT_TRUE(id == kEave || id == kRidge) << "segment " << id;
    EXPECT_LT(Distance(l.segment, id == kEave ? eave : ridge), 1e-6);
    found |= 1 << id;
    for (const auto& [v, seg] : l.observations) EXPECT_EQ(seg, id);
  }
  EXPECT_EQ(found, 3);
  // The course meets the verges in their middles: no corner, no line.
  EXPECT_EQ(jc.candidates, 2 * 3);
}

TEST(JunctionCompletion, ASegmentSeenInOneViewOnlyIsNotCompleted) {
  // The ridge is detected in view 0 only.
  const Scene s = MakeScene([](int v, Segments2D* segs) {
    if (v > 0) (*segs)[kRidge].p1 = (*segs)[kRidge].p0 + Eigen::Vector2d(0, 300);
  });
  const JunctionCompletion jc =
      CompleteAtJunctions(s.views, s.verges, SceneHeightRange(s.block, 3.0), MatchOptions{});
  ASSERT_EQ(jc.lines.size(), 1u);
  EXPECT_EQ(jc.lines[0].observations[0].second, kEave);
}

TEST(JunctionCompletion, TheCornersMustBeSeenAgain) {
  // In views 1 and 2 the ridge stops 20 px short of one corner: the line
  // is supported, but the junction, which alone fixes its depth, is not.
  const Scene s = MakeScene([](int v, Segments2D* segs) {
    if (v == 0) return;
    Segment2D& r = (*segs)[kRidge];
    r.p1 -= 20.0 * r.Direction();
  });
  MatchOptions two_ends;
  two_ends.junction_horizontal = false;
  const JunctionCompletion jc =
      CompleteAtJunctions(s.views, s.verges, SceneHeightRange(s.block, 3.0), two_ends);
  ASSERT_EQ(jc.lines.size(), 1u);
  EXPECT_EQ(jc.lines[0].observations[0].second, kEave);
  // The shortened ridge has one corner, at the verge; as a horizontal line
  // from there its other end is seen again in the other shortened view.
  const JunctionCompletion jh =
      CompleteAtJunctions(s.views, s.verges, SceneHeightRange(s.block, 3.0), MatchOptions{});
  ASSERT_EQ(jh.lines.size(), 2u);
  EXPECT_EQ(jh.horizontal, 1);
  for (const Line3D& l : jh.lines) {
    if (!l.horizontal_assumed) continue;
    EXPECT_EQ(l.observations[0].second, kRidge);
    EXPECT_NE(l.observations[0].first, 0);  // from the shortened views
    for (const Eigen::Vector3d& p : {l.segment.a, l.segment.b}) {
      EXPECT_NEAR(p.y(), 0, 1e-6);
      EXPECT_NEAR(p.z(), 14, 1e-6);
    }
  }
}

TEST(JunctionCompletion, OneCornerGivesAHorizontalLineButNotASlopedOne) {
  // Anchors: the left verge and the eave. The ridge meets the verge at one
  // end only and comes out horizontal, as it is. The right verge meets the
  // eave at one end only: horizontal from there it would stay at the eave's
  // height, where the other views do not see it (it is not along the
  // epipolar lines), so it is not completed.
  Scene s = MakeScene();
  Line3D eave;
  eave.segment = Edges()[kEave];
  eave.observations = {{0, kEave}, {1, kEave}, {2, kEave}};
  const std::vector<Line3D> anchors = {s.verges[0], eave};
  const JunctionCompletion jc =
      CompleteAtJunctions(s.views, anchors, SceneHeightRange(s.block, 3.0), MatchOptions{});
  ASSERT_EQ(jc.lines.size(), 1u);
  const Line3D& l = jc.lines[0];
  EXPECT_TRUE(l.horizontal_assumed);
  EXPECT_STREQ(DepthFrom(l), "junction_horizontal");
  EXPECT_EQ(l.observations[0].second, kRidge);
  EXPECT_LT(Distance(l.segment, {kRidgeA, kRidgeB}), 1e-6);
  // Off, a single corner completes nothing.
  MatchOptions two_ends;
  two_ends.junction_horizontal = false;
  EXPECT_TRUE(CompleteAtJunctions(s.views, anchors, SceneHeightRange(s.block, 3.0), two_ends)
                  .lines.empty());
}

TEST(JunctionCompletion, NoAnchorsNoLines) {
  const Scene s = MakeScene();
  const JunctionCompletion jc =
      CompleteAtJunctions(s.views, {}, SceneHeightRange(s.block, 3.0), MatchOptions{});
  EXPECT_TRUE(jc.lines.empty());
  EXPECT_EQ(jc.candidates, 0);
}

}  // namespace
}  // namespace roofsweep
