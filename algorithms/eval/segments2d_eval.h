#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/edges/segment2d.h"
#include "algorithms/geometry/camera.h"
#include "algorithms/geometry/view.h"
#include "algorithms/simulate/scene_truth.h"

namespace roofsweep {
namespace eval {

// Image-space evaluation of detected 2D segments against the projected
// true 3D edges of a simulated scene (issue 4). Lengths in pixels, angles
// in degrees. Pixel convention as everywhere: origin at the top-left corner.
struct Segment2DEvalOptions {
  // A true-edge sample is covered by a detected segment (and a detected
  // sample lies on a true edge) when the point-to-segment distance is at
  // most max_distance_px and the directions differ by at most max_angle_deg.
  double max_distance_px = 1.5;
  double max_angle_deg = 5.0;
  // True edges shorter than this in the image (the part inside the image)
  // are not counted in recall: the detector drops segments below 15 px.
  double min_edge_length_px = 15.0;
  // Spacing of the samples along true edges and detected segments.
  double sample_step_px = 1.0;
  // Samples nearer than this to the image border are ignored (the gradient
  // is not defined there).
  double border_px = 2.0;
  // Diagnostics: the "interior" scores leave out the samples within this
  // distance of either end of the projected edge (junctions and corners,
  // where any detector loses a few pixels).
  double end_margin_px = 5.0;
  // Visibility probes: the sample and the points this far across the edge on
  // either side (an eave or verge is the border of its face, so the pixel on
  // the edge itself may show the ground behind; one side shows the face).
  double probe_offset_px = 1.0;
};

// Whether the surface point at camera depth `depth` (m, camera z) that
// projects to `pixel` is what the image shows there.
using VisibilityFn = std::function<bool(const Eigen::Vector2d& pixel, double depth)>;

// Visibility from a depth map sampled at pixel centres (CV_32F, camera z,
// +inf where nothing; the renderer's GeometryMaps::depth): the pixel holding
// `pixel` agrees with `depth` within max(tolerance_m, tolerance_rel * depth).
// Points outside the map are not visible. The map is shared, not copied.
VisibilityFn DepthMapVisibility(const cv::Mat& depth, double tolerance_m = 0.25,
                                double tolerance_rel = 0.005);

struct LengthScore {
  double length_px = 0;   // visible projected length evaluated
  double covered_px = 0;  // of it, covered by a detected segment
  double Ratio() const { return length_px > 0 ? covered_px / length_px : 0.0; }
};

struct Segment2DScores {
  // Recall: visible projected length of the roof edges (sim::IsRoofEdge)
  // at least min_edge_length_px long, and the part of it covered.
  LengthScore roof;
  // The same per kind, for every kind (walls, footprints, markings too).
  std::map<sim::EdgeKind, LengthScore> per_kind;
  // The same without the end_margin_px at either end of each edge.
  LengthScore roof_interior;
  std::map<sim::EdgeKind, LengthScore> per_kind_interior;
  // Per true edge (same order as the input): visible evaluated length and
  // covered length; zero for edges too short, outside or hidden.
  std::vector<LengthScore> per_edge;
  // Precision: detected length, and the part lying on SOME true edge of any
  // kind. Every projected true edge counts here, visible or not: a detector
  // finding an edge of the scene is right even where the depth map says a
  // thin occluder (a tree crown's border) covers it, and hidden edges are
  // rarely hit by chance at 1.5 px and 5 deg.
  double detected_px = 0;
  double detected_on_truth_px = 0;
  // Per detected segment (same order as the input): its length and the part
  // on a true edge, for diagnosing what the false positives are.
  std::vector<LengthScore> per_segment;
  int segments = 0;

  double Recall() const { return roof.Ratio(); }
  double Precision() const { return detected_px > 0 ? detected_on_truth_px / detected_px : 0.0; }
};

// Scores `detected` (segments of the image of camera/pose) against `truth`
// (the scene's 3D edges, local frame). Deterministic; pure.
Segment2DScores EvaluateSegments2D(const Camera& camera, const Pose& pose,
                                   const std::vector<sim::TrueEdge>& truth,
                                   const VisibilityFn& visible, const Segments2D& detected,
                                   const Segment2DEvalOptions& options = {});

}  // namespace eval
}  // namespace roofsweep
