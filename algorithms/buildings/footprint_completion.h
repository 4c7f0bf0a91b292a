#pragma once

#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/buildings/footprint.h"

namespace roofsweep {

struct FootprintCompletionOptions {
  // A proposal is left out when the footprint has the same plane over this
  // fraction of the proposed patch already.
  double same_cover = 0.9;
  // Footprints this close (m) are neighbours (terraced houses, party walls).
  double neighbour_gap_m = 0.5;
  // A plane is a neighbour's when it covers this much of the neighbour (m²).
  double min_over_neighbour_m2 = 2.0;
  // Proposals smaller than this (m²) are left out.
  double min_patch_m2 = 4.0;
  // Two proposals for one footprint within these are the same plane.
  double same_angle_deg = 2.0;
  double same_offset_m = 0.2;
};

// Completion by footprints: a row of terraced houses shares its roof
// planes, and the sweep often finds them over some houses only. Each plane
// over a footprint is proposed over every neighbouring footprint: the plane
// unchanged, its patch the footprint's hull cut to the band the plane's
// patch spans across the slope (the front or the back of a gable row; all
// of it for a flat roof), unless the footprint has that plane there
// already. Other planes over the footprint do not stop a proposal, as they
// are often partial or wrong. A proposal is a hypothesis only: the caller verifies it
// photometrically like any other plane. Ids say where a proposal comes from.
// Deterministic.
std::vector<RoofPlaneHypothesis> PlanesFromNeighbourFootprints(
    const std::vector<RoofPlaneHypothesis>& planes, const std::vector<Footprint>& footprints,
    const FootprintCompletionOptions& options = {});

// Footprints no plane covers: the planes' patches together overlap less
// than `min_cover` of the footprint's area (each patch counted alone, so
// overlapping patches may overstate the cover). Indices into `footprints`,
// ascending.
std::vector<int> BareFootprints(const std::vector<RoofPlaneHypothesis>& planes,
                                const std::vector<Footprint>& footprints, double min_cover = 0.25);

}  // namespace roofsweep
