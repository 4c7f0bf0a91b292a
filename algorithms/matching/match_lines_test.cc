// End-to-end matching on small simulated blocks, and degenerate input.
#include "algorithms/matching/match_lines.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <set>

#include "algorithms/core/error.h"
#include "algorithms/eval/line_eval.h"
#include "algorithms/matching/residual_test.h"
#include "algorithms/matching/sim_block_fixture.h"

namespace roofsweep {
namespace {

TEST(MatchLines, SimulatedBlockThreeSeeds) {
  for (uint64_t seed : {1, 2, 3}) {
    const SimBlock b = SimulateSmallBlock(seed);
    NullProgress np;
    const MatchResult r =
        MatchLines(b.block, b.images, MatchOptions{}, EdgeOptions{}, np, &b.truth);
    std::vector<Segment3> lines;
    for (const Line3D& l : r.lines) lines.push_back(l.segment);
    const eval::LineScores s = eval::EvaluateLines(lines, b.roof, b.extra, eval::LineEvalOptions{});
    ASSERT_GT(s.result_length_m, 0) << "seed " << seed;
    std::printf("seed %d: %zu roof edges, %.1f m of roof edge\n", static_cast<int>(seed),
                b.roof.size(), s.roof_edge_length_m);
    // The fixture must hold a few buildings, or the scores mean nothing.
    ASSERT_GT(s.roof_edge_length_m, 100.0) << "seed " << seed << ": degenerate scene";
    const double precision = s.result_on_reference_m / s.result_length_m;
    const double roof_completeness = s.roof_edge_covered_m / s.roof_edge_length_m;
    eval::LineEvalOptions loose;
    loose.distance_m = 0.5;
    const eval::LineScores s50 = eval::EvaluateLines(lines, b.roof, b.extra, loose);
    std::printf("seed %d: within 0.5 m: precision %.3f, roof-edge completeness %.3f\n",
                static_cast<int>(seed), s50.result_on_reference_m / s50.result_length_m,
                s50.roof_edge_covered_m / s50.roof_edge_length_m);
    const MatchFunnel& f = r.funnel;
    const double chroma_kept = static_cast<double>(f.true_chromatic) / f.true_geometric;
    std::printf(
        "seed %d: %zu lines, precision %.3f, roof-edge completeness %.3f, "
        "true pairs kept by the chromatic test %.3f\n%s",
        static_cast<int>(seed), r.lines.size(), precision, roof_completeness, chroma_kept,
        FormatFunnel(f).c_str());
    // Measured (seeds 1-3, 15 cm fixture, with junction completion):
    // precision 0.245 / 0.225 / 0.214, roof-edge completeness 0.390 / 0.521 /
    // 0.429. These floors sit below; the
    // issue's targets (0.95 / 0.90) are NOT reached yet.
    EXPECT_GT(precision, 0.15) << "seed " << seed;
    EXPECT_GT(roof_completeness, 0.08) << "seed " << seed;
    EXPECT_GE(f.geometric, f.chromatic);
    EXPECT_GE(f.chromatic, f.correlation);
    EXPECT_GE(f.correlation, f.verified);
    EXPECT_GE(f.verified, f.unambiguous);
    EXPECT_GE(f.unambiguous, f.assigned);
    // Per true edge: each stage keeps a subset of the previous one's edges,
    // and the final pairs lie on some.
    EXPECT_GE(f.true_edges_all_m, f.true_edges_geometric_m);
    EXPECT_GE(f.true_edges_geometric_m, f.true_edges_chromatic_m);
    EXPECT_GE(f.true_edges_chromatic_m, f.true_edges_correlation_m);
    EXPECT_GE(f.true_edges_correlation_m, f.true_edges_verified_m);
    EXPECT_GE(f.true_edges_all_m, f.true_edges_verified_m);
    EXPECT_GE(f.true_edges_verified_m, f.true_edges_unambiguous_m);
    EXPECT_GE(f.true_edges_unambiguous_m, f.true_edges_assigned_m);
    if (f.true_assigned > 0) {
      EXPECT_GT(f.true_edges_assigned_m, 0);
    }
    // Per true edge, the furthest stage agrees with the funnel's lengths; an
    // edge that every pair holding it sees along its epipolar lines, or that
    // fewer than two views hold, is never a candidate.
    ASSERT_EQ(r.truth_edges.size(), b.truth.size());
    double eligible_m = 0, verified_m = 0;
    int out_of_reach = 0;
    for (size_t e = 0; e < b.truth.size(); ++e) {
      const TruthEdgeReach& t = r.truth_edges[e];
      EXPECT_GE(t.view_pairs, t.along_epipolar);
      EXPECT_LE(t.view_pairs, t.views * (t.views - 1) / 2);
      if (t.stage >= 1) eligible_m += b.truth[e].Length();
      if (t.stage >= 5) verified_m += b.truth[e].Length();
      if (t.views < 2 || t.along_epipolar == t.view_pairs) {
        EXPECT_EQ(t.stage, 0) << "edge " << e;
        out_of_reach += t.views >= 2;
      }
    }
    EXPECT_NEAR(eligible_m, f.true_edges_all_m, 1e-6);
    EXPECT_NEAR(verified_m, f.true_edges_verified_m, 1e-6);
    std::printf("seed %d: %d edges held by two views or more only along epipolar lines\n",
                static_cast<int>(seed), out_of_reach);
    // One-to-one: no (view, segment) in two lines before merging.
    std::set<std::pair<int, int>> used;
    size_t obs = 0;
    for (const Line3D& l : r.lines) {
      obs += l.observations.size();
      used.insert(l.observations.begin(), l.observations.end());
      EXPECT_GE(l.Views(), 2);
      EXPECT_LE(l.rms_px, MatchOptions{}.max_residual);
      // The residual test ran on the stereo lines (junction lines have their own checks).
      if (!l.from_junctions) {
        EXPECT_TRUE(ResidualConsistent({l.rms_px, l.Views()}, f.residual_sigma_px,
                                       MatchOptions{}.residual_alpha));
      }
    }
    EXPECT_EQ(used.size(), obs);
    // Synthetic images with exact orientations: segment noise of a few
    // tenths of a pixel at most.
    EXPECT_GT(f.residual_sigma_px, 0.01) << "seed " << seed;
    EXPECT_LT(f.residual_sigma_px, 0.5) << "seed " << seed;
  }
}

TEST(MatchLines, DegenerateInput) {
  SimBlock b = SimulateSmallBlock(1);
  NullProgress np;
  // Image count mismatch: a clear error.
  EXPECT_THROW(MatchLines(b.block, {b.images[0]}, {}, {}, np), Error);
  // A single view: an empty result with a message.
  Block one = b.block;
  one.views.resize(1);
  MatchResult r = MatchLines(one, {b.images[0]}, {}, {}, np);
  EXPECT_TRUE(r.lines.empty());
  ASSERT_FALSE(r.messages.empty());
  EXPECT_NE(r.messages[0].find("at least two"), std::string::npos);
  // Identical views: no stereo, empty with a message.
  Block same = b.block;
  same.views.resize(2);
  same.views[1] = same.views[0];
  same.views[1].name = "copy";
  r = MatchLines(same, {b.images[0], b.images[0]}, {}, {}, np);
  EXPECT_TRUE(r.lines.empty());
  EXPECT_FALSE(r.messages.empty());
  // Non-overlapping views: the second camera moved 5 km away.
  Block apart = b.block;
  apart.views.resize(2);
  apart.views[1].pose.C.x() += 5000;
  r = MatchLines(apart, {b.images[0], b.images[1]}, {}, {}, np);
  EXPECT_TRUE(r.lines.empty());
  EXPECT_FALSE(r.messages.empty());
  // Blank images: no segments, nothing to match, no crash.
  std::vector<cv::Mat> blank(b.block.views.size(),
                             cv::Mat(512, 512, CV_32FC3, cv::Scalar(0.4, 0.4, 0.4)));
  r = MatchLines(b.block, blank, {}, {}, np);
  EXPECT_TRUE(r.lines.empty());
}

}  // namespace
}  // namespace roofsweep
