#include "algorithms/eval/match_eval.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "algorithms/edges/segment_geometry.h"

namespace roofsweep::eval {
namespace {

// The annotated line a detected segment images, or -1.
int Label(const Segment2D& s, const Segments2D& annotated, const MatchEvalOptions& o) {
  int best = -1;
  double best_overlap = 0;
  for (size_t a = 0; a < annotated.size(); ++a) {
    const Segment2D& r = annotated[a];
    const double on_r = CoveredFraction(s, r, o.max_distance_px, o.max_angle_deg);
    const double on_s = CoveredFraction(r, s, o.max_distance_px, o.max_angle_deg);
    const bool s_shorter = s.Length() <= r.Length();
    if ((s_shorter ? on_r : on_s) < o.min_cover) continue;
    const double overlap = on_r * s.Length();
    if (overlap > best_overlap) {
      best_overlap = overlap;
      best = static_cast<int>(a);
    }
  }
  return best;
}

// Whether the annotated 3D lines of rows r and q project onto each other in
// view v: each one's projected endpoints within `tolerance` px of the other's
// projected (infinite) line.
bool RowsCoincideInView(const LineTracks& truth, int r, int q, int v, double tolerance) {
  const int n = static_cast<int>(truth.lines3d.size());
  if (!truth.project || r >= n || q >= n) return false;
  Eigen::Vector2d p[2][2];
  for (int k = 0; k < 2; ++k) {
    const Segment3& l = truth.lines3d[k == 0 ? r : q];
    const auto a = truth.project(v, l.a), b = truth.project(v, l.b);
    if (!a || !b || !((*b - *a).norm() > 1e-9)) return false;
    p[k][0] = *a;
    p[k][1] = *b;
  }
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector2d& a = p[1 - k][0];
    const Eigen::Vector2d d = (p[1 - k][1] - a).normalized();
    for (const Eigen::Vector2d& x : p[k]) {
      const Eigen::Vector2d w = x - a;
      if (std::abs(w.x() * d.y() - w.y() * d.x()) > tolerance) return false;
    }
  }
  return true;
}

double DistanceToLine(const Eigen::Vector3d& p, const Segment3& l) {
  const Eigen::Vector3d d = (l.b - l.a).normalized();
  const Eigen::Vector3d w = p - l.a;
  return (w - w.dot(d) * d).norm();
}

}  // namespace

MatchScores EvaluateMatches(const std::vector<Segments2D>& detected,
                            const std::vector<std::vector<std::pair<int, int>>>& observations,
                            const std::vector<Segment3>& result_lines, const LineTracks& truth,
                            const MatchEvalOptions& o) {
  MatchScores out;
  const int nv = static_cast<int>(std::min(detected.size(), truth.lines.size()));
  // (view, annotated id) -> rows.
  std::map<std::pair<int, int>, std::vector<int>> rows_of;
  for (size_t r = 0; r < truth.rows.size(); ++r)
    for (int v = 0; v < static_cast<int>(truth.rows[r].size()) && v < nv; ++v)
      if (truth.rows[r][v] >= 0) rows_of[{v, truth.rows[r][v]}].push_back(static_cast<int>(r));
  auto marked_in = [&](int v, int id, int other) {
    auto it = rows_of.find({v, id});
    if (it == rows_of.end()) return false;
    for (int r : it->second)
      if (other < static_cast<int>(truth.rows[r].size()) && truth.rows[r][other] >= 0) return true;
    return false;
  };
  auto common_row = [&](int va, int ia, int vb, int ib) {
    auto it = rows_of.find({va, ia});
    if (it == rows_of.end()) return -1;
    for (int r : it->second)
      if (vb < static_cast<int>(truth.rows[r].size()) && truth.rows[r][vb] == ib) return r;
    return -1;
  };

  std::map<std::pair<int, int>, int> label;
  auto label_of = [&](int v, int s) {
    auto it = label.find({v, s});
    if (it != label.end()) return it->second;
    const int l = v < nv && s >= 0 && s < static_cast<int>(detected[v].size())
                      ? Label(detected[v][s], truth.lines[v], o)
                      : -1;
    label[{v, s}] = l;
    return l;
  };

  std::set<std::tuple<int, int, int>> found;  // (row, view a, view b), a < b
  std::vector<double> distances;
  for (size_t n = 0; n < observations.size(); ++n) {
    const auto& obs = observations[n];
    bool any = false, all = true;
    std::map<int, int> row_votes;
    for (size_t a = 0; a < obs.size(); ++a)
      for (size_t b = a + 1; b < obs.size(); ++b) {
        const auto [va, sa] = obs[a];
        const auto [vb, sb] = obs[b];
        if (va == vb) continue;
        const int la = label_of(va, sa), lb = label_of(vb, sb);
        if (la < 0 || lb < 0) continue;
        if (!marked_in(va, la, vb) && !marked_in(vb, lb, va)) continue;
        ++out.pairs_evaluable;
        any = true;
        const int r = common_row(va, la, vb, lb);
        if (r < 0) {
          int pieces_of = -1;
          for (int ra : rows_of.count({va, la}) ? rows_of.at({va, la}) : std::vector<int>{})
            for (int rb : rows_of.count({vb, lb}) ? rows_of.at({vb, lb}) : std::vector<int>{})
              if (pieces_of < 0 && RowsCoincideInView(truth, ra, rb, va, o.max_distance_px) &&
                  RowsCoincideInView(truth, ra, rb, vb, o.max_distance_px))
                pieces_of = ra;
          if (pieces_of < 0) {
            all = false;
            continue;
          }
          ++out.pairs_collinear_rows;
          ++out.pairs_correct;
          ++row_votes[pieces_of];
          continue;
        }
        ++out.pairs_correct;
        ++row_votes[r];
        found.insert({r, std::min(va, vb), std::max(va, vb)});
      }
    if (!any) continue;
    ++out.lines_evaluable;
    if (!all) continue;
    ++out.lines_correct;
    if (n < result_lines.size() && !row_votes.empty()) {
      const int r = std::max_element(row_votes.begin(), row_votes.end(), [](auto& x, auto& y) {
                      return x.second < y.second;
                    })->first;
      if (r < static_cast<int>(truth.lines3d.size()) &&
          (truth.lines3d[r].b - truth.lines3d[r].a).norm() > 0)
        distances.push_back(std::max(DistanceToLine(result_lines[n].a, truth.lines3d[r]),
                                     DistanceToLine(result_lines[n].b, truth.lines3d[r])));
    }
  }

  std::set<int> rows_found;
  for (const auto& [r, a, b] : found) rows_found.insert(r);
  for (size_t r = 0; r < truth.rows.size(); ++r) {
    int marked = 0;
    for (int v = 0; v < static_cast<int>(truth.rows[r].size()) && v < nv; ++v)
      marked += truth.rows[r][v] >= 0;
    if (marked < 2) continue;
    ++out.annotated_lines;
    out.annotated_pairs += marked * (marked - 1) / 2;
  }
  out.annotated_pairs_found = static_cast<long long>(found.size());
  out.annotated_lines_found = static_cast<int>(rows_found.size());

  if (!truth.lines3d.empty()) {
    Eigen::Vector3d lo = truth.lines3d[0].a, hi = lo;
    for (const Segment3& l : truth.lines3d)
      for (const Eigen::Vector3d& p : {l.a, l.b}) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    out.scene_size = (hi - lo).norm();
  }
  out.lines_3d = static_cast<int>(distances.size());
  if (!distances.empty()) {
    std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
    out.median_distance_3d = distances[distances.size() / 2];
  }
  return out;
}

}  // namespace roofsweep::eval
