#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "algorithms/edges/segment2d.h"
#include "algorithms/geometry/segment3.h"

namespace roofsweep::eval {

// Annotated line correspondences over several views, as the Oxford VGG
// sets give them: per view its annotated 2D lines, and per 3D line (row)
// the annotated line id in each view (-1 where it is not marked).
struct LineTracks {
  std::vector<Segments2D> lines;       // per view, pixel-corner coordinates
  std::vector<std::vector<int>> rows;  // per 3D line: id per view, -1 none
  std::vector<Segment3> lines3d;       // per row, when known (same frame as the result)
  // Point of that frame to pixel (pixel-corner coordinates) in a view, when
  // the cameras are known; empty behind the camera. With it and lines3d, two
  // rows whose lines coincide in both views of a pair count as one line there
  // (MatchScores::pairs_collinear_rows).
  std::function<std::optional<Eigen::Vector2d>(int view, const Eigen::Vector3d&)> project;
};

struct MatchEvalOptions {
  // A detected segment is the image of an annotated line when at least
  // min_cover of the shorter of the two lies on the other, within
  // max_distance_px and max_angle_deg (as the issue-4 comparison).
  double max_distance_px = 2.0;
  double max_angle_deg = 5.0;
  double min_cover = 0.5;
};

struct MatchScores {
  // Pairs of observations (two views of one result line) on which the
  // annotation has a say: both segments are images of annotated lines, and
  // one of them is marked in the other's view.
  long long pairs_evaluable = 0, pairs_correct = 0;
  // Of the correct pairs, those whose two segments are marked in different
  // rows whose annotated 3D lines project onto each other (within
  // max_distance_px) in both views of the pair. Each segment then images
  // both rows' lines, so the pair is a correct match of either. Mostly the
  // annotation splits an edge into collinear pieces (the upper and lower
  // part of a wall corner, Merton I) and marks each in a row of its own; a
  // segment that spans both takes one piece's label in one view and the
  // other's in the next. Not counted as annotated pairs found (recall).
  long long pairs_collinear_rows = 0;
  // Result lines with at least one evaluable pair, and those whose
  // evaluable pairs are all correct.
  int lines_evaluable = 0, lines_correct = 0;
  // Annotated correspondences (pairs of views within one row) and those a
  // result line reproduces; annotated 3D lines with at least one.
  long long annotated_pairs = 0, annotated_pairs_found = 0;
  int annotated_lines = 0, annotated_lines_found = 0;
  // 3D: for each correct result line with a known annotated 3D line, the
  // larger distance of its endpoints from that (infinite) line; median, and
  // the size of the scene (diagonal of the annotated 3D lines' box).
  int lines_3d = 0;
  double median_distance_3d = 0, scene_size = 0;
};

// `detected`: per view, the segments the observations index (pixel-corner
// coordinates); `observations`: per result line, its (view, segment) keys.
MatchScores EvaluateMatches(const std::vector<Segments2D>& detected,
                            const std::vector<std::vector<std::pair<int, int>>>& observations,
                            const std::vector<Segment3>& result_lines, const LineTracks& truth,
                            const MatchEvalOptions& options = {});

}  // namespace roofsweep::eval
