#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/geometry/block.h"

namespace roofsweep {

// What `roofsweep info` reports about a block's geometry: where each image
// looks, at what ground sample distance, and which images see the same ground.

struct ViewFootprint {
  bool valid = false;                    // enough of the image border meets the plane
  std::vector<Eigen::Vector3d> outline;  // convex outline on the reference plane, world
  double area_m2 = 0;
  double gsd_m = 0;                 // metres per pixel where the optical axis meets the plane
  double distance_m = 0;            // camera centre to that point
  double height_above_plane_m = 0;  // signed: negative = camera below the ground
  double off_nadir_deg = 0;         // angle between the optical axis and the plane normal
};

struct ViewOverlap {
  int a = 0, b = 0;
  double fraction = 0;  // overlap area / area of the smaller footprint
};

struct BlockOverview {
  // The plane footprints are taken on: the ground (z = ground height at the
  // block centre) when known, else the "scene plane" through the point
  // nearest to all optical axes, normal to the mean viewing direction.
  Eigen::Vector4d plane = Eigen::Vector4d(0, 0, 1, 0);
  bool plane_is_ground = false;
  std::vector<ViewFootprint> footprints;  // one per view
  std::vector<ViewOverlap> overlaps;      // pairs with fraction > min_overlap
  std::vector<std::string> warnings;      // one line each, naming the image or the DTM
};

struct BlockOverviewOptions {
  double min_overlap = 0.01;  // pairs overlapping less are not listed
  int border_samples = 16;    // rays per image side for the footprint
  // Rays meeting the plane farther than this many times the camera's height
  // above it are cut there (obliques looking at the horizon).
  double max_range_factor = 8.0;
};

BlockOverview AnalyzeBlock(const Block& block, const BlockOverviewOptions& options = {});

// A surface model (DSM) given as the ground: walls and tree crowns make
// height steps between neighbouring cells that bare terrain does not have,
// and with it roof lines count as lines on the ground and walls end at
// roof level. A one-line warning when more than `min_share` of the pairs
// of neighbouring grid cells differ by more than max(min_step_m, the step
// of a 60 degree slope over one cell); nullopt otherwise or without a
// grid. (ODM's dsm.tif of `orthority-odm-drone`: see the test.)
std::optional<std::string> SurfaceModelWarning(const GroundModel& ground, double min_step_m = 2.5,
                                               double min_share = 0.005);

}  // namespace roofsweep
