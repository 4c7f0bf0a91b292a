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

// Options of FootprintsBeyondRidges.
struct BeyondRidgeOptions {
  // The face must slope at least this much (a flat roof has no ridge).
  double min_slope_deg = 10.0;
  // The footprint holds one face: every plane covering at least
  // min_face_fraction of it (and 2 m²) lies within same_angle_deg of the
  // first; smaller ones (dormers, chimneys, slivers) do not count.
  double same_angle_deg = 5.0;
  double min_face_fraction = 0.1;
  // The part beyond the face's top covers at least this much of the
  // footprint and min_area_m2.
  double min_fraction = 0.25;
  double min_area_m2 = 5.0;
};

// The part of a footprint beyond the top of the one sloped face found over
// it: the other side of a gable, a shed against a higher wing.
struct FootprintBeyondRidge {
  Footprint part;      // id "<footprint id> beyond <plane id>"
  int footprint = -1;  // index into the footprints
  int plane = -1;      // the face, index into the planes
  double face_slope_deg = 0;
};

// For every footprint over which the planes hold one sloped face (see
// BeyondRidgeOptions), the largest piece of the footprint uphill of the
// highest point of that face's patches over it. Deterministic.
std::vector<FootprintBeyondRidge> FootprintsBeyondRidges(
    const std::vector<RoofPlaneHypothesis>& planes, const std::vector<Footprint>& footprints,
    const BeyondRidgeOptions& options = {});

}  // namespace roofsweep
