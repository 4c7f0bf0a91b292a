#pragma once

#include <utility>
#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/core/progress.h"
#include "algorithms/edges/segment2d.h"
#include "algorithms/geometry/block.h"
#include "algorithms/geometry/segment3.h"
#include "algorithms/sweep/sweep_half_planes.h"

namespace roofsweep {

// Options of SweepLevelLines. Heights in metres above the ground.
struct LevelLineOptions {
  // Segments whose lift at mid height is shorter are left out: a short
  // segment's band holds too few points to place a face.
  double min_length_m = 3.0;
  // A segment is a candidate when every other view that sees it sees it
  // within this angle of its epipolar lines (LiftOptions::fixing_angle_deg):
  // correspondence cannot place it, and no view fixes its depth.
  double along_epipolar_deg = 15.0;
  // The heights tried: from the ground to max_height_m above it every
  // coarse_step_m with a cheap sweep near the line (a few angles within
  // coarse_theta_deg of level, points within coarse_band_px: there the
  // face's slope moves the texture little), then around each side's best
  // every fine_step_m (fine_steps each way) with the block's sweep. The
  // best height must lie at min_height_m or more: cars, hedges and ground
  // markings peak lower.
  double min_height_m = 3.0;
  double max_height_m = 24.0;
  double coarse_step_m = 1.0;
  double coarse_theta_deg = 40.0;
  double coarse_theta_step_deg = 20.0;
  double coarse_band_px = 30.0;
  int coarse_max_points = 40;
  double fine_step_m = 0.25;
  int fine_steps = 2;
  // The best height must stand out: its side's Sim at least this many times
  // the median of the best Sim over all heights (the height's counterpart
  // of SweepOptions::calibration_peak_ratio), and not at either end of the
  // range.
  double min_height_ratio = 2.0;
  // See SweepLevelLines; negative: no segment is left out for a plane.
  double plane_margin_m = 0.5;
  // The best side's points that correlate at its best plane (not
  // outsiders, SweepOptions::outlier_min_score), as a fraction of its
  // points of interest, must reach this.
  double min_face_fraction = 0.6;
  // Candidates swept at most, the longest first: the sweep costs about
  // (max - min) / coarse_step sides per candidate.
  int max_candidates = 300;
};

// What SweepLevelLines did, for the stage table.
struct LevelLineStats {
  int candidates = 0;  // segments no view fixes, one per edge
  int swept = 0;       // of them swept (max_candidates)
  int peaked = 0;      // with a height that stands out
};

// A level 3D line placed by the sweep of its faces alone.
struct LevelLine {
  Segment3 segment;         // local frame, level
  int view = -1;            // the view whose segment it lifts (its reference view)
  int segment_id = -1;      // index into that view's segments
  double height_m = 0;      // above the ground
  double similarity = 0;    // Sim of its best side at that height
  double height_ratio = 0;  // similarity over the median over the heights
  HalfPlane side;           // its best side at the best fine height swept
};

// A 2D sweep for the segments along the epipolar lines of every view that
// sees them: eaves and ridges along the flight line seen from one strip.
// Correspondence cannot place them (matching leaves them out), and a view
// of the strip sees them along the same image line at any depth. Eaves and
// ridges are level, so the segment's 3D line is its view's ray plane cut at
// a height h, and the faces beside it are the half-planes of Baillard &
// Zisserman (2000, §3) about that line: Sim(theta) over the strip's views
// now has two parameters, (h, theta). The texture of the faces moves across
// itself as h changes where the views' parallax has a component across it
// (mottling, the joints between tiles), so the best (h, theta) places both
// the line and its face; where the texture runs along the baselines only,
// Sim stays flat over h and the height test below refuses the segment.
//
// `segments`: per view, the segments matching worked on; `used`: per view
// and segment, true when a 3D line already observes it; a segment along
// the projection of one of the `known` 3D lines is left out as well.
// Segments whose
// lift onto one of `planes` lies within its patch grown by
// plane_margin_m have their depth from that plane (LiftSegmentsOntoPlanes
// judges them) and are left out. `threshold`: the
// Sim a side needs (CandidateThreshold of the block's sides). Periodic
// texture segments are left out. Deterministic: candidates by length, then
// view and index; the sweep does not depend on the thread count.
std::vector<LevelLine> SweepLevelLines(const Block& block, const std::vector<ViewTexture>& textures,
                                       const std::vector<Segments2D>& segments,
                                       const std::vector<std::vector<bool>>& used,
                                       const std::vector<RoofPlaneHypothesis>& planes,
                                       const std::vector<Segment3>& known, double ground_fallback_z,
                                       double threshold, const SweepOptions& sweep,
                                       const LevelLineOptions& options, Progress& progress,
                                       LevelLineStats* stats = nullptr);

}  // namespace roofsweep
