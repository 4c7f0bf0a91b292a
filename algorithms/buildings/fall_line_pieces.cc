#include "algorithms/buildings/fall_line_pieces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "algorithms/buildings/convex_polygon2.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

}  // namespace

std::vector<FallLinePiece> PiecesAcrossFallLines(const std::vector<RoofPlaneHypothesis>& planes,
                                                 const FallLinePieceOptions& o) {
  const double cos_max = std::cos(o.max_angle_deg * kDeg);
  std::vector<FallLinePiece> out;
  for (size_t i = 0; i < planes.size(); ++i) {
    const RoofPlaneHypothesis& p = planes[i];
    const Eigen::Vector2d g = p.plane.head<2>();
    // |n_xy| = sin(slope) for a unit normal.
    if (p.patch.size() < 3 || g.norm() < std::sin(o.min_slope_deg * kDeg)) continue;
    const Eigen::Vector2d fall = g.normalized(), across(-fall.y(), fall.x());
    const auto [a_lo, a_hi] = ConvexExtent(p.patch, across);
    std::vector<double> at;
    for (const auto& l : p.lines_xy) {
      const Eigen::Vector2d d = l[1] - l[0];
      const double len = d.norm();
      if (len < 1e-6 || std::abs(d.dot(fall)) < cos_max * len) continue;
      const double s = across.dot(0.5 * (l[0] + l[1]));
      if (s - a_lo < o.min_width_m || a_hi - s < o.min_width_m) continue;
      const auto [c_lo, c_hi] = ConvexChord(p.patch, across, fall, s);
      if (!(c_hi - c_lo >= o.min_depth_m) || std::abs(d.dot(fall)) < o.min_span * (c_hi - c_lo))
        continue;
      at.push_back(s);
    }
    if (at.empty()) continue;
    std::sort(at.begin(), at.end());
    std::vector<double> bounds{a_lo};
    for (double s : at)
      if (s - bounds.back() >= o.min_width_m) bounds.push_back(s);
    bounds.push_back(a_hi);
    const size_t n = bounds.size() - 1;
    if (n < 2) continue;
    for (size_t k = 0; k < n; ++k) {
      FallLinePiece piece;
      piece.plane = static_cast<int>(i);
      piece.order = static_cast<int>(k);
      piece.piece = p;
      piece.piece.id = p.id + " piece " + std::to_string(k + 1) + " of " + std::to_string(n);
      piece.piece.patch = ConvexSlab(p.patch, across, bounds[k], bounds[k + 1]);
      piece.piece.lines_xy.clear();
      for (const auto& l : p.lines_xy)
        if (InsideConvex(piece.piece.patch, 0.5 * (l[0] + l[1]))) piece.piece.lines_xy.push_back(l);
      piece.piece.lines = static_cast<int>(piece.piece.lines_xy.size());
      piece.piece.colour_breaks.clear();
      out.push_back(std::move(piece));
    }
  }
  return out;
}

std::vector<int> CutRefutedFallLinePieces(const std::vector<FallLinePiece>& pieces,
                                          const std::vector<char>& refuted,
                                          std::vector<RoofPlaneHypothesis>* planes) {
  // Per plane: its pieces by order.
  std::map<int, std::vector<size_t>> of_plane;
  for (size_t k = 0; k < pieces.size(); ++k) of_plane[pieces[k].plane].push_back(k);
  std::vector<int> cut;
  for (auto& [plane, ks] : of_plane) {
    std::sort(ks.begin(), ks.end(),
              [&](size_t a, size_t b) { return pieces[a].order < pieces[b].order; });
    // Runs of consecutive pieces kept, as hulls.
    std::vector<Ring2> runs;
    std::vector<size_t> dropped;
    std::vector<Eigen::Vector2d> run;
    for (size_t k : ks) {
      if (refuted[k]) {
        dropped.push_back(k);
        if (!run.empty()) runs.push_back(ConvexHull(std::move(run)));
        run.clear();
      } else {
        run.insert(run.end(), pieces[k].piece.patch.begin(), pieces[k].piece.patch.end());
      }
    }
    if (!run.empty()) runs.push_back(ConvexHull(std::move(run)));
    if (dropped.empty() || runs.empty()) continue;
    for (size_t k : dropped) cut.push_back(static_cast<int>(k));
    size_t largest = 0;
    for (size_t r = 1; r < runs.size(); ++r)
      if (SignedArea(runs[r]) > SignedArea(runs[largest])) largest = r;
    RoofPlaneHypothesis whole = (*planes)[plane];
    int part = 1;
    for (size_t r = 0; r < runs.size(); ++r) {
      RoofPlaneHypothesis q = whole;
      q.patch = runs[r];
      // Its weight in the conflicts, patch area x similarity, shrinks with it.
      q.score = std::abs(SignedArea(q.patch)) * q.similarity;
      if (r == largest) {
        (*planes)[plane] = std::move(q);
      } else {
        q.id += " part " + std::to_string(++part);
        planes->push_back(std::move(q));
      }
    }
  }
  std::sort(cut.begin(), cut.end());
  return cut;
}

}  // namespace roofsweep
