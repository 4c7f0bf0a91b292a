#pragma once

#include <Eigen/Core>
#include <limits>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "algorithms/core/progress.h"
#include "algorithms/geometry/block.h"
#include "algorithms/geometry/segment3.h"
#include "algorithms/sweep/points_of_interest.h"
#include "algorithms/sweep/sweep_options.h"

namespace roofsweep {

// A 3D line to sweep. The sweep needs only the end points; `views` (block
// view indices where the line was observed, as matching's
// Line3D::observations give them) restricts the choice of the reference
// view when not empty. Every view that sees a part of the line (see
// SweepOptions::min_visible_px) takes part in Sim.
struct SweepLine {
  Segment3 segment;
  std::vector<int> views;
  // Reprojection residual of the matched line (Line3D::rms_px); NaN when
  // unknown (lines read from a file without it, true edges). Not used by
  // the sweep; carried to the buildings' quality attributes.
  double rms_px = std::numeric_limits<double>::quiet_NaN();
  // Placed level by the sweep of its face alone (SweepLevelLines): any two
  // such lines at one height are coplanar with a flat roof there, so it
  // joins planes only through its own half-planes, not as a coplanar line
  // (AttachCoplanarLines, PlanesFromLinePairs).
  bool level = false;
};

// One line side with its best half-plane (Baillard & Zisserman 2000, §3.4)
// and the reliability indicators §4 sorts by.
struct HalfPlane {
  int line = -1;            // index into the input lines
  int side = 0;             // +1 left of a -> b seen from above, -1 right (HalfPlaneFamily)
  int reference_view = -1;  // most textured view of this side; -1 when none
  double theta_deg = 0;     // HalfPlaneFamily angle of the best plane
  Eigen::Vector4d plane = Eigen::Vector4d::Zero();  // n . X + pi_4 = 0, n unit and upward
  double similarity = 0;                            // Sim(theta*) in [0, 1]
  double curvature = 0;     // Sim''(theta*) per rad^2 (negative at a maximum)
  int points = 0;           // points of interest used (after outlier removal)
  int points_detected = 0;  // points of interest in the neighbourhood
  int views = 0;            // valid views besides the reference in Sim
  // How far the plane reaches from the line on this side (m, in the plane):
  // a high quantile of the distances of the points of interest that still
  // correlate at theta* (the sweep's own evidence of the face; bounded by
  // the band width). 0 when unknown. Grouping and delineation (§4, §5) use
  // it as the half-plane's first extent.
  double extent_m = 0;
  // Plan view (x, y) outline of the same evidence: the convex hull of the
  // line's end points and the correlating points within extent_m, lifted
  // onto the plane. Empty when there were no such points.
  std::vector<Eigen::Vector2d> support;
  bool accepted = false;  // the paper's test (SweepOptions::min_similarity, min_curvature)
  // Passes the looser candidate test (SweepOptions::candidate_*): enough
  // to propose a plane that §5's verification over the whole patch then
  // confirms or rejects. Every accepted half-plane is a candidate.
  bool candidate = false;
  // Sim(theta*) over the median of `profile`: how far the peak stands out,
  // whatever the image noise (SweepOptions::calibration_peak_ratio).
  double peak_ratio = 0;
  // An interior maximum with enough views and curvature: a candidate once
  // Sim reaches the block's calibrated threshold.
  bool candidate_shape = false;
  std::string reason;  // why not accepted; empty when accepted
  // Sim at the coarse samples theta_min, theta_min + step, ... (all points
  // and views, before outlier removal and the valid-view test).
  std::vector<double> profile;
};

// The side of `line` (as HalfPlane::side: +1 left of a -> b seen from
// above) on which the plan point p lies; 0 on the line.
inline int SideOf(const Segment3& line, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = (line.b - line.a).head<2>();
  const Eigen::Vector2d m = p - line.a.head<2>();
  const double cross = d.x() * m.y() - d.y() * m.x();
  return cross > 0 ? 1 : (cross < 0 ? -1 : 0);
}

// The Sim a side with a candidate's shape needs to be a candidate, at the
// image quality of the block these sides were swept from
// (SweepOptions::calibration_peak_ratio).
double CandidateThreshold(const std::vector<HalfPlane>& sides, const SweepOptions& options);

// True when these sides were swept from imagery noisy enough for the wider
// correlation window (SweepOptions::wide_ncc_radius), with the narrower one.
bool WantsWiderWindow(const std::vector<HalfPlane>& sides, const SweepOptions& options);

// A correlation threshold set for clear images (VerifyOptions::min_score)
// at the image quality of these sides: scaled by the square root of the
// scale CandidateThreshold applies, since Sim is a mean of squared
// correlations. Never raised.
double ScoreThresholdAtImageQuality(double min_score, const std::vector<HalfPlane>& sides,
                                    const SweepOptions& options);

// Sweeps both sides of every line: two results per line, at 2 i (side +1)
// and 2 i + 1 (side -1). `images`: one per block view, CV_32FC3 RGB or
// CV_32FC1 in [0, 1] (io's ReadImage), of the cameras' size. Parallel over
// lines (TBB); the result does not depend on the thread count. Throws
// roofsweep::Error for a count or size mismatch, Cancelled when progress
// asks to stop.
//
// `previous`: the result of an earlier call on the first previous->size() / 2
// of these lines, before the others were added. Those lines keep their
// sides unless an added line comes near their band in some view; the
// result equals a sweep of all lines from scratch.
std::vector<HalfPlane> SweepHalfPlanes(const Block& block, const std::vector<cv::Mat>& images,
                                       const std::vector<SweepLine>& lines,
                                       const SweepOptions& options, Progress& progress,
                                       const std::vector<HalfPlane>* previous = nullptr);

// What the sweep reads of every view, prepared once for several sweeps of
// one block (`run` sweeps three times). Checks the images as
// SweepHalfPlanes does.
std::vector<ViewTexture> PrepareViewTextures(const Block& block, const std::vector<cv::Mat>& images,
                                             const SweepOptions& options);

// SweepHalfPlanes on views PrepareViewTextures prepared with the same
// options.
std::vector<HalfPlane> SweepHalfPlanes(const Block& block, const std::vector<ViewTexture>& textures,
                                       const std::vector<SweepLine>& lines,
                                       const SweepOptions& options, Progress& progress,
                                       const std::vector<HalfPlane>* previous = nullptr);

}  // namespace roofsweep
