#pragma once

#include <limits>
#include <string>
#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/buildings/city_model.h"
#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/footprint.h"
#include "algorithms/geometry/block.h"
#include "algorithms/geometry/segment3.h"

namespace roofsweep {

// LoD1 blocks: the fallback for a footprint whose roof could not be
// reconstructed. A survey office that hands in its cadastre expects a model
// of every building; 3DBAG's roofer gives each footprint an LoD1.2 block
// (the footprint extruded to the 70th percentile of the roof's heights)
// beside its LoD2.2 model. Here the heights come from the 3D lines over the
// footprint: the evidence the roof's planes did not get out of.

struct Lod1Options {
  // A line counts for a footprint by its stretch inside it or within this
  // of its outline (m; eaves lie on the outline), when that stretch is at
  // least min_line_length_m long ...
  double line_margin_m = 0.5;
  double min_line_length_m = 1.0;
  // ... and both its ends lie this high above the ground at least (m):
  // lower lines are the ground's, the walls' feet and the cars'.
  double min_height_m = 2.0;
  // ... and it rises at most this steeply (deg): steeper lines are the
  // walls' corners, not the roof.
  double max_slope_deg = 70.0;
  // The roof's height: this quantile of the heights along the lines,
  // weighted by length (3DBAG's LoD1.2 takes the 70th percentile of its
  // roof points). Over the 30 runs with footprints (10 blocks x 3 matching
  // seeds, 51 blocks) the tops lay 0.01 m below the reference roofs on
  // average, so the blocks keep the buildings' volume, at an RMSZ of
  // 1.50 m (1.04 m at each roof's mean height, the least a flat top can
  // reach); the median (0.5) gave 1.38 m but lay 0.55 m too low.
  double quantile = 0.7;
  // Lines that lie wholly farther than this from the median height of the
  // lines over the footprint are left out (m): a roof rarely rises more
  // above its eaves, and a short line matched at a wrong height could
  // otherwise decide the block's height.
  double max_spread_m = 8.0;
  // Too little evidence for a height: fewer lines or less length than this.
  int min_lines = 2;
  double min_length_m = 4.0;
};

struct Lod1Height {
  double z = std::numeric_limits<double>::quiet_NaN();  // NaN: no height
  int lines = 0;                                        // the lines that count (Lod1Options)
  double length_m = 0;  // the length of their stretches over the footprint
};

// The height of an LoD1 block over `outline` (counter-clockwise, local
// frame) standing on `ground_z`, from the 3D lines over it, up to
// `max_height_m` above the ground; z is NaN when the lines that count are
// too few or too short. Deterministic.
Lod1Height Lod1HeightFromLines(const Ring2& outline, double ground_z, double max_height_m,
                               const std::vector<Segment3>& lines, const Lod1Options& options = {});

// The block: the outline extruded from ground_z to roof_z, one surface per
// polygon (ground, flat roof, one wall per outline edge), closed and
// outward oriented; lod 1, roof type unknown (a block says nothing of the
// roof's shape), measured_height roof_z - ground_z. The outline must be
// counter-clockwise with roof_z > ground_z.
Building Lod1Block(const Ring2& outline, double ground_z, double roof_z);

struct Lod1Counts {
  int footprints_without = 0;  // footprint ids without a building in the model
  int blocks = 0;              // of those, given an LoD1 building
};

// Gives every footprint id that no building of `assembled->model` carries
// (footprint_id) an LoD1 building, where the 3D lines `lines` over it give
// a height (Lod1HeightFromLines; ground from `ground`, the lowest under the
// outline as for LoD2): one block per piece of a multipolygon footprint,
// as parts of one building when there are several; a piece whose block
// fails CheckBuildingSolid (a degenerate outline) is left out. The
// building carries footprint_id, outline, supporting_lines,
// lod1_line_length_m, footprint_m2 and lod1_reason: the footprint's reason
// (AssemblyResult::footprint_rejection), whose line in `rejected` is marked
// "; a flat block instead (LoD1)". Ids rs_l0001, ... in footprint order.
// Local frame. Deterministic.
//
// Not the images' height where the lines give none: the flat roof's best
// height over such a footprint (RoofsOverBareFootprints) was tried as a
// fallback over the 30 runs with footprints (10 blocks x 3 matching
// seeds): 25 more blocks, but their heights were off by a median 7.4 m
// (up to 37 m, at scores up to 0.45), and the blocks' RMSZ rose from
// 1.50 m to 11.67 m. A footprint without lines keeps its reason only.
Lod1Counts AddLod1Blocks(const std::vector<Footprint>& footprints, const GroundModel& ground,
                         double max_building_height_m, const std::vector<Segment3>& lines,
                         const Lod1Options& options, AssemblyResult* assembled);

}  // namespace roofsweep
