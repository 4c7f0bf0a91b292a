#include "algorithms/edges/line_pieces.h"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <numeric>
#include <tuple>

namespace roofsweep {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BPoint = bg::model::point<double, 2, bg::cs::cartesian>;

constexpr double kPi = 3.14159265358979323846;

double Distance(const LineFit& f, const Eigen::Vector2d& q) {
  return std::fabs((q - f.centroid).dot(f.Normal()));
}

}  // namespace

Points2 PiecePositions(const std::vector<int>& ids, const EdgeMap& map) {
  Points2 out;
  out.reserve(ids.size());
  for (int id : ids) out.emplace_back(map.points[id].x, map.points[id].y);
  return out;
}

LinePiece MakePiece(std::vector<int> ids, const EdgeMap& map) {
  const LineFit fit = FitLine(PiecePositions(ids, map));
  return OrientPiece(std::move(ids), fit, map);
}

LinePiece OrientPiece(std::vector<int> ids, const LineFit& fit, const EdgeMap& map) {
  LinePiece piece;
  piece.fit = fit;
  double polarity = 0;
  const Eigen::Vector2d n = piece.fit.Normal();
  for (int id : ids) polarity += map.points[id].gx * n.x() + map.points[id].gy * n.y();
  if (polarity < 0) {
    piece.fit.direction = -piece.fit.direction;
    std::swap(piece.fit.t_min, piece.fit.t_max);
    piece.fit.t_min = -piece.fit.t_min;
    piece.fit.t_max = -piece.fit.t_max;
  }
  piece.points = std::move(ids);
  return piece;
}

std::vector<LinePiece> ChainsToPieces(const std::vector<std::vector<int>>& chains,
                                      const EdgeMap& map, const EdgeOptions& options) {
  std::vector<LinePiece> pieces;
  for (const auto& chain : chains) {
    if (static_cast<int>(chain.size()) < options.min_support) continue;
    const Points2 positions = PiecePositions(chain, map);
    for (const StraightRun& run : SplitIntoStraightPieces(positions, options)) {
      pieces.push_back(OrientPiece(
          std::vector<int>(chain.begin() + run.first, chain.begin() + run.last), run.fit, map));
    }
  }
  return pieces;
}

std::vector<LinePiece> MergeCollinearPieces(std::vector<LinePiece> pieces, const EdgeMap& map,
                                            const EdgeOptions& o) {
  const int n = static_cast<int>(pieces.size());
  if (n < 2) return pieces;
  const double cos_angle = std::cos(o.merge_max_angle * kPi / 180.0);

  // R-tree over both endpoints of every piece (value: point, 2 id + end).
  using Value = std::pair<BPoint, int>;
  std::vector<Value> ends;
  ends.reserve(2 * static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = pieces[i].fit.Start();
    const Eigen::Vector2d b = pieces[i].fit.End();
    ends.emplace_back(BPoint(a.x(), a.y()), 2 * i);
    ends.emplace_back(BPoint(b.x(), b.y()), 2 * i + 1);
  }
  const bgi::rtree<Value, bgi::quadratic<16>> tree(ends.begin(), ends.end());

  // Candidate pairs: an end of i near an end of j, oriented directions
  // close. Sorted by end distance, ties by ids, for determinism.
  std::vector<std::tuple<double, int, int>> pairs;
  std::vector<Value> found;
  const double r = o.merge_max_gap + o.merge_max_offset;
  for (const Value& e : ends) {
    const int i = e.second / 2;
    found.clear();
    const bg::model::box<BPoint> box(BPoint(bg::get<0>(e.first) - r, bg::get<1>(e.first) - r),
                                     BPoint(bg::get<0>(e.first) + r, bg::get<1>(e.first) + r));
    tree.query(bgi::intersects(box), std::back_inserter(found));
    for (const Value& f : found) {
      const int j = f.second / 2;
      if (j <= i) continue;
      if (pieces[i].fit.direction.dot(pieces[j].fit.direction) < cos_angle) continue;
      const double d = bg::distance(e.first, f.first);
      if (d <= r) pairs.emplace_back(d, i, j);
    }
  }
  std::sort(pairs.begin(), pairs.end());

  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& [dist, i0, j0] : pairs) {
    const int i = root(i0);
    const int j = root(j0);
    if (i == j) continue;
    const LineFit& a = pieces[i].fit;
    const LineFit& b = pieces[j].fit;
    if (a.direction.dot(b.direction) < cos_angle) continue;
    // Gap along a's line between the two extents (negative: overlap).
    const double b0 = (b.Start() - a.centroid).dot(a.direction);
    const double b1 = (b.End() - a.centroid).dot(a.direction);
    const double gap = std::max(std::min(b0, b1) - a.t_max, a.t_min - std::max(b0, b1));
    if (gap > o.merge_max_gap) continue;
    // Overlapping pieces are parallel duplicates or crossings, not gaps.
    if (gap < -o.merge_max_gap) continue;
    if (Distance(a, b.Start()) > o.merge_max_offset || Distance(a, b.End()) > o.merge_max_offset ||
        Distance(b, a.Start()) > o.merge_max_offset || Distance(b, a.End()) > o.merge_max_offset) {
      continue;
    }
    std::vector<int> ids = pieces[i].points;
    ids.insert(ids.end(), pieces[j].points.begin(), pieces[j].points.end());
    const Points2 positions = PiecePositions(ids, map);
    const LineFit fit = FitLine(positions);
    if (fit.max_deviation > o.fit_max_deviation ||
        IsCurved(positions, fit, o.fit_max_sagitta, o.fit_curve_min_explained)) {
      continue;
    }
    const int keep = std::min(i, j);
    const int drop = std::max(i, j);
    pieces[keep] = OrientPiece(std::move(ids), fit, map);
    pieces[drop].points.clear();
    parent[drop] = keep;
  }

  std::vector<LinePiece> out;
  for (auto& p : pieces) {
    if (!p.points.empty()) out.push_back(std::move(p));
  }
  return out;
}

}  // namespace roofsweep
