#pragma once

#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/geometry/block.h"

namespace roofsweep {

// Where a sloped roof face changes colour across its whole depth: the
// party wall of terraced houses whose roofs were laid or renewed apart.
// The grouping joins such houses into one plane when they share eave,
// ridge and pitch, and no 3D line runs down the wall when the two roofs
// meet flush (README "Party walls where no line was matched"). The
// assembly cuts there as at a party line (AssemblyOptions::
// split_at_party_lines), and the facing face must show the wall too.
struct ColourBreakOptions {
  // Only sloped faces: the break runs down the fall line, the direction a
  // party wall takes under a pitched roof.
  double min_slope_deg = 10.0;
  // Plan-view sample spacing over the patch; at least half a pixel of the
  // finest view of the patch.
  double spacing_m = 0.1;
  // The colours compared on either side of a break are taken over this
  // width, leaving this gap at the break (the seam, a verge tile, the
  // blur of the images).
  double window_m = 1.5;
  double gap_m = 0.2;
  // A break leaves at least this much of the face on either side and lies
  // this far from any other break (AssemblyOptions::party_min_width_m).
  double min_side_m = 3.0;
  // Faces shallower than this along the fall line are not searched
  // (AssemblyOptions::party_min_depth_m: porches, dormers).
  double min_depth_m = 2.5;
  // The face's depth is cut into this many bands; the colour must change in
  // every band, so that a dormer, a skylight or a shadow that covers part
  // of the depth does not make a break.
  int depth_bands = 3;
  // CIE76 colour difference between the two sides' median L*a*b* colours
  // that each band must reach: a change a person sees at a glance, far
  // above the noise of one roof's median colour over a few hundred
  // samples. On nine simulated blocks (matched lines, seed 1) 63 of the 74
  // breaks scoring 12 or more lay within 0.5 m of a true roof edge, 8 of
  // the 18 scoring 8-12.
  double min_delta_e = 12.0;
  // A side's median needs this many samples in each band.
  int min_samples = 20;
  // Views a sample is coloured from: the median over the views that see
  // it, so that a view in which a neighbour hides it does not decide.
  int min_views = 2;
};

// Per plane, the colour breaks found on it: plan segments down the fall
// line across the patch. Parallel over planes (TBB), deterministic.
// `images` RGB (CV_32FC3, 0..1) as VerifyPlanes takes them; grey images
// give none.
std::vector<std::vector<std::array<Eigen::Vector2d, 2>>> FindColourBreaks(
    const Block& block, const std::vector<cv::Mat>& images,
    const std::vector<RoofPlaneHypothesis>& planes, const ColourBreakOptions& options);

}  // namespace roofsweep
