#include "algorithms/matching/end_check.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <utility>

#include "algorithms/matching/epipolar.h"
#include "algorithms/matching/line_triangulation.h"
#include "algorithms/matching/view_support.h"

namespace roofsweep {
namespace {

// Whether the pair (a, b) sees the line at min_epipolar_angle or more from
// its epipolar lines in both views, as the candidate stage asks of a pair.
bool SeesAcrossEpipolarLines(const ViewFeatures& a, const ViewFeatures& b, const Segment3& line,
                             const MatchOptions& o) {
  auto angle = [&](const ViewFeatures& v, const ViewFeatures& other) {
    Segment2D s;
    s.p0 = (v.P * line.a.homogeneous()).hnormalized();
    s.p1 = (v.P * line.b.homogeneous()).hnormalized();
    return EpipolarAngle(v.P * other.pose.C.homogeneous(), s);
  };
  return angle(a, b) >= o.min_epipolar_angle && angle(b, a) >= o.min_epipolar_angle;
}

}  // namespace

double CutUnconfirmedEnds(const std::vector<ViewFeatures>& views, const MatchOptions& o,
                          Line3D* line) {
  const Segment3 seg = line->segment;
  const double length = seg.Length();
  if (!(length > 0)) return 0;
  std::vector<LineObservation> obs;
  for (const auto& [v, s] : line->observations)
    obs.push_back({views[v].P, views[v].ideal[s].p0, views[v].ideal[s].p1});
  const std::vector<std::pair<double, double>> spans = ObservationSpans(obs, seg);
  // Per view, the hull of its observations (fragments of one edge).
  std::map<int, std::pair<double, double>> hull;
  for (size_t k = 0; k < spans.size(); ++k) {
    if (!std::isfinite(spans[k].first)) continue;
    const int v = line->observations[k].first;
    auto [it, fresh] = hull.emplace(v, spans[k]);
    if (!fresh) {
      it->second.first = std::min(it->second.first, spans[k].first);
      it->second.second = std::max(it->second.second, spans[k].second);
    }
  }
  if (hull.size() < 2) return 0;
  // The part whose depth stereo fixes: where two views hold it that see the
  // line at min_epipolar_angle or more from their epipolar lines. Two views
  // of one strip do not fix a line along the flight direction. They see a
  // ridge and whatever lies in line with it beyond the gable at any depth
  // as one image edge, and used to carry the ridge 10 m on into the air
  // (matching README, "Ends held only along the epipolar lines").
  double c0 = NAN, c1 = NAN;
  for (auto i = hull.begin(); i != hull.end(); ++i)
    for (auto j = std::next(i); j != hull.end(); ++j) {
      const double t0 = std::max(i->second.first, j->second.first);
      const double t1 = std::min(i->second.second, j->second.second);
      if (!(t1 > t0) || !SeesAcrossEpipolarLines(views[i->first], views[j->first], seg, o))
        continue;
      c0 = std::isfinite(c0) ? std::min(c0, t0) : t0;
      c1 = std::isfinite(c1) ? std::max(c1, t1) : t1;
    }
  if (!std::isfinite(c0)) {
    // No such pair overlaps (the refined line turned towards a baseline):
    // fall back to the part any two views hold.
    std::vector<std::pair<double, int>> events;
    for (const auto& [v, h] : hull) {
      events.emplace_back(h.first, +1);
      events.emplace_back(h.second, -1);
    }
    std::sort(events.begin(), events.end());
    int count = 0;
    for (const auto& [t, step] : events) {
      const int before = count;
      count += step;
      if (before < 2 && count >= 2 && !std::isfinite(c0)) c0 = t;
      if (before >= 2 && count < 2) c1 = t;
    }
  }
  if (!std::isfinite(c0) || !std::isfinite(c1) || c1 <= c0) return 0;
  c0 = std::max(c0, 0.0);
  c1 = std::min(c1, length);
  const Eigen::Vector3d dir = seg.Direction();
  auto confirmed = [&](double t0, double t1) {
    std::vector<int> holding;
    for (const auto& [v, h] : hull)
      if (h.first < t1 && h.second > t0) holding.push_back(v);
    const Segment3 end{seg.a + t0 * dir, seg.a + t1 * dir};
    return SupportInViews(views, end, holding, o).Accepted(o);
  };
  double lo = 0, hi = length;
  if (c0 > 0 && !confirmed(0, c0)) lo = c0;
  if (c1 < length && !confirmed(c1, length)) hi = c1;
  if (lo == 0 && hi == length) return 0;
  line->segment = Segment3{seg.a + lo * dir, seg.a + hi * dir};
  return length - (hi - lo);
}

}  // namespace roofsweep
