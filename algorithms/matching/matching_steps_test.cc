// Unit tests of the matching steps on synthetic two-view setups.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <random>

#include "algorithms/geometry/test_blocks.h"
#include "algorithms/matching/assignment.h"
#include "algorithms/matching/chromatic_test.h"
#include "algorithms/matching/correlation.h"
#include "algorithms/matching/epipolar.h"
#include "algorithms/matching/junction_support.h"
#include "algorithms/matching/line_triangulation.h"
#include "algorithms/matching/robust_estimate.h"
#include "algorithms/matching/view_features.h"

namespace roofsweep {
namespace {

// Two nadir views 100 m above z = 0 (10 cm GSD), `baseline` apart along x.
Block TwoViewBlock(double baseline = 30) {
  return NadirTestBlock({{-baseline / 2, 0, 100}, {baseline / 2, 0, 100}});
}

Segment2D ProjectSeg(const Block& b, int v, const Eigen::Vector3d& A, const Eigen::Vector3d& B) {
  Segment2D s;
  s.p0 = *Project(b.cameras[0], b.views[v].pose, A);
  s.p1 = *Project(b.cameras[0], b.views[v].pose, B);
  return s;
}

// Colour texture on the ground: two differently coloured, textured halves
// either side of x = 0.
cv::Vec3f Texture(double x, double y) {
  const float t =
      static_cast<float>(0.08 * std::sin(1.7 * x + 0.3 * y) + 0.06 * std::cos(2.3 * y - 0.9 * x));
  const float u = static_cast<float>(0.07 * std::sin(2.9 * y + 1.1 * x));
  if (x < 0) return cv::Vec3f(0.6f + t, 0.3f + u, 0.2f - t / 2);
  return cv::Vec3f(0.25f + u, 0.45f - t, 0.55f + t);
}

cv::Mat RenderGround(const Block& b, int v) {
  cv::Mat img(b.cameras[0].height, b.cameras[0].width, CV_32FC3);
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      const Ray r = BackProject(b.cameras[0], b.views[v].pose, {x + 0.5, y + 0.5});
      const auto X = IntersectHorizontalPlane(r, 0.0);
      img.at<cv::Vec3f>(y, x) = Texture(X->x(), X->y());
    }
  return img;
}

TEST(EpipolarCandidates, StripAngleAndHeightRange) {
  const Block b = TwoViewBlock();
  MatchOptions o;
  // A building edge at 10 m, running north (across the epipolar lines).
  const Eigen::Vector3d A(2, -5, 10), B(2, 5, 10);
  Segments2D s0 = {ProjectSeg(b, 0, A, B)};
  Segments2D s1 = {
      ProjectSeg(b, 1, A, B),  // 0: the match
      ProjectSeg(b, 1, A + Eigen::Vector3d(0, 30, 0),
                 B + Eigen::Vector3d(0, 30, 0)),  // 1: outside the strip
      ProjectSeg(b, 1, A + Eigen::Vector3d(-2, 0, 0),
                 A + Eigen::Vector3d(6, 3, 0)),  // 2: wrong angle
      ProjectSeg(b, 1, A + Eigen::Vector3d(25, 0, 0),
                 B + Eigen::Vector3d(25, 0, 0)),  // 3: far: below ground
      ProjectSeg(b, 1, A + Eigen::Vector3d(1, 0, 0), B + Eigen::Vector3d(1, 2, 0)),  // 4: plausible
  };
  const cv::Mat blank(1000, 1000, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  const ViewFeatures v0 = PrepareView(b, 0, blank, s0, o);
  const ViewFeatures v1 = PrepareView(b, 1, blank, s1, o);
  const PairGeometry g = MakePairGeometry(v0, v1);
  ASSERT_TRUE(g.valid);
  const auto z = SceneHeightRange(b, o.height_margin_m);
  ASSERT_TRUE(z);
  const auto c = GeometricCandidates(v0, v1, 0, 1, g, 0, z, o);
  std::vector<int> ids;
  for (const auto& h : c) ids.push_back(h.sj);
  EXPECT_EQ(ids, (std::vector<int>{0, 4}));
  // The true pair reconstructs the edge.
  ASSERT_FALSE(c.empty());
  EXPECT_LT((c[0].line.a - A).norm(), 1e-6);
  EXPECT_LT((c[0].line.b - B).norm(), 1e-6);
  EXPECT_FALSE(c[0].reversed);
  // A segment along the epipolar lines (east-west) gets no candidates.
  Segments2D e0 = {ProjectSeg(b, 0, {0, 0, 5}, {10, 0, 5})};
  Segments2D e1 = {ProjectSeg(b, 1, {0, 0, 5}, {10, 0, 5})};
  const ViewFeatures w0 = PrepareView(b, 0, blank, e0, o);
  const ViewFeatures w1 = PrepareView(b, 1, blank, e1, o);
  EXPECT_TRUE(GeometricCandidates(w0, w1, 0, 1, MakePairGeometry(w0, w1), 0, z, o).empty());
}

// A hillside: the ground rises 1 m per metre eastwards, from z = -40 at
// x = -40 to z = 40 at x = 40 (a 2 m DTM).
Block HillsideBlock() {
  Block b = TwoViewBlock();
  b.ground.height.reset();
  b.ground.grid = SampledGrid(-40, 40, 2, 40, 40, [](double x, double) { return x; });
  return b;
}

TEST(EpipolarCandidates, HeightRangeFollowsTheGroundUnderThePoint) {
  const Block b = HillsideBlock();  // max_building_height 20
  MatchOptions o;
  const auto z = SceneHeightRange(b, o.height_margin_m);
  ASSERT_TRUE(z);
  // Block-wide: the lowest ground less the margin up to the highest plus 20.
  EXPECT_NEAR(z->lo, -39 - 3, 1e-9);
  EXPECT_NEAR(z->hi, 39 + 20 + 3, 1e-9);
  // A roof 10 m above the slope, and the ground itself, are scene points...
  EXPECT_TRUE(z->Contains({-20, 0, -10}));
  EXPECT_TRUE(z->Contains({20, 0, 20}));
  EXPECT_TRUE(z->Contains({20, 0, 18}));
  // ... a point 30 m above the ground on the low side, within the block's
  // range, is not; nor is one 10 m under the ground on the high side.
  EXPECT_FALSE(z->Contains({-20, 0, 10}));
  EXPECT_FALSE(z->Contains({20, 0, 10}));

  // An edge 5 m above the ground at x = -10 (running north, across the
  // epipolar lines), and a segment of view 1 that would put it 30 m higher:
  // inside the block-wide range, but 35 m above the ground there.
  const Eigen::Vector3d A(-10, -5, -5), B(-10, 5, -5);
  const Segments2D s0 = {ProjectSeg(b, 0, A, B)};
  const Eigen::Vector3d C0 = b.views[0].pose.C;
  auto along_ray = [&](const Eigen::Vector3d& P, double height) -> Eigen::Vector3d {
    return C0 + (P - C0) * ((height - C0.z()) / (P.z() - C0.z()));
  };
  const Segments2D s1 = {ProjectSeg(b, 1, A, B),
                         ProjectSeg(b, 1, along_ray(A, 25), along_ray(B, 25))};
  const cv::Mat blank(1000, 1000, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  const ViewFeatures v0 = PrepareView(b, 0, blank, s0, o);
  const ViewFeatures v1 = PrepareView(b, 1, blank, s1, o);
  const PairGeometry g = MakePairGeometry(v0, v1);
  ASSERT_TRUE(g.valid);
  std::vector<int> ids;
  for (const auto& h : GeometricCandidates(v0, v1, 0, 1, g, 0, z, o)) ids.push_back(h.sj);
  EXPECT_EQ(ids, (std::vector<int>{0}));
}

TEST(EpipolarCandidates, LinesAreCutToTheSceneHeights) {
  const Block b = HillsideBlock();
  const auto z = SceneHeightRange(b, 3.0);
  ASSERT_TRUE(z);
  // A line at z = 0 from x = -30 to x = 30: under the ground beyond x = 3,
  // more than 23 m above it before x = -23.
  Segment3 s{{-30, 0, 0}, {30, 0, 0}};
  ASSERT_TRUE(z->Clip(&s));
  EXPECT_NEAR(s.a.x(), -23, 0.26);
  EXPECT_NEAR(s.b.x(), 3, 0.26);
  EXPECT_TRUE(z->Contains(s.a));
  EXPECT_TRUE(z->Contains(s.b));
  // A line inside is left exactly as it is; one wholly outside is refused.
  Segment3 in{{-10, 0, -5}, {10, 3, 15}};
  const Segment3 before = in;
  ASSERT_TRUE(z->Clip(&in));
  EXPECT_EQ(in.a, before.a);
  EXPECT_EQ(in.b, before.b);
  Segment3 under{{-10, 0, -30}, {10, 0, -20}};
  EXPECT_FALSE(z->Clip(&under));
}

TEST(EpipolarCandidates, IdenticalViewsHaveNoGeometry) {
  Block b = TwoViewBlock();
  b.views[1].pose = b.views[0].pose;
  const cv::Mat blank(1000, 1000, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  MatchOptions o;
  const ViewFeatures v0 = PrepareView(b, 0, blank, {}, o), v1 = PrepareView(b, 1, blank, {}, o);
  EXPECT_FALSE(MakePairGeometry(v0, v1).valid);
}

SideColour Region(std::mt19937& rng, Eigen::Vector2d mean, double sa, double sb, int n,
                  double outliers = 0) {
  std::normal_distribution<double> z(0, 1);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Eigen::Vector2d> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back(u(rng) < outliers
                      ? Eigen::Vector2d(40 + 5 * z(rng), -30 + 5 * z(rng))
                      : Eigen::Vector2d(mean + Eigen::Vector2d(sa * z(rng), sb * z(rng))));
  const Robust2D r = RobustMcd2D(pts, 1);
  SideColour s;
  s.valid = r.valid;
  s.n = r.inliers;
  s.mean = r.mean;
  s.cov = r.cov;
  return s;
}

TEST(ChromaticTests, SameDistributionPassesDifferentFails) {
  // The MCD estimates are less efficient than the sample moments, so under
  // H0 the statistics exceed chi2 (median ~2x); the automatic thresholds
  // (factor x median of pairs believed correct, sec. 3.3) absorb that.
  std::mt19937 rng(11);
  const int trials = 200, n = 150;
  std::vector<std::pair<double, double>> init;
  for (int t = 0; t < 40; ++t) {
    const SideColour a = Region(rng, {10, 20}, 2, 1.5, n);
    const SideColour b = Region(rng, {10, 20}, 2, 1.5, n, 0.2);
    init.emplace_back(MeanStatistic(a, b, 1000), CovStatistic(a, b, 1000));
  }
  MatchOptions o;
  const ChromaticThresholds thr = InitThresholds(init, o.threshold_factor);
  int pass_same = 0, pass_mean = 0, pass_cov = 0;
  for (int t = 0; t < trials; ++t) {
    const SideColour a = Region(rng, {10, 20}, 2, 1.5, n);
    const SideColour same = Region(rng, {10, 20}, 2, 1.5, n, 0.2);  // 20 % outliers
    const SideColour shifted = Region(rng, {13, 21.5}, 2, 1.5, n);  // 1.5 sigma
    const SideColour wider = Region(rng, {10, 20}, 6, 4.5, n);      // 3 x the spread
    pass_same += SidesCompatible(a, same, thr, 1000);
    pass_mean += MeanStatistic(a, shifted, 1000) <= thr.mean;
    pass_cov += CovStatistic(a, wider, 1000) <= thr.cov;
  }
  EXPECT_GE(pass_same, 0.95 * trials);
  EXPECT_LE(pass_mean, 0.02 * trials);
  EXPECT_LE(pass_cov, 0.02 * trials);
}

TEST(ChromaticTests, ThresholdInitialisationUsesMedians) {
  // Per random segment the statistics of its most similar candidate; a few
  // segments whose true partner is missing give outliers the median ignores.
  std::vector<std::pair<double, double>> stats = {{10, 20}, {20, 30},   {30, 40},  {40, 50},
                                                  {50, 60}, {500, 600}, {800, 900}};
  const ChromaticThresholds t = InitThresholds(stats, 2.0);
  EXPECT_DOUBLE_EQ(t.mean, 80.0);  // 2 x median
  EXPECT_DOUBLE_EQ(t.cov, 100.0);
  // Never below the chi2 0.001 quantiles; too few samples: those quantiles x factor.
  const ChromaticThresholds low =
      InitThresholds({{0.1, 0.1}, {0.2, 0.2}, {0.1, 0.3}, {0.2, 0.1}, {0.1, 0.2}}, 2.0);
  EXPECT_NEAR(low.mean, 13.816, 1e-3);
  EXPECT_NEAR(low.cov, 16.266, 1e-3);
  const ChromaticThresholds few = InitThresholds({{1, 1}}, 2.0);
  EXPECT_NEAR(few.mean, 2 * 13.816, 1e-3);
}

TEST(Correlation, NccBasics) {
  std::vector<float> a = {1, 2, 3, 5, 4}, b, c;
  for (float x : a) {
    b.push_back(3 * x + 7);
    c.push_back(-x);
  }
  EXPECT_NEAR(Ncc(a.data(), b.data(), 5), 1.0, 1e-9);
  EXPECT_NEAR(Ncc(a.data(), c.data(), 5), -1.0, 1e-9);
  std::vector<float> flat(5, 2.f);
  EXPECT_EQ(Ncc(a.data(), flat.data(), 5), 0.0);
}

// The 30 m line x = 0 on the ground of TwoViewBlock(20), seen in both views,
// and in view 1 a false partner 4 m further east (same direction): the
// true and the false candidate of the one segment in view 0, and per side
// the correlation of each (SideCorrelation).
struct ShiftedPair {
  ViewFeatures v0, v1;
  std::array<double, 2> good{}, bad{};
};

ShiftedPair CorrelateShiftedPair(const Block& b, const cv::Mat& i0, const cv::Mat& i1,
                                 const MatchOptions& o) {
  const Eigen::Vector3d A(0, -15, 0), B(0, 15, 0);
  Segments2D s0 = {ProjectSeg(b, 0, A, B)};
  Segments2D s1 = {ProjectSeg(b, 1, A, B),
                   ProjectSeg(b, 1, A + Eigen::Vector3d(4, 0, 0), B + Eigen::Vector3d(4, 0, 0))};
  ShiftedPair r{PrepareView(b, 0, i0, s0, o), PrepareView(b, 1, i1, s1, o)};
  const PairGeometry g = MakePairGeometry(r.v0, r.v1);
  const auto c = GeometricCandidates(r.v0, r.v1, 0, 1, g, 0, std::nullopt, o);
  EXPECT_EQ(c.size(), 2u);
  if (c.size() != 2) return r;
  for (int side = 0; side < 2; ++side) {
    r.good[side] = SideCorrelation(r.v0, r.v1, g, c[0], side, o);
    r.bad[side] = SideCorrelation(r.v0, r.v1, g, c[1], side, o);
  }
  return r;
}

TEST(Correlation, TruePairCorrelatesShiftedPairDoesNot) {
  const Block b = TwoViewBlock(20);
  const ShiftedPair r = CorrelateShiftedPair(b, RenderGround(b, 0), RenderGround(b, 1), {});
  for (int side = 0; side < 2; ++side) {
    EXPECT_GT(r.good[side], 1.5) << "side " << side;
    EXPECT_LT(r.bad[side], 0.5) << "side " << side;
  }
  // The chromatic attributes of the true pair agree.
  for (int side = 0; side < 2; ++side) {
    EXPECT_LT(MeanStatistic(r.v0.sides[0][side], r.v1.sides[0][side], 200), 13.82);
  }
}

// Grey texture with chroma noise of its own in each view: a* and b* carry
// nothing the views share, so only L* tells the true partner from the
// false one (MatchOptions::correlate_lightness).
TEST(Correlation, LightnessTellsPartnersApartOnGreyTexture) {
  const Block b = TwoViewBlock(20);
  auto grey = [&](int v) {
    cv::Mat g, rgb;
    cv::cvtColor(RenderGround(b, v), g, cv::COLOR_RGB2GRAY);
    cv::cvtColor(g, rgb, cv::COLOR_GRAY2RGB);
    cv::Mat noise(rgb.size(), CV_32FC3);
    cv::RNG rng(static_cast<uint64_t>(v) + 1);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, 0.02);
    noise.forEach<cv::Vec3f>([](cv::Vec3f& p, const int*) { p[1] = 0; });  // G carries L*
    rgb += noise;
    return rgb;
  };
  const cv::Mat i0 = grey(0), i1 = grey(1);
  for (bool lightness : {true, false}) {
    MatchOptions o;
    o.correlate_lightness = lightness;
    const ShiftedPair r = CorrelateShiftedPair(b, i0, i1, o);
    for (int side = 0; side < 2; ++side) {
      const double good = r.good[side], bad = r.bad[side];
      if (lightness) {
        EXPECT_GT(good, 0.5) << "side " << side;
        EXPECT_GT(good - bad, 0.4) << "side " << side;
      } else {
        EXPECT_LT(std::abs(good - bad), 0.4) << "side " << side;
      }
    }
  }
}

TEST(Triangulation, AccurateUnderNoise) {
  Block b = TwoViewBlock(30);
  View v = b.views[0];
  v.pose.C = {0, 25, 100};
  b.views.push_back(v);
  v.pose.C = {10, -20, 95};
  b.views.push_back(v);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0, 0.2);
  double worst = 0, sum2 = 0;
  int n = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d A(-5 + trial * 0.3, -4, 8), B(4, 6 - trial * 0.2, 12);
    std::vector<LineObservation> obs;
    for (int k = 0; k < 4; ++k) {
      LineObservation o;
      o.P = ProjectionMatrix(b.cameras[0], b.views[k].pose);
      // Each view sees a different stretch of the line.
      const Eigen::Vector3d a = A + (B - A) * (0.05 * k), bb = B - (B - A) * (0.03 * k);
      o.q0 = *Project(b.cameras[0], b.views[k].pose, a) + Eigen::Vector2d(noise(rng), noise(rng));
      o.q1 = *Project(b.cameras[0], b.views[k].pose, bb) + Eigen::Vector2d(noise(rng), noise(rng));
      obs.push_back(o);
    }
    Segment3 init;
    init.a = A + Eigen::Vector3d(0.5, -0.3, 1.0);
    init.b = B + Eigen::Vector3d(-0.4, 0.2, -0.8);
    const LineEstimate e = TriangulateLine(obs, init);
    ASSERT_TRUE(e.valid);
    EXPECT_LT(e.rms_px, 0.4);
    const Segment3 truth{A, B};
    // Distance of the estimated endpoints to the true line, and the extent.
    for (const Eigen::Vector3d& p : {e.segment.a, e.segment.b}) {
      worst = std::max(worst, truth.Distance(p));
      sum2 += truth.Distance(p) * truth.Distance(p);
      ++n;
    }
    EXPECT_LT(std::min((e.segment.a - A).norm(), (e.segment.b - A).norm()), 0.25);
    EXPECT_LT(std::min((e.segment.a - B).norm(), (e.segment.b - B).norm()), 0.25);
  }
  // 0.2 px at 10 cm GSD with base/height 0.3-0.45 gives ~7 cm in height per
  // view pair; the line through four views does better in the middle, worse
  // at the extrapolated ends.
  EXPECT_LT(std::sqrt(sum2 / n), 0.08);
  EXPECT_LT(worst, 0.2);
}

TEST(Assignment, PicksTheConsistentOneToOneSet) {
  // Segment (0,0) likes (1,0) best, (0,1) can only go with (1,0) weakly, and
  // (0,0)-(1,1) is the alternative: the one-to-one rule keeps each segment once.
  std::vector<AssignmentItem> items(4);
  items[0] = {{{0, 0}, {1, 0}}, 0.9};
  items[1] = {{{0, 1}, {1, 0}}, 0.5};
  items[2] = {{{0, 0}, {1, 1}}, 0.7};
  items[3] = {{{0, 1}, {1, 2}, {2, 5}}, 0.4};
  const auto a = AssignOneToOne(items);
  EXPECT_FALSE(a[0].empty());
  EXPECT_TRUE(a[1].empty());   // (1,0) already taken by the better hypothesis
  EXPECT_TRUE(a[2].empty());   // (0,0) taken
  ASSERT_EQ(a[3].size(), 3u);  // (0,1) goes to its remaining partner, with support
  // Symmetric: reversing the roles of the views gives the same pairs.
  std::vector<AssignmentItem> rev = items;
  for (auto& it : rev) std::swap(it.keys[0], it.keys[1]);
  const auto b = AssignOneToOne(rev);
  for (size_t k = 0; k < items.size(); ++k) EXPECT_EQ(a[k].empty(), b[k].empty());
}

TEST(Assignment, ASegmentDoesNotFallBackToItsSecondChoice) {
  // Tile courses: (0,2)'s best partner (1,5) goes to the better (0,1)-(1,5).
  // The greedy assignment alone then pairs (0,2) with its second choice
  // (1,6), the neighbouring course.
  std::vector<AssignmentItem> items(3);
  items[0] = {{{0, 1}, {1, 5}}, 5.0};
  items[1] = {{{0, 2}, {1, 5}}, 4.0};
  items[2] = {{{0, 2}, {1, 6}}, 3.0};
  const auto greedy = AssignOneToOne(items);
  EXPECT_FALSE(greedy[2].empty());
  const std::vector<char> unique = UnambiguousItems(items);
  EXPECT_TRUE(unique[0]);
  EXPECT_FALSE(unique[1]);  // (1,5) has a better line
  EXPECT_FALSE(unique[2]);  // (0,2) has a better, different line
}

TEST(Assignment, RivalsOfEqualScoreBothGoAndOneLineInTwoViewPairsStays) {
  std::vector<AssignmentItem> items(4);
  // (0,1) with (1,5) or (1,6), equally good: ambiguous, both go.
  items[0] = {{{0, 1}, {1, 5}}, 2.0};
  items[1] = {{{0, 1}, {1, 6}}, 2.0};
  // (0,3) matched in view 1 and in view 2: one line when the view-2 segment
  // supports the view-1 match (or the other way round), not rivals.
  items[2] = {{{0, 3}, {1, 7}, {2, 8}}, 3.0};
  items[3] = {{{0, 3}, {2, 8}}, 2.5};
  const std::vector<char> unique = UnambiguousItems(items);
  EXPECT_FALSE(unique[0]);
  EXPECT_FALSE(unique[1]);
  EXPECT_TRUE(unique[2]);
  EXPECT_TRUE(unique[3]);
  // Without the support link they are rivals and the weaker one goes.
  items[2].keys.pop_back();
  const std::vector<char> rivals = UnambiguousItems(items);
  EXPECT_TRUE(rivals[2]);
  EXPECT_FALSE(rivals[3]);
}

TEST(JunctionSupport, EndsOnOtherLinesCountRivalsAndCollinearOnesDoNot) {
  using V = Eigen::Vector3d;
  using Keys = std::vector<std::pair<int, int>>;
  // An eave from (0,0,5) to (10,0,5) and two verges from its ends; the
  // second verge stops 0.27 m short of the corner (the eave's end meets its
  // prolongation).
  std::vector<Segment3> lines = {
      {V(0, 0, 5), V(10, 0, 5)},        // 0: eave
      {V(0, 0.1, 5), V(0, 8, 8)},       // 1: verge at the eave's first end
      {V(10, 0.25, 5.05), V(10, 8, 8)}  // 2: verge near its second end
  };
  std::vector<Keys> keys = {{{0, 1}, {1, 1}}, {{0, 2}, {1, 2}}, {{0, 3}, {1, 3}}};
  // 3: the eave matched to the wrong tile course, 1.5 m lower: same first
  //    segment (a rival), ends in mid-air.
  lines.push_back({V(0, -0.6, 3.5), V(10, -0.6, 3.5)});
  keys.push_back({{0, 1}, {1, 9}});
  // 4: a collinear fragment on the eave: the same edge, no junction.
  lines.push_back({V(3, 0.05, 5), V(6, 0.05, 5)});
  keys.push_back({{0, 4}, {1, 4}});
  std::vector<int> ends = JunctionSupport(lines, keys);
  ASSERT_EQ(ends.size(), 5u);
  EXPECT_EQ(ends[0], 2);
  EXPECT_EQ(ends[1], 1);  // its upper end meets nothing
  EXPECT_EQ(ends[2], 1);
  EXPECT_EQ(ends[3], 0);
  EXPECT_EQ(ends[4], 0);
  // A line that shares a key with the eave (its support in a third view) is
  // the same line, not a junction: the verge at the first end now counts
  // for neither.
  keys[1].push_back({2, 5});
  keys[0].push_back({2, 5});
  ends = JunctionSupport(lines, keys);
  EXPECT_EQ(ends[0], 1);
  EXPECT_EQ(ends[1], 0);
}

}  // namespace
}  // namespace roofsweep
