#pragma once

// 3D lines against a surface model (a DSM), for real blocks that have no
// reference model: the share of line length lying on the surface. It checks
// the matching where `eval` cannot, with what photogrammetry delivers anyway
// (ODM, Pix4D and Metashape write a DSM beside the orientations).

#include <vector>

#include "algorithms/geometry/block.h"
#include "algorithms/geometry/segment3.h"

namespace roofsweep::eval {

struct SurfaceAgreementOptions {
  // A point of a line agrees when its height lies within tolerance_m of the
  // surface's lowest to highest value within window_m of it in plan: roof
  // edges lie where the surface steps, and a DSM smooths a step over a few
  // posts.
  double tolerance_m = 2.0;
  double window_m = 1.5;
  double step_m = 0.5;  // spacing of the points tested along each line
};

struct SurfaceAgreement {
  // [0]: lines seen in two views, [1]: in three or more. Length over the
  // surface model (points where it has no data left out), and the part of
  // it that agrees.
  int lines[2] = {0, 0};
  double length_m[2] = {0, 0};
  double agreeing_m[2] = {0, 0};
};

// `views[k]` is the number of views line k was matched in. Local frame, as
// the grid.
SurfaceAgreement LinesOnSurface(const std::vector<Segment3>& lines, const std::vector<int>& views,
                                const GroundModel::Grid& surface,
                                const SurfaceAgreementOptions& options = {});

}  // namespace roofsweep::eval
