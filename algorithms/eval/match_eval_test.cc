#include "algorithms/eval/match_eval.h"

#include <gtest/gtest.h>

namespace roofsweep::eval {
namespace {

Segment2D Seg(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y1}}; }

// Two views; annotated lines 0 and 1 in both, plus line 2 in view 0 only.
// Rows: line 0 <-> 0, line 1 <-> 1, line 2 unmarked in view 1.
LineTracks Truth() {
  LineTracks t;
  t.lines = {{Seg(0, 0, 100, 0), Seg(0, 50, 100, 50), Seg(0, 90, 100, 90)},
             {Seg(10, 0, 110, 0), Seg(10, 50, 110, 50)}};
  t.rows = {{0, 0}, {1, 1}, {2, -1}};
  t.lines3d = {{{0, 0, 0}, {10, 0, 0}}, {{0, 5, 0}, {10, 5, 0}}, {{0, 9, 0}, {10, 9, 0}}};
  return t;
}

TEST(EvaluateMatches, CountsCorrectWrongAndUnjudgedPairs) {
  // Detected: view 0 finds all three lines (the first only in part), plus
  // a texture line; view 1 finds its two lines, offset by 1 px.
  const std::vector<Segments2D> detected = {
      {Seg(0, 0.5, 60, 0.5), Seg(0, 50, 100, 50), Seg(0, 90, 100, 90), Seg(0, 200, 80, 200)},
      {Seg(10, 1, 110, 1), Seg(10, 51, 110, 51)}};
  const std::vector<std::vector<std::pair<int, int>>> obs = {
      {{0, 0}, {1, 0}},  // right
      {{0, 1}, {1, 0}},  // wrong: line 1 with line 0
      {{0, 2}, {1, 1}},  // line 2 is not marked in view 1, line 1 is in view 0: judged, wrong
      {{0, 3}, {1, 1}},  // a texture line: no annotation, not judged
  };
  const std::vector<Segment3> lines = {
      {{0, 0.1, 0}, {6, 0.1, 0.2}}, {{0, 5, 0}, {10, 5, 0}}, {{0, 9, 0}, {1, 9, 0}}, {}};
  const MatchScores s = EvaluateMatches(detected, obs, lines, Truth());
  EXPECT_EQ(s.pairs_evaluable, 3);
  EXPECT_EQ(s.pairs_correct, 1);
  EXPECT_EQ(s.lines_evaluable, 3);
  EXPECT_EQ(s.lines_correct, 1);
  EXPECT_EQ(s.annotated_lines, 2);  // row 2 is marked in one view only
  EXPECT_EQ(s.annotated_pairs, 2);
  EXPECT_EQ(s.annotated_pairs_found, 1);
  EXPECT_EQ(s.annotated_lines_found, 1);
  ASSERT_EQ(s.lines_3d, 1);
  EXPECT_NEAR(s.median_distance_3d, std::hypot(0.1, 0.2), 1e-9);
  EXPECT_NEAR(s.scene_size, std::hypot(10, 9), 1e-9);
}

TEST(EvaluateMatches, ASegmentFarFromEveryAnnotatedLineIsNotJudged) {
  const std::vector<Segments2D> detected = {{Seg(0, 3, 100, 3)}, {Seg(10, 0, 110, 0)}};
  const MatchScores s = EvaluateMatches(detected, {{{0, 0}, {1, 0}}}, {}, Truth());
  EXPECT_EQ(s.pairs_evaluable, 0);
  EXPECT_EQ(s.lines_evaluable, 0);
  EXPECT_EQ(s.annotated_pairs_found, 0);
}

// One edge annotated as two collinear pieces (rows 0 and 1), and a parallel
// edge (row 2) 0.3 m beside it, in two views of a camera that maps (x, y, z)
// to 10 (x + view, y) px.
LineTracks Pieces(bool with_cameras) {
  LineTracks t;
  t.lines = {{Seg(0, 0, 50, 0), Seg(50, 0, 100, 0), Seg(0, 3, 100, 3)},
             {Seg(10, 0, 60, 0), Seg(60, 0, 110, 0), Seg(10, 3, 110, 3)}};
  t.rows = {{0, 0}, {1, 1}, {2, 2}};
  t.lines3d = {{{0, 0, 0}, {5, 0, 0}}, {{5, 0, 0}, {10, 0, 0}}, {{0, 0.3, 0}, {10, 0.3, 0}}};
  if (with_cameras)
    t.project = [](int v, const Eigen::Vector3d& p) -> std::optional<Eigen::Vector2d> {
      return Eigen::Vector2d(10 * (p.x() + v), 10 * p.y());
    };
  return t;
}

TEST(EvaluateMatches, CollinearPiecesOfOneEdgeAreOneLineWhenTheCamerasAreKnown) {
  // Line 0 spans the edge: mostly the first piece in view 0, the second in
  // view 1. Line 1 takes the parallel edge in view 1: a mismatch.
  const std::vector<Segments2D> detected = {{Seg(0, 0, 60, 0), Seg(0, 0.2, 100, 0.2)},
                                            {Seg(50, 0, 110, 0), Seg(10, 3, 110, 3)}};
  const std::vector<std::vector<std::pair<int, int>>> obs = {{{0, 0}, {1, 0}}, {{0, 1}, {1, 1}}};
  const MatchScores blind = EvaluateMatches(detected, obs, {}, Pieces(false));
  EXPECT_EQ(blind.pairs_evaluable, 2);
  EXPECT_EQ(blind.pairs_correct, 0);
  EXPECT_EQ(blind.pairs_collinear_rows, 0);
  const MatchScores s = EvaluateMatches(detected, obs, {}, Pieces(true));
  EXPECT_EQ(s.pairs_evaluable, 2);
  EXPECT_EQ(s.pairs_correct, 1);
  EXPECT_EQ(s.pairs_collinear_rows, 1);
  EXPECT_EQ(s.lines_correct, 1);
  EXPECT_EQ(s.annotated_pairs_found, 0);  // recall counts a row's own pairs only
}

}  // namespace
}  // namespace roofsweep::eval
