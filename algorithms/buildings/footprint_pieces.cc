#include "algorithms/buildings/footprint_pieces.h"

#include <cmath>
#include <map>
#include <set>
#include <string>

#include "algorithms/buildings/polygon2.h"

namespace roofsweep {

std::vector<FootprintPiece> PiecesOverFootprints(const std::vector<RoofPlaneHypothesis>& planes,
                                                 const std::vector<Footprint>& footprints,
                                                 const FootprintPieceOptions& o) {
  std::vector<Eigen::Vector4d> bounds;
  for (const Footprint& f : footprints) bounds.push_back(RingBounds(f.outline));
  std::vector<FootprintPiece> out;
  for (size_t i = 0; i < planes.size(); ++i) {
    const RoofPlaneHypothesis& p = planes[i];
    if (p.patch.size() < 3) continue;
    const Eigen::Vector4d pb = RingBounds(p.patch);
    std::vector<FootprintPiece> pieces;
    std::set<std::string> ids;
    for (size_t f = 0; f < footprints.size(); ++f) {
      if (!BoundsMeet(pb, bounds[f])) continue;
      Ring2 part = LargestIntersection(p.patch, footprints[f].outline);
      if (part.size() < 3 || SignedArea(part) < o.min_piece_m2) continue;
      part = ConvexHull(std::move(part));
      FootprintPiece piece;
      piece.plane = static_cast<int>(i);
      piece.footprint = static_cast<int>(f);
      piece.piece = p;
      piece.piece.id = p.id + " over footprint " + footprints[f].id;
      piece.piece.lines_xy.clear();
      for (const auto& l : p.lines_xy)
        if (InsideConvex(part, 0.5 * (l[0] + l[1]))) piece.piece.lines_xy.push_back(l);
      piece.piece.lines = static_cast<int>(piece.piece.lines_xy.size());
      piece.piece.colour_breaks.clear();
      piece.piece.patch = std::move(part);
      ids.insert(footprints[f].id);
      pieces.push_back(std::move(piece));
    }
    // Over the pieces of one footprint id (a multipolygon's rectangles) the
    // plane is one building's face; it is weighed piece by piece only where
    // it spans buildings.
    if (ids.size() < 2) continue;
    for (FootprintPiece& q : pieces) out.push_back(std::move(q));
  }
  return out;
}

Ring2 PatchOverPieces(const std::vector<Ring2>& kept, const std::vector<Ring2>& dropped,
                      const FootprintPieceOptions& o) {
  if (kept.empty()) return {};
  std::vector<Eigen::Vector2d> points;
  for (const Ring2& k : kept) points.insert(points.end(), k.begin(), k.end());
  Ring2 hull = ConvexHull(std::move(points));
  for (const Ring2& d : dropped)
    if (IntersectionArea(hull, d) >= o.min_piece_m2) return LargestRing(kept);
  return hull;
}

std::vector<int> CutRefutedPieces(const std::vector<FootprintPiece>& pieces,
                                  const std::vector<char>& refuted,
                                  const std::vector<Footprint>& footprints,
                                  std::vector<RoofPlaneHypothesis>* planes,
                                  const FootprintPieceOptions& o) {
  // Per plane: its pieces kept and the outlines of those refuted.
  std::map<int, std::pair<std::vector<Ring2>, std::vector<Ring2>>> of_plane;
  for (size_t k = 0; k < pieces.size(); ++k) {
    auto& [kept, dropped] = of_plane[pieces[k].plane];
    if (refuted[k])
      dropped.push_back(footprints[pieces[k].footprint].outline);
    else
      kept.push_back(pieces[k].piece.patch);
  }
  std::vector<int> cut;
  for (size_t k = 0; k < pieces.size(); ++k) {
    const auto& [kept, dropped] = of_plane[pieces[k].plane];
    if (refuted[k] && !kept.empty()) cut.push_back(static_cast<int>(k));
  }
  for (const auto& [plane, sides] : of_plane) {
    if (sides.first.empty() || sides.second.empty()) continue;
    RoofPlaneHypothesis& p = (*planes)[plane];
    p.patch = PatchOverPieces(sides.first, sides.second, o);
    // Its weight in later conflicts, patch area x similarity, shrinks with it.
    p.score = std::abs(SignedArea(p.patch)) * p.similarity;
  }
  return cut;
}

}  // namespace roofsweep
