#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/core/progress.h"
#include "algorithms/edges/edge_options.h"
#include "algorithms/edges/segment2d.h"
#include "algorithms/geometry/block.h"
#include "algorithms/geometry/segment3.h"
#include "algorithms/matching/chromatic_test.h"
#include "algorithms/matching/match_options.h"

namespace roofsweep {

// A reconstructed 3D line with what supports it.
struct Line3D {
  Segment3 segment;  // local frame; a -> b runs like the first observation's p0 -> p1
  std::vector<std::pair<int, int>> observations;  // (view index, segment id)
  double rms_px = 0;                              // reprojection residual
  // Mean RGB ([0, 1]) of the flanking strips left and right of the first
  // observation, walking a -> b.
  Eigen::Vector3f colour_left = Eigen::Vector3f::Zero();
  Eigen::Vector3f colour_right = Eigen::Vector3f::Zero();
  // Depth from the 3D lines at its ends rather than from stereo
  // (CompleteAtJunctions).
  bool from_junctions = false;
  // Depth from one junction, the line assumed horizontal.
  bool horizontal_assumed = false;
  int Views() const { return static_cast<int>(observations.size()); }
};

// Where a line's depth comes from, as written in `lines3d.depth_from`:
// "stereo", "junctions" or "junction_horizontal".
const char* DepthFrom(const Line3D& line);

// Counts of the reduction funnel (Scholze et al. 2000, §4) summed over the
// view pairs, with the ground-truth counterparts when truth was given.
struct MatchFunnel {
  long long segments = 0;          // detected, all views
  int view_pairs = 0;              // pairs with distinct centres
  long long skipped_epipolar = 0;  // segment/pair combinations nearly along the epipolar lines
  long long geometric = 0, chromatic = 0, correlation = 0, verified = 0, unambiguous = 0,
            assigned = 0;
  int lines_before_merge = 0, lines = 0;
  // Lines cut back to the part two views hold, and the length removed.
  int ends_cut = 0;
  double ends_cut_m = 0;
  // Junction completion: unused segments anchored at both ends, those that
  // passed the verification, and the lines added (included in `lines`).
  long long junction_candidates = 0, junction_verified = 0;
  int junction_lines = 0, junction_horizontal = 0;
  int junction_true = -1;  // with truth: added lines whose observations share a true edge
  // Residual test (residual_test.h): the noise level (0: not estimated), the
  // lines it rests on (-1: test off), the lines rejected and, with truth,
  // how many of those had observations sharing a true edge.
  double residual_sigma_px = 0;
  int residual_lines = -1, residual_rejected = 0, residual_rejected_true = -1;
  // Ground truth (-1: unknown): true pairs among all segment pairs of
  // overlapping views, and how many of them survive each stage.
  long long true_all = -1, true_geometric = -1, true_chromatic = -1, true_correlation = -1,
            true_verified = -1, true_unambiguous = -1, true_assigned = -1;
  // The same per true edge: the 3D length of the distinct true edges that
  // at least one true pair of the stage lies on (several view pairs, and
  // fragments, give one edge several true pairs; the one-to-one step keeps
  // one of them by design, so the pairs fall faster than the edges).
  double true_edges_all_m = -1, true_edges_geometric_m = -1, true_edges_chromatic_m = -1,
         true_edges_correlation_m = -1, true_edges_verified_m = -1, true_edges_unambiguous_m = -1,
         true_edges_assigned_m = -1;
};

struct MatchTimings {
  double edges_s = 0, features_s = 0, candidates_s = 0, verify_s = 0, assign_s = 0,
         triangulate_s = 0;
};

// With ground truth: how far each true edge got. Its views hold a matched
// segment (after the texture filter) within 1.5 px and 3 deg of its
// projection.
struct TruthEdgeReach {
  int views = 0;       // views holding a segment on it
  int view_pairs = 0;  // pairs of overlapping views that both hold one
  // Of those pairs, the ones where each of the first view's segments on it
  // lies within min_epipolar_angle of the epipolar lines: no pair can fix
  // its depth (an edge along the flight line seen from one strip only).
  int along_epipolar = 0;
  // The furthest stage a true pair on it reached: 0 none, 1 eligible,
  // 2 geometric, 3 chromatic, 4 chromatic correlation, 5 verified in other
  // views, 6 unambiguous, 7 one-to-one.
  int stage = 0;
};

struct MatchResult {
  std::vector<Segments2D> segments;  // per view, as matched (MatchOptions::match_texture)
  std::vector<Line3D> lines;
  MatchFunnel funnel;
  std::vector<TruthEdgeReach> truth_edges;  // with truth, one per true edge
  MatchTimings timings;
  std::vector<std::string> messages;  // why a result is empty or partial
};

// Matches the straight segments of all views and reconstructs 3D lines
// (Scholze et al. 2000, §3, extended to many views). `images`: one per
// block view, CV_32FC3 RGB or CV_32FC1 in [0, 1]. Edges are extracted first
// (TBB across images) with `edge_options`. A block with fewer than two
// views, or without pairs of distinct overlapping views, gives an empty
// result with a message. `truth_edges` (local frame) enables the
// ground-truth counts of the funnel. Throws roofsweep::Error when the image
// count differs from the view count.
// The segments of every view as MatchLines works on them (texture
// segments left out unless MatchOptions::match_texture): the segment ids of
// Line3D::observations index these.
std::vector<Segments2D> ExtractViewSegments(const std::vector<cv::Mat>& images,
                                            const MatchOptions& options,
                                            const EdgeOptions& edge_options);

MatchResult MatchLines(const Block& block, const std::vector<cv::Mat>& images,
                       const MatchOptions& options, const EdgeOptions& edge_options,
                       Progress& progress, const std::vector<Segment3>* truth_edges = nullptr);

// The funnel as the paper's table (text).
std::string FormatFunnel(const MatchFunnel& funnel);

}  // namespace roofsweep
