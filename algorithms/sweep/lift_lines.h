#pragma once

#include <utility>
#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/edges/segment2d.h"
#include "algorithms/geometry/block.h"
#include "algorithms/geometry/segment3.h"
#include "algorithms/sweep/sweep_half_planes.h"

namespace roofsweep {

// Options of LiftSegmentsOntoPlanes. Lengths in metres unless named _px.
struct LiftOptions {
  // A segment is lifted onto a plane when at least half of its lift lies
  // over the plane's patch grown by this much: the sweep's patches stop
  // short of the eaves and verges that bound them (the band keeps off the
  // line ends), and those edges are the ones wanted.
  double patch_margin_m = 1.0;
  // Shorter lifts are left out: they neither carry a half-plane nor an
  // outline edge.
  double min_length_m = 1.5;
  // A view confirms a lift when detected segments run along its projection
  // there: within this distance and angle ...
  double confirm_distance_px = 1.5;
  double confirm_angle_deg = 5.0;
  // ... over at least this fraction of the projection's length.
  double confirm_coverage = 0.5;
  // Rays meeting the plane at a grazing angle place the lift badly: the
  // cosine between ray and normal must reach this.
  double min_incidence = 0.25;
  // A lift within this distance (both ends of the shorter from the longer's
  // line) and angle of a line already known, and overlapping it, adds
  // nothing.
  double duplicate_distance_m = 0.3;
  double duplicate_angle_deg = 5.0;
  // A lift needs this many confirming views whose epipolar lines cross it
  // at fixing_angle_deg or more: only those check its depth. Along the
  // epipolar lines every view of the strip confirms a lift at any depth:
  // on `realistic` s1, 62 % of the length of such lifts lay off every
  // surface of the scene (by 0.3 m or more), against 16 % of the lifts a
  // view across them confirmed.
  int min_fixing = 1;
  double fixing_angle_deg = 15.0;
  // KeepBorderLifts: the half-plane on the plane's side must lie within
  // this angle of the plane, and the other one must not.
  double border_angle_deg = 10.0;
};

struct LiftedLine {
  Segment3 segment;  // local frame
  int plane = -1;    // index into the planes it was lifted onto
  // (view, segment id): the lifted segment first, then one confirming
  // segment per confirming view.
  std::vector<std::pair<int, int>> observations;
  int fixing = 0;  // confirming views whose epipolar lines cross it (LiftOptions)
};

// Plane-guided line matching: image segments that no 3D line explains are
// lifted onto the roof planes found so far, through their view's ray, and
// kept when another view sees an edge along the lift. It reaches the
// edges that correspondence cannot place, those along the epipolar lines
// of every pair that sees them (eaves and ridges along the flight line,
// seen from one strip): the plane gives their depth. Baillard & Zisserman
// (2000, §5) take border lines from the plane's delineation in the same
// spirit. A lift along the epipolar lines is confirmed by the other views
// of its strip whatever the plane; the sweep and the verification of the
// planes it then supports are what judge it.
//
// `segments`: per view, the segments matching worked on; `used`: per view
// and segment, true when a matched 3D line observes it (those are not
// lifted again). `known`: the 3D lines already there, for duplicates.
// Deterministic: candidates are taken by confirming views, then length,
// then plane, view and segment index; each segment serves one lift.
std::vector<LiftedLine> LiftSegmentsOntoPlanes(const Block& block,
                                               const std::vector<Segments2D>& segments,
                                               const std::vector<std::vector<bool>>& used,
                                               const std::vector<RoofPlaneHypothesis>& planes,
                                               const std::vector<Segment3>& known,
                                               const LiftOptions& options);

// The lifts that bound their plane, as Baillard & Zisserman's border lines
// do (§5): `sides` holds the sweep of the lifted lines (SweepHalfPlanes,
// two per line). Kept when the side facing the plane's patch is a
// candidate within border_angle_deg of the plane and the other side is not.
// Lifts inside a face (texture, shadows: on the plane on both sides) add
// no edge, and a lift beyond the face's true edge shows no plane on
// the patch side. On `realistic` s1 the test raised the share of lifted
// length on a true roof edge (within 0.3 m) from 32 % to 50 %.
std::vector<LiftedLine> KeepBorderLifts(const std::vector<LiftedLine>& lifted,
                                        const std::vector<HalfPlane>& sides,
                                        const std::vector<RoofPlaneHypothesis>& planes,
                                        const LiftOptions& options);

}  // namespace roofsweep
