#pragma once

#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/buildings/footprint.h"

namespace roofsweep {

// Options of PiecesOverFootprints.
struct FootprintPieceOptions {
  // A piece smaller than this (m²) is eave overhang or registration error,
  // as in AssemblyOptions::footprint_min_piece_m2.
  double min_piece_m2 = 2.0;
};

// The part of a plane over one footprint, as a hypothesis of its own.
struct FootprintPiece {
  int plane = -1;      // index into the planes
  int footprint = -1;  // index into the footprints
  // The plane unchanged; its patch the hull of the patch's largest piece
  // over the footprint, its lines those whose middle lies in that piece.
  // Id "<plane id> over footprint <footprint id>".
  RoofPlaneHypothesis piece;
};

// The pieces of every plane whose patch covers footprints of two ids or
// more by at least min_piece_m2 each. A plane verified as a whole can be
// one roof's face running on over a neighbour's footprint (a gable row
// that ends at a flat house): the verification's textured samples lie
// mostly on the face, and the part over the neighbour is never weighed on
// its own. The caller verifies each piece. Deterministic.
std::vector<FootprintPiece> PiecesOverFootprints(const std::vector<RoofPlaneHypothesis>& planes,
                                                 const std::vector<Footprint>& footprints,
                                                 const FootprintPieceOptions& options = {});

// A plane's patch cut back to the pieces kept: the hull of those pieces,
// or of the largest alone where that hull still reaches over a dropped
// footprint by min_piece_m2 (a piece dropped between two kept ones). The
// patch's parts over no footprint go: with footprints the assembly cuts at
// them anyway. Empty when no piece is kept.
Ring2 PatchOverPieces(const std::vector<Ring2>& kept, const std::vector<Ring2>& dropped,
                      const FootprintPieceOptions& options = {});

// Cuts the pieces the verification refuted (refuted[k] for pieces[k]) out
// of their planes: each such plane's patch becomes PatchOverPieces of its
// other pieces, its score that patch's area x its similarity (as the
// verification scores planes for the conflicts). A plane whose every piece
// is refuted stays whole: it was verified as a whole, and no footprint
// holds the evidence for it. Returns the indices of the pieces cut,
// ascending.
std::vector<int> CutRefutedPieces(const std::vector<FootprintPiece>& pieces,
                                  const std::vector<char>& refuted,
                                  const std::vector<Footprint>& footprints,
                                  std::vector<RoofPlaneHypothesis>* planes,
                                  const FootprintPieceOptions& options = {});

}  // namespace roofsweep
