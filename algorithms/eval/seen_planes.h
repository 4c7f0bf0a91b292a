#pragma once

#include <Eigen/Core>
#include <vector>

#include "algorithms/buildings/city_model.h"
#include "algorithms/eval/evaluate.h"

namespace roofsweep {

// One reference roof polygon and what each view saw of it (the simulator's
// groundtruth_visibility.json): the share of its projected area where it
// is the visible surface. Found again in the model by its centroid (mean
// of the exterior ring's vertices).
struct SeenPolygon {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  std::vector<float> seen;
};

// Options of ScoreSeenPlanes.
struct SeenPlaneOptions {
  // A plane counts as seen by a view when the view sees this share of it
  // (area-weighted over its polygons), and as seen when min_views views do:
  // stereo needs two.
  double min_fraction = 0.5;
  int min_views = 2;
  // A polygon's centroid and its record's may differ by the writer's
  // rounding.
  double match_m = 0.05;
};

// Completeness over the reference planes the images show. Garden sheds
// under trees and roofs at the block's edge are in the reference but seen
// by fewer than two views: no method reconstructs them, and this tells how
// many of the misses they are. The figures of Evaluate stay as they are.
struct SeenPlaneScores {
  // Per reference plane (EvalResult::reference_planes order): how many
  // views see it; -1 where a polygon of it has no record.
  std::vector<int> views;
  int seen = 0, seen_true_positive = 0;      // planes seen by min_views or more
  int unseen = 0, unseen_true_positive = 0;  // seen by fewer
  int unknown = 0;
  double Completeness() const {
    return seen > 0 ? static_cast<double>(seen_true_positive) / seen : 0.0;
  }
};

// `truth` is the model Evaluate scored (its planes are
// eval.reference_planes); `polygons` in the same frame. Deterministic.
SeenPlaneScores ScoreSeenPlanes(const CityModel& truth, const EvalResult& eval,
                                const std::vector<SeenPolygon>& polygons,
                                const SeenPlaneOptions& options = {});

}  // namespace roofsweep
