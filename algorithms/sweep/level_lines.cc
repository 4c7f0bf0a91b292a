#include "algorithms/sweep/level_lines.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/edges/segment_index.h"
#include "algorithms/geometry/view.h"

namespace roofsweep {
namespace {

constexpr double kDegToRad = M_PI / 180.0;
// A segment lies along another (a known line's projection, the same edge
// in another view of the strip) within this distance and angle: the views
// of a strip see one level edge on nearly the same image line at any
// height, its parallax running along it.
constexpr double kAlongPx = 3.0;
constexpr double kAlongDeg = 5.0;
// A known 3D line projects onto its own segments: tighter.
constexpr double kKnownPx = 2.0;

struct Candidate {
  int view = -1, id = -1;
  double ground = 0;  // z of the ground under it
  double length_m = 0;
};

// The segment's ray plane cut at z: its 3D line at that height.
std::optional<Segment3> LiftAt(const Block& block, int v, const Segment2D& s, double z) {
  const View& view = block.views[v];
  const Camera& cam = block.CameraOf(view);
  const auto a = IntersectHorizontalPlane(BackProject(cam, view.pose, s.p0), z);
  const auto b = IntersectHorizontalPlane(BackProject(cam, view.pose, s.p1), z);
  if (!a || !b) return std::nullopt;
  return Segment3{*a, *b};
}

double GroundUnder(const Block& block, const Eigen::Vector3d& p, double fallback) {
  const double g = block.ground.HeightAt(p.x(), p.y());
  return std::isfinite(g) ? g : fallback;
}

}  // namespace

std::vector<LevelLine> SweepLevelLines(const Block& block, const std::vector<ViewTexture>& textures,
                                       const std::vector<Segments2D>& segments,
                                       const std::vector<std::vector<bool>>& used,
                                       const std::vector<RoofPlaneHypothesis>& planes,
                                       const std::vector<Segment3>& known, double ground_fallback_z,
                                       double threshold, const SweepOptions& sweep,
                                       const LevelLineOptions& o, Progress& progress,
                                       LevelLineStats* stats) {
  if (stats) *stats = {};
  const int nv = static_cast<int>(block.views.size());
  if (static_cast<int>(segments.size()) != nv || static_cast<int>(used.size()) != nv) return {};
  if (!(o.coarse_step_m > 0) || !(o.fine_step_m > 0) || !(o.max_height_m > o.min_height_m) ||
      !(o.min_height_m >= 0))
    return {};
  const double mid_height = 0.5 * o.max_height_m;
  const double cos_along = std::cos(o.along_epipolar_deg * kDegToRad);

  std::vector<Ring2> grown(planes.size());
  for (size_t p = 0; p < planes.size(); ++p)
    if (planes[p].patch.size() >= 3) grown[p] = GrowConvex(planes[p].patch, o.plane_margin_m);
  // True when the segment's lift onto a plane lies on its grown patch.
  auto on_a_plane = [&](int v, const Segment2D& s) {
    if (o.plane_margin_m < 0) return false;
    const View& view = block.views[v];
    const Camera& cam = block.CameraOf(view);
    for (size_t p = 0; p < planes.size(); ++p) {
      if (grown[p].empty()) continue;
      const auto a = IntersectPlane(BackProject(cam, view.pose, s.p0), planes[p].plane, 0.25);
      const auto b = IntersectPlane(BackProject(cam, view.pose, s.p1), planes[p].plane, 0.25);
      if (!a || !b) continue;
      int inside = 0;
      for (double t : {0.0, 0.5, 1.0})
        inside += InsideConvex(grown[p], (*a + t * (*b - *a)).head<2>());
      if (inside >= 2) return true;
    }
    return false;
  };
  // Known 3D lines projected into each view: a segment along one is
  // explained whatever `used` says (a tile's windows renumber segments).
  std::vector<Segments2D> known_px(nv);
  for (int v = 0; v < nv; ++v) {
    const Camera& cam = block.CameraOf(block.views[v]);
    for (const Segment3& k : known) {
      const auto pa = Project(cam, block.views[v].pose, k.a);
      const auto pb = Project(cam, block.views[v].pose, k.b);
      if (!pa || !pb) continue;
      Segment2D q;
      q.p0 = *pa;
      q.p1 = *pb;
      if (q.Length() >= 1) known_px[v].push_back(q);
    }
  }
  std::vector<SegmentIndex> known_index;
  known_index.reserve(nv);
  for (int v = 0; v < nv; ++v) known_index.emplace_back(known_px[v]);
  auto explained = [&](int v, const Segment2D& s) {
    const Eigen::Vector2d d = s.Direction();
    const Eigen::Vector2d nrm(-d.y(), d.x());
    for (int id : known_index[v].Near(s, kKnownPx)) {
      const Segment2D& k = known_px[v][id];
      if (std::abs(k.Direction().dot(d)) < std::cos(kAlongDeg * kDegToRad)) continue;
      if (std::abs((k.p0 - s.p0).dot(nrm)) > kKnownPx ||
          std::abs((k.p1 - s.p0).dot(nrm)) > kKnownPx)
        continue;
      double u0 = (k.p0 - s.p0).dot(d), u1 = (k.p1 - s.p0).dot(d);
      if (u0 > u1) std::swap(u0, u1);
      if (std::min(u1, s.Length()) - std::max(u0, 0.0) >= 0.5 * s.Length()) return true;
    }
    return false;
  };
  // 1. The segments no view fixes.
  std::vector<Candidate> cands;
  std::map<std::pair<int, int>, int> index_of;
  for (int v = 0; v < nv; ++v) {
    const View& view = block.views[v];
    for (int id = 0; id < static_cast<int>(segments[v].size()); ++id) {
      const Segment2D& s = segments[v][id];
      if (used[v][id] || s.texture) continue;
      const auto rough = LiftAt(block, v, s, ground_fallback_z + mid_height);
      if (!rough) continue;
      const double g = GroundUnder(block, 0.5 * (rough->a + rough->b), ground_fallback_z);
      const auto lift = LiftAt(block, v, s, g + mid_height);
      if (!lift || lift->Length() < o.min_length_m) continue;
      const Eigen::Vector3d mid = 0.5 * (lift->a + lift->b);
      const auto m0 = Project(block.CameraOf(view), view.pose, mid);
      if (!m0) continue;
      int seen = 0;
      bool fixed = false;
      for (int w = 0; w < nv && !fixed; ++w) {
        if (w == v) continue;
        const Camera& cw = block.CameraOf(block.views[w]);
        const auto pa = Project(cw, block.views[w].pose, lift->a);
        const auto pb = Project(cw, block.views[w].pose, lift->b);
        if (!pa || !pb || !cw.Contains(*pa) || !cw.Contains(*pb)) continue;
        ++seen;
        const Eigen::Vector3d base = (block.views[w].pose.C - view.pose.C).normalized();
        const auto m1 = Project(block.CameraOf(view), view.pose, mid + base);
        if (!m1 || (*m1 - *m0).norm() < 1e-9) continue;
        if (std::abs((*m1 - *m0).normalized().dot(s.Direction())) < cos_along) fixed = true;
      }
      if (fixed || seen == 0 || on_a_plane(v, s) || explained(v, s)) continue;
      index_of[{v, id}] = static_cast<int>(cands.size());
      cands.push_back({v, id, g, lift->Length()});
    }
  }
  // 2. One segment per edge: the views of a strip see it along the same
  // image line, so the longest stands for the others.
  std::vector<int> order(cands.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](int x, int y) { return cands[x].length_m > cands[y].length_m; });
  std::vector<SegmentIndex> index;
  index.reserve(nv);
  for (int v = 0; v < nv; ++v) index.emplace_back(segments[v]);
  std::vector<char> covered(cands.size(), 0);
  std::vector<int> chosen;
  for (int c : order) {
    if (covered[c]) continue;
    if (static_cast<int>(chosen.size()) >= o.max_candidates) break;
    chosen.push_back(c);
    const Candidate& k = cands[c];
    const auto lift = LiftAt(block, k.view, segments[k.view][k.id], k.ground + mid_height);
    for (int w = 0; w < nv && lift; ++w) {
      if (w == k.view) continue;
      const Camera& cw = block.CameraOf(block.views[w]);
      const auto pa = Project(cw, block.views[w].pose, lift->a);
      const auto pb = Project(cw, block.views[w].pose, lift->b);
      if (!pa || !pb) continue;
      Segment2D q;
      q.p0 = *pa;
      q.p1 = *pb;
      if (q.Length() < 1) continue;
      const Eigen::Vector2d d = q.Direction();
      for (int id : index[w].Near(q, kAlongPx)) {
        const auto it = index_of.find({w, id});
        if (it == index_of.end()) continue;
        const Segment2D& s = segments[w][id];
        if (std::abs(s.Direction().dot(d)) < std::cos(kAlongDeg * kDegToRad)) continue;
        const Eigen::Vector2d n(-d.y(), d.x());
        if (std::abs((s.p0 - q.p0).dot(n)) > kAlongPx || std::abs((s.p1 - q.p0).dot(n)) > kAlongPx)
          continue;
        covered[it->second] = 1;
      }
    }
  }
  if (chosen.empty()) return {};

  // 3. Coarse heights from the ground up with a cheap sweep near the line,
  // then, for each side apart (an eave's other side is the ground), fine
  // heights around its best with the block's sweep.
  const int coarse = static_cast<int>(std::floor(o.max_height_m / o.coarse_step_m)) + 1;
  const int fine_n = 2 * o.fine_steps + 1;
  const int passes = coarse + 2 * fine_n;
  const size_t n = chosen.size();
  if (stats) {
    stats->candidates = static_cast<int>(std::count(covered.begin(), covered.end(), 0));
    stats->swept = static_cast<int>(n);
  }
  SweepOptions cheap = sweep;
  cheap.theta_min_deg = -o.coarse_theta_deg;
  cheap.theta_max_deg = o.coarse_theta_deg;
  cheap.coarse_step_deg = o.coarse_theta_step_deg;
  cheap.coarse_max_points = o.coarse_max_points;
  // Only the coarse profile is read: no points beyond the coarse subset,
  // and the refinement stops at once.
  cheap.max_points = o.coarse_max_points;
  cheap.refine_tolerance_deg = o.coarse_theta_step_deg;
  cheap.band_width_px = std::min(sweep.band_width_px, o.coarse_band_px);
  // The sides of each candidate with its line at z[i] (empty: not swept).
  auto sweep_at = [&](const std::vector<double>& z, const SweepOptions& so, int pass) {
    std::vector<SweepLine> lines;
    std::vector<size_t> which;
    for (size_t i = 0; i < n; ++i) {
      if (!std::isfinite(z[i])) continue;
      const Candidate& k = cands[chosen[i]];
      const auto lift = LiftAt(block, k.view, segments[k.view][k.id], z[i]);
      if (!lift) continue;
      lines.push_back({*lift, {k.view}, std::nan("")});
      which.push_back(i);
    }
    SubProgress sub(progress, static_cast<double>(pass) / passes,
                    static_cast<double>(pass + 1) / passes);
    const std::vector<HalfPlane> sides = SweepHalfPlanes(block, textures, lines, so, sub);
    return std::make_pair(sides, which);
  };
  // sim[i][side][k]: the best coarse Sim of side (0: +1, 1: -1).
  std::vector<std::array<std::vector<double>, 2>> sim(n);
  for (auto& s2 : sim) s2 = {std::vector<double>(coarse, 0.0), std::vector<double>(coarse, 0.0)};
  for (int c = 0; c < coarse; ++c) {
    std::vector<double> z(n);
    for (size_t i = 0; i < n; ++i) z[i] = cands[chosen[i]].ground + c * o.coarse_step_m;
    const auto [sides, which] = sweep_at(z, cheap, c);
    for (size_t j = 0; j < which.size(); ++j)
      for (int side = 0; side < 2 && 2 * j + side < sides.size(); ++side) {
        const auto& p = sides[2 * j + side].profile;
        sim[which[j]][side][c] = p.empty() ? 0.0 : *std::max_element(p.begin(), p.end());
      }
  }
  // Each side's coarse best, when it stands out.
  std::vector<std::array<int, 2>> best(n, {-1, -1});
  std::vector<std::array<double, 2>> ratio(n, {0.0, 0.0});
  for (size_t i = 0; i < n; ++i)
    for (int side = 0; side < 2; ++side) {
      const std::vector<double>& p = sim[i][side];
      const auto top = std::max_element(p.begin(), p.end());
      const int k = static_cast<int>(top - p.begin());
      if (*top <= 0 || k == coarse - 1 ||
          k * o.coarse_step_m < o.min_height_m - 0.5 * o.coarse_step_m)
        continue;
      std::vector<double> sorted = p;
      std::nth_element(sorted.begin(), sorted.begin() + coarse / 2, sorted.end());
      const double median = sorted[coarse / 2];
      ratio[i][side] = median > 0 ? *top / median : 1e9;
      if (ratio[i][side] < o.min_height_ratio) continue;
      best[i][side] = k;
    }
  if (stats)
    for (size_t i = 0; i < n; ++i) stats->peaked += best[i][0] >= 0 || best[i][1] >= 0;
  // Fine: each side at offsets -fine_steps..fine_steps from its coarse best.
  std::vector<std::array<std::vector<double>, 2>> fine(n);
  // Each side's half-plane at its first best offset so far: the one the
  // refinement below starts from.
  std::vector<std::array<HalfPlane, 2>> fine_top(n);
  for (auto& f2 : fine) f2 = {std::vector<double>(fine_n, 0.0), std::vector<double>(fine_n, 0.0)};
  int pass = coarse;
  for (int side = 0; side < 2; ++side)
    for (int j = 0; j < fine_n; ++j) {
      std::vector<double> z(n, std::nan(""));
      for (size_t i = 0; i < n; ++i)
        if (best[i][side] >= 0)
          z[i] = cands[chosen[i]].ground + best[i][side] * o.coarse_step_m +
                 (j - o.fine_steps) * o.fine_step_m;
      const auto [sides, which] = sweep_at(z, sweep, pass++);
      for (size_t w = 0; w < which.size(); ++w) {
        const HalfPlane& h = sides[2 * w + side];
        // Nothing but the face places a level line: most of the points
        // beside it must correlate there (the sweep drops at most half as
        // outsiders, so a weak or broken face keeps half).
        const bool face = h.candidate_shape && h.points >= o.min_face_fraction * h.points_detected;
        std::vector<double>& f = fine[which[w]][side];
        f[j] = face ? h.similarity : 0.0;
        if (j == 0 || f[j] > *std::max_element(f.begin(), f.begin() + j))
          fine_top[which[w]][side] = h;
      }
    }
  std::vector<double> best_h(n, std::nan("")), best_sim(n, 0.0), best_ratio(n, 0.0);
  std::vector<HalfPlane> best_side(n);
  for (size_t i = 0; i < n; ++i)
    for (int side = 0; side < 2; ++side) {
      if (best[i][side] < 0) continue;
      const std::vector<double>& f = fine[i][side];
      const auto top = std::max_element(f.begin(), f.end());
      const int j = static_cast<int>(top - f.begin());
      if (*top <= best_sim[i]) continue;
      double t = j;
      // Parabolic refinement, as the sweep refines theta.
      if (j > 0 && j + 1 < fine_n) {
        const double den = f[j - 1] - 2 * f[j] + f[j + 1];
        if (den < 0) t += std::clamp(0.5 * (f[j - 1] - f[j + 1]) / den, -0.5, 0.5);
      }
      const double h = best[i][side] * o.coarse_step_m + (t - o.fine_steps) * o.fine_step_m;
      if (h < o.min_height_m) continue;
      best_sim[i] = *top;
      best_h[i] = h;
      best_ratio[i] = ratio[i][side];
      best_side[i] = fine_top[i][side];
    }

  std::vector<LevelLine> out;
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(best_h[i]) || best_sim[i] < threshold) continue;
    const Candidate& k = cands[chosen[i]];
    const auto lift = LiftAt(block, k.view, segments[k.view][k.id], k.ground + best_h[i]);
    if (!lift) continue;
    out.push_back({*lift, k.view, k.id, best_h[i], best_sim[i], best_ratio[i], best_side[i]});
  }
  return out;
}

}  // namespace roofsweep
