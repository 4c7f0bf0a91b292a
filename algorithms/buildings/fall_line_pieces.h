#pragma once

#include <vector>

#include "algorithms/buildings/assemble_buildings.h"

namespace roofsweep {

// Options of PiecesAcrossFallLines. Which lines cut a face is the party-wall
// rule of the assembly (AssemblyOptions::party_*), with the same defaults.
struct FallLinePieceOptions {
  // Faces at least this steep have a fall line.
  double min_slope_deg = 10.0;
  // A supporting line within this angle of the fall line ...
  double max_angle_deg = 10.0;
  // ... spanning at least this share of the face's depth there, a depth
  // of at least min_depth_m ...
  double min_span = 0.6;
  double min_depth_m = 2.5;
  // ... cuts the face when at least min_width_m of it lies on either side
  // and no other cut lies within min_width_m: a narrower piece holds too
  // few textured samples to be weighed alone.
  double min_width_m = 3.0;
};

// One piece of a face between its lines down the fall line.
struct FallLinePiece {
  int plane = -1;  // index into the planes
  int order = 0;   // 0, 1, ... across the fall line
  // The plane unchanged; its patch the piece, its lines those whose middle
  // lies in the piece. Id "<plane id> piece <order + 1> of <n>".
  RoofPlaneHypothesis piece;
};

// The pieces of every sloped face that has supporting lines down its fall
// line (verges, party walls) with room on both sides. A terraced row whose
// gables stand at one eave, ridge and pitch with a flat-roofed house
// between them is one plane to the sweep: its ridge and eave run on across
// the gap as one image edge (the stereo pairs of a strip see them along
// their epipolar lines), and its patch, their hull, spans the flat house.
// The verification weighs the patch as a whole, where the two gables carry
// it. Cut at the gables' verges, the piece over the flat house is weighed
// alone. Without footprints this is the only place where a face spanning
// two houses is weighed house by house (PiecesOverFootprints does it with
// them). The caller verifies each piece. Deterministic.
std::vector<FallLinePiece> PiecesAcrossFallLines(const std::vector<RoofPlaneHypothesis>& planes,
                                                 const FallLinePieceOptions& options = {});

// Cuts the pieces the verification refuted (refuted[k] for pieces[k]) out
// of their planes. Each run of consecutive pieces kept becomes a patch of
// its own, the hull of the run: the plane keeps the run of largest area,
// and each other run is appended to `planes` as a copy (id "<plane id>
// part <k>"). Scores become patch area x similarity, as the verification
// scores planes for the conflicts. A plane whose every piece is refuted
// stays whole: it was verified as a whole. Returns the indices of the
// pieces cut, ascending.
std::vector<int> CutRefutedFallLinePieces(const std::vector<FallLinePiece>& pieces,
                                          const std::vector<char>& refuted,
                                          std::vector<RoofPlaneHypothesis>* planes);

}  // namespace roofsweep
