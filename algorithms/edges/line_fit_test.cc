#include "algorithms/edges/line_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "algorithms/edges/edge_linking.h"
#include "algorithms/edges/line_pieces.h"

namespace roofsweep {
namespace {

Points2 LinePoints(const Eigen::Vector2d& start, double angle_deg, int count, double noise,
                   std::uint64_t seed) {
  cv::RNG rng(seed);
  const double a = angle_deg * M_PI / 180;
  const Eigen::Vector2d d(std::cos(a), std::sin(a)), n(std::sin(a), -std::cos(a));
  Points2 p;
  for (int i = 0; i < count; ++i) p.push_back(start + i * d + rng.gaussian(noise) * n);
  return p;
}

Points2 ArcPoints(const Eigen::Vector2d& c, double radius, double from_deg, double to_deg) {
  Points2 p;
  const double step = 1.0 / radius;  // ~1 px apart
  for (double t = from_deg * M_PI / 180; t <= to_deg * M_PI / 180; t += step) {
    p.push_back(c + radius * Eigen::Vector2d(std::cos(t), std::sin(t)));
  }
  return p;
}

TEST(LineFit, OrthogonalRegressionRecoversTheLine) {
  const Points2 p = LinePoints({10, 20}, 33, 50, 0.0, 1);
  const LineFit f = FitLine(p);
  EXPECT_NEAR(std::fabs(f.direction.dot(
                  Eigen::Vector2d(std::cos(33 * M_PI / 180), std::sin(33 * M_PI / 180)))),
              1.0, 1e-12);
  EXPECT_LT(f.rms, 1e-9);
  EXPECT_NEAR(f.Length(), 49.0, 1e-9);
  const double forward = (f.Start() - p.front()).norm() + (f.End() - p.back()).norm();
  const double backward = (f.Start() - p.back()).norm() + (f.End() - p.front()).norm();
  EXPECT_LT(std::min(forward, backward), 1e-9);
}

TEST(LineFit, VerticalLine) {
  Points2 p;
  for (int i = 0; i < 10; ++i) p.emplace_back(5.0, i);
  const LineFit f = FitLine(p);
  EXPECT_NEAR(std::fabs(f.direction.y()), 1.0, 1e-12);
  EXPECT_NEAR(f.max_deviation, 0.0, 1e-12);
}

TEST(LineFit, CurvatureTest) {
  // An arc of radius 100 over 40 px has a sagitta of 2 px.
  const Points2 arc = ArcPoints({0, 0}, 100, 0, 23);
  EXPECT_TRUE(IsCurved(arc, FitLine(arc), 0.3, 0.75));
  // A noisy straight line is not curved, even with noise near the sagitta.
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Points2 line = LinePoints({0, 0}, 12, 60, 0.15, seed);
    EXPECT_FALSE(IsCurved(line, FitLine(line), 0.3, 0.75)) << seed;
  }
}

TEST(LineFit, SplitsAtCornersAndKeepsLinesWhole) {
  Points2 p = LinePoints({0, 0}, 0, 40, 0.0, 1);
  const Points2 leg = LinePoints({40, 0}, 70, 40, 0.0, 1);
  p.insert(p.end(), leg.begin(), leg.end());
  const auto pieces = SplitIntoStraightPieces(p, EdgeOptions{});
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_GE(pieces[0].last - pieces[0].first, 35);
  EXPECT_GE(pieces[1].last - pieces[1].first, 35);
  // A gentle bend (10°) is not a tangent discontinuity, but the fit splits it.
  Points2 q = LinePoints({0, 0}, 0, 60, 0.0, 1);
  const Points2 bend = LinePoints({60, 0}, 10, 60, 0.0, 1);
  q.insert(q.end(), bend.begin(), bend.end());
  EXPECT_EQ(SplitIntoStraightPieces(q, EdgeOptions{}).size(), 2u);
}

TEST(LineFit, ArcsAreNotApproximatedPiecewise) {
  const EdgeOptions o;
  for (double radius : {30.0, 60.0, 100.0}) {
    const Points2 circle = ArcPoints({200, 200}, radius, 0, 360);
    for (const StraightRun& run : SplitIntoStraightPieces(circle, o)) {
      const Points2 piece(circle.begin() + run.first, circle.begin() + run.last);
      // Sagitta s = L²/(8R) <= ~fit_max_sagitta: L <= sqrt(8 R 0.3).
      EXPECT_LE(FitLine(piece).Length(), std::sqrt(8 * radius * 0.3 * 1.5)) << radius;
    }
  }
}

// (e) Collinear fragments across a 3 px gap (3 missing points) merge; the
// merge refuses an offset, a bend or a long gap.
EdgeMap MapOf(const std::vector<Points2>& runs) {
  EdgeMap map;
  map.index = cv::Mat(1, 1, CV_32S, cv::Scalar(-1));
  for (const auto& run : runs) {
    const Eigen::Vector2d d = (run.back() - run.front()).normalized();
    for (const auto& q : run) {
      EdgePoint e;
      e.x = static_cast<float>(q.x());
      e.y = static_cast<float>(q.y());
      // Gradient along the left normal (d.y, -d.x): same polarity as d.
      e.gx = static_cast<float>(d.y());
      e.gy = static_cast<float>(-d.x());
      e.magnitude = 1;
      map.points.push_back(e);
    }
  }
  return map;
}

std::vector<LinePiece> PiecesOf(const EdgeMap& map, const std::vector<int>& sizes) {
  std::vector<LinePiece> pieces;
  int next = 0;
  for (int n : sizes) {
    std::vector<int> ids;
    for (int k = 0; k < n; ++k) ids.push_back(next++);
    pieces.push_back(MakePiece(ids, map));
  }
  return pieces;
}

TEST(MergeCollinearPieces, MergesAcrossAThreePixelGap) {
  const double a = 17;
  const Eigen::Vector2d d(std::cos(a * M_PI / 180), std::sin(a * M_PI / 180));
  const Eigen::Vector2d n(d.y(), -d.x());
  struct Case {
    double gap, offset, turn_deg;
    bool merges;
  };
  for (const Case c : {Case{3, 0, 0, true}, Case{3, 0.3, 0.5, true}, Case{3.5, 0, 0, true},
                       Case{8, 0, 0, false}, Case{3, 2.0, 0, false}, Case{3, 0, 6, false}}) {
    const Points2 first = LinePoints({20, 20}, a, 30, 0.05, 1);
    const Eigen::Vector2d start = first.back() + (c.gap + 1) * d + c.offset * n;
    const Points2 second = LinePoints(start, a + c.turn_deg, 30, 0.05, 2);
    const EdgeMap map = MapOf({first, second});
    const auto merged = MergeCollinearPieces(PiecesOf(map, {30, 30}), map, EdgeOptions{});
    EXPECT_EQ(merged.size(), c.merges ? 1u : 2u) << c.gap << " " << c.offset << " " << c.turn_deg;
    if (c.merges && merged.size() == 1u) {
      EXPECT_EQ(merged[0].points.size(), 60u);
      EXPECT_NEAR(merged[0].fit.Length(), 29 + c.gap + 1 + 29, 0.5);
    }
  }
}

TEST(MergeCollinearPieces, OppositePolarityDoesNotMerge) {
  const Points2 first = LinePoints({20, 20}, 0, 30, 0.0, 1);
  const Points2 second = LinePoints({53, 20}, 0, 30, 0.0, 2);
  EdgeMap map = MapOf({first, second});
  for (int k = 30; k < 60; ++k) map.points[k].gy = -map.points[k].gy;
  EXPECT_EQ(MergeCollinearPieces(PiecesOf(map, {30, 30}), map, EdgeOptions{}).size(), 2u);
}

TEST(LinkEdgePoints, FollowsAnEdgeAndStopsAtJunctions) {
  // A horizontal edge on row 5 (x 2..20) and a vertical one on column 12
  // (rows 6..15) meeting it: a T-junction.
  EdgeMap map;
  map.index = cv::Mat(20, 25, CV_32S, cv::Scalar(-1));
  auto add = [&](int x, int y, float gx, float gy) {
    EdgePoint e;
    e.px = x;
    e.py = y;
    e.x = x + 0.5f;
    e.y = y + 0.5f;
    e.gx = gx;
    e.gy = gy;
    e.magnitude = 1;
    map.index.at<int>(y, x) = static_cast<int>(map.points.size());
    map.points.push_back(e);
  };
  for (int x = 2; x <= 20; ++x) add(x, 5, 0, 1);
  for (int y = 6; y <= 15; ++y) add(12, y, 1, 0);
  const auto chains = LinkEdgePoints(map, 40);
  ASSERT_EQ(chains.size(), 2u);
  EXPECT_EQ(chains[0].size() + chains[1].size(), 29u);
  for (const auto& chain : chains) {
    // Every chain is straight: all its points share a row or a column.
    bool same_row = true, same_col = true;
    for (int id : chain) {
      same_row &= map.points[id].py == map.points[chain[0]].py;
      same_col &= map.points[id].px == map.points[chain[0]].px;
    }
    EXPECT_TRUE(same_row || same_col);
  }
}

}  // namespace
}  // namespace roofsweep
