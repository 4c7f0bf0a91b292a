#include "algorithms/eval/evaluate.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <set>
#include <unordered_map>

#include "algorithms/core/error.h"
#include "algorithms/eval/roof_height_grid.h"

namespace roofsweep {
namespace {

using eval::Box2;
using eval::MultiPolygon2;

struct Region {
  const MultiPolygon2* plan = nullptr;
  Box2 box;
  double area = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

struct Overlap {
  int res = -1, ref = -1;
  double area = 0;       // m² in plan
  double angle_deg = 0;  // between upward normals
};

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(std::abs(a.dot(b)), 0.0, 1.0)) * 180.0 / M_PI;
}

std::optional<double> Ratio(double num, double den) {
  if (den <= 0) return std::nullopt;
  return num / den;
}

// All pairs with a positive plan overlap. Reference boxes are bucketed on a
// coarse grid so that city-sized models do not cost N_res x N_ref clippings.
std::vector<Overlap> Overlaps(const std::vector<Region>& res, const std::vector<Region>& ref) {
  constexpr double kCell = 32.0;
  auto cell = [](double v) { return static_cast<long long>(std::floor(v / kCell)); };
  auto key = [](long long x, long long y) { return x * 73856093LL ^ y * 19349663LL; };
  std::unordered_map<long long, std::vector<int>> grid;
  for (int j = 0; j < static_cast<int>(ref.size()); ++j) {
    const Box2& b = ref[j].box;
    if (b.Empty()) continue;
    for (long long x = cell(b.min.x()); x <= cell(b.max.x()); ++x)
      for (long long y = cell(b.min.y()); y <= cell(b.max.y()); ++y) grid[key(x, y)].push_back(j);
  }
  std::vector<Overlap> out;
  for (int i = 0; i < static_cast<int>(res.size()); ++i) {
    const Box2& b = res[i].box;
    if (b.Empty()) continue;
    std::set<int> cands;  // ordered: deterministic output
    for (long long x = cell(b.min.x()); x <= cell(b.max.x()); ++x)
      for (long long y = cell(b.min.y()); y <= cell(b.max.y()); ++y) {
        const auto it = grid.find(key(x, y));
        if (it != grid.end()) cands.insert(it->second.begin(), it->second.end());
      }
    for (int j : cands) {
      if (!b.Intersects(ref[j].box)) continue;
      const double a = eval::IntersectionArea(*res[i].plan, *ref[j].plan);
      if (a <= 0) continue;
      out.push_back({i, j, a, AngleDeg(res[i].normal, ref[j].normal)});
    }
  }
  return out;
}

// The one-counterpart rule of the header, for one side. `pick` gives the
// judged region's index in an overlap, `other` the counterpart's. Among
// several counterparts the one of largest intersection over union is taken,
// so that a plane (or footprint) nested in a larger one of the other model
// does not steal the match from its true twin.
struct SideMatch {
  std::vector<int> best;          // qualifying counterpart of largest IoU, else -1
  std::vector<int> any_best;      // counterpart of largest IoU regardless of the rule
  std::vector<double> best_area;  // overlap with `best`
  std::vector<double> any_area;   // overlap with `any_best`
  // For UnmatchedKind: the largest single overlap, all overlaps summed, and
  // those at the judged region's slope (normals within the angle) summed.
  std::vector<double> largest_area, summed_area, summed_level_area;
  int tp = 0;
};

template <typename Pick, typename Other>
SideMatch MatchSide(const std::vector<Region>& regions, const std::vector<Region>& others,
                    const std::vector<Overlap>& overlaps, double fraction, double max_angle_deg,
                    Pick pick, Other other) {
  SideMatch m;
  const size_t n = regions.size();
  m.best.assign(n, -1);
  m.any_best.assign(n, -1);
  m.best_area.assign(n, 0);
  m.any_area.assign(n, 0);
  m.largest_area.assign(n, 0);
  m.summed_area.assign(n, 0);
  m.summed_level_area.assign(n, 0);
  std::vector<double> best_iou(n, -1), any_iou(n, -1);
  for (const Overlap& o : overlaps) {
    const int i = pick(o), j = other(o);
    m.largest_area[i] = std::max(m.largest_area[i], o.area);
    m.summed_area[i] += o.area;
    if (o.angle_deg <= max_angle_deg) m.summed_level_area[i] += o.area;
    const double iou = o.area / std::max(regions[i].area + others[j].area - o.area, 1e-12);
    if (iou > any_iou[i]) {
      any_iou[i] = iou;
      m.any_area[i] = o.area;
      m.any_best[i] = j;
    }
    if (o.area >= fraction * regions[i].area && o.angle_deg <= max_angle_deg && iou > best_iou[i]) {
      best_iou[i] = iou;
      m.best_area[i] = o.area;
      m.best[i] = j;
    }
  }
  for (size_t i = 0; i < n; ++i)
    if (m.best[i] >= 0) ++m.tp;
  return m;
}

double PointSegmentDistance2D(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                              const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double l2 = d.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

template <typename F>
void ForEachRing(const MultiPolygon2& m, F f) {
  for (const auto& p : m) {
    f(p.outer);
    for (const auto& h : p.holes) f(h);
  }
}

double DistanceToOutline(const Eigen::Vector2d& p, const MultiPolygon2& m) {
  double best = std::numeric_limits<double>::infinity();
  ForEachRing(m, [&](const eval::Ring2& r) {
    for (size_t i = 0; i < r.size(); ++i)
      best = std::min(best, PointSegmentDistance2D(p, r[i], r[(i + 1) % r.size()]));
  });
  return best;
}

void CheckOptions(const EvalOptions& o) {
  auto fraction = [](double v, const char* name) {
    if (!(v > 0 && v <= 1))
      throw Error(std::string("evaluation option ") + name + " must be in (0, 1]");
  };
  fraction(o.plane_overlap_fraction, "plane_overlap_fraction");
  fraction(o.segmentation_overlap_fraction, "segmentation_overlap_fraction");
  fraction(o.building_overlap_fraction, "building_overlap_fraction");
  if (!(o.max_normal_angle_deg >= 0 && o.max_normal_angle_deg <= 90))
    throw Error("evaluation option max_normal_angle_deg must be in [0, 90]");
  if (!(o.rmsz_grid_m > 0)) throw Error("evaluation option rmsz_grid_m must be positive");
  if (!(o.building_top_tolerance_m >= 0))
    throw Error("evaluation option building_top_tolerance_m must be >= 0");
  if (!(o.gsd_m >= 0)) throw Error("evaluation option gsd_m must be >= 0");
  if (!(o.large_plane_m2 >= 0) || !std::isfinite(o.large_plane_m2))
    throw Error("evaluation option large_plane_m2 must be >= 0");
  if (!(o.vertex_max_distance_m > 0))
    throw Error("evaluation option vertex_max_distance_m must be positive");
  if (!(o.vertex_on_outline_m >= 0))
    throw Error("evaluation option vertex_on_outline_m must be >= 0");
  if (!(o.planes.vertical_roof_deg > 0 && o.planes.vertical_roof_deg <= 90))
    throw Error("evaluation option vertical_roof_deg must be in (0, 90]");
}

InputCounts Counts(const eval::RoofPlaneSet& s) {
  return {s.roof_polygons, s.vertical_polygons, s.degenerate_polygons, s.invalid_polygons,
          s.downward_polygons};
}

std::vector<Region> Regions(const eval::RoofPlaneSet& s) {
  std::vector<Region> out;
  for (const auto& p : s.planes) out.push_back({&p.plan, p.box, p.plan_area, p.normal});
  return out;
}

std::vector<PlaneRecord> Records(const eval::RoofPlaneSet& s, const CityModel& model,
                                 const SideMatch& m, const std::vector<Region>& other,
                                 double fraction) {
  std::vector<PlaneRecord> out;
  for (size_t i = 0; i < s.planes.size(); ++i) {
    const auto& p = s.planes[i];
    PlaneRecord r;
    r.building = p.building;
    r.building_id = model.buildings[p.building].id;
    r.plan_area = p.plan_area;
    r.normal = p.normal;
    r.true_positive = m.best[i] >= 0;
    r.counterpart = r.true_positive ? m.best[i] : m.any_best[i];
    if (r.counterpart >= 0) {
      r.angle_deg = AngleDeg(p.normal, other[r.counterpart].normal);
      r.overlap_fraction =
          (r.true_positive ? m.best_area[i] : m.any_area[i]) / std::max(p.plan_area, 1e-12);
    }
    if (!r.true_positive) {
      // Overlaps are summed, so planes of the other model stacked in plan
      // (a dormer over its roof) could count twice: capped at the whole.
      const double covered = std::min(m.summed_area[i], p.plan_area);
      const double level = std::min(m.summed_level_area[i], p.plan_area);
      r.unmatched = covered < fraction * p.plan_area              ? UnmatchedKind::kUncovered
                    : m.largest_area[i] >= fraction * p.plan_area ? UnmatchedKind::kOtherSlope
                    : level >= fraction * p.plan_area ? UnmatchedKind::kSeveralAtItsSlope
                                                      : UnmatchedKind::kSeveral;
    }
    out.push_back(r);
  }
  return out;
}

void ScoreSegmentation(const std::vector<Region>& res, const std::vector<Region>& ref,
                       const std::vector<Overlap>& overlaps, double fraction, RoofPlaneScores* s) {
  const int nr = static_cast<int>(res.size()), nt = static_cast<int>(ref.size());
  std::vector<int> deg_res(nr, 0), deg_ref(nt, 0), parent(nr + nt);
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> find = [&](int i) {
    return parent[i] == i ? i : parent[i] = find(parent[i]);
  };
  for (const Overlap& o : overlaps) {
    if (o.area < fraction * std::min(res[o.res].area, ref[o.ref].area)) continue;
    ++deg_res[o.res];
    ++deg_ref[o.ref];
    parent[find(o.res)] = find(nr + o.ref);
  }
  for (int d : deg_ref) s->n_1_to_m += d > 1;
  for (int d : deg_res) s->n_n_to_1 += d > 1;
  std::unordered_map<int, std::pair<int, int>> cluster;  // root -> (#res, #ref)
  for (int i = 0; i < nr; ++i) ++cluster[find(i)].first;
  for (int j = 0; j < nt; ++j) ++cluster[find(nr + j)].second;
  for (const auto& [root, c] : cluster) s->n_n_to_m += c.first > 1 && c.second > 1;
}

// A point of the plane the result's roof polygons of `p` lie in.
Eigen::Vector3d PointOn(const eval::RoofPlane& p, const CityModel& model) {
  const auto [s, k] = p.polygons.front();
  return model.buildings[p.building].surfaces[s].polygons[k].exterior.front();
}

// Where v lies against reference plane t (see VertexPlace); d its distance
// to t's outline.
VertexPlace PlaceOf(const Eigen::Vector2d& v, double d, const eval::RoofPlaneSet& ref, size_t t,
                    const EvalOptions& o) {
  const double on = o.gsd_m > 0 ? 2 * o.gsd_m : o.vertex_on_outline_m;
  if (d <= on) return VertexPlace::kOnOutline;
  if (eval::Contains(ref.planes[t].plan, v)) return VertexPlace::kInside;
  for (size_t k = 0; k < ref.planes.size(); ++k) {
    const eval::Box2& b = ref.planes[k].box;
    if (k == t || v.x() < b.min.x() || v.x() > b.max.x() || v.y() < b.min.y() || v.y() > b.max.y())
      continue;
    if (eval::Contains(ref.planes[k].plan, v)) return VertexPlace::kOverAnotherRoof;
  }
  return VertexPlace::kOverNoRoof;
}

void ScoreGeometry(const eval::RoofPlaneSet& res, const eval::RoofPlaneSet& ref,
                   const CityModel& result, const SideMatch& ref_match,
                   const std::vector<Region>& res_regions, const std::vector<Region>& ref_regions,
                   const EvalOptions& o, GeometryScores* g, std::vector<VertexRecord>* records) {
  std::vector<double> angles, dist;
  double v2 = 0;
  for (size_t t = 0; t < ref.planes.size(); ++t) {
    const int r = ref_match.best[t];
    if (r < 0) continue;
    angles.push_back(AngleDeg(res_regions[r].normal, ref_regions[t].normal));
    const Eigen::Vector3d n = res.planes[r].normal, x0 = PointOn(res.planes[r], result);
    ForEachRing(res.planes[r].outline, [&](const eval::Ring2& ring) {
      for (const auto& v : ring) {
        const double d = DistanceToOutline(v, ref.planes[t].outline);
        const VertexPlace place = PlaceOf(v, d, ref, t, o);
        const int k = static_cast<int>(place);
        ++g->vertex_place_count[k];
        dist.push_back(d);
        if (d > o.vertex_max_distance_m) {
          ++g->vertex_outliers;
        } else {
          ++g->vertices;
          v2 += d * d;
          g->vertex_place_sum2[k] += d * d;
        }
        if (records) {
          // Roof planes are not vertical (RoofPlaneOptions::vertical_roof_deg).
          const double z = x0.z() - (n.x() * (v.x() - x0.x()) + n.y() * (v.y() - x0.y())) / n.z();
          records->push_back({{v.x(), v.y(), z}, r, static_cast<int>(t), d, place});
        }
      }
    });
  }
  g->matched_pairs = static_cast<int>(angles.size());
  if (!angles.empty()) {
    double a2 = 0;
    for (double a : angles) a2 += a * a;
    g->angle_rms_deg = std::sqrt(a2 / angles.size());
    g->angle_max_deg = *std::max_element(angles.begin(), angles.end());
    std::sort(angles.begin(), angles.end());
    const size_t n = angles.size();
    g->angle_median_deg = n % 2 ? angles[n / 2] : 0.5 * (angles[n / 2 - 1] + angles[n / 2]);
  }
  if (g->vertices > 0) {
    g->vertex_rms_m = std::sqrt(v2 / g->vertices);
    if (o.gsd_m > 0) g->vertex_rms_gsd = *g->vertex_rms_m / o.gsd_m;
  }
  if (!dist.empty()) {
    std::sort(dist.begin(), dist.end());
    const size_t n = dist.size();
    g->vertex_median_m = n % 2 ? dist[n / 2] : 0.5 * (dist[n / 2 - 1] + dist[n / 2]);
    if (o.gsd_m > 0)
      g->vertex_within_2gsd =
          static_cast<double>(std::upper_bound(dist.begin(), dist.end(), 2 * o.gsd_m) -
                              dist.begin()) /
          n;
  }
}

void ScoreHeights(const CityModel& result, const CityModel& truth, const EvalOptions& o,
                  GeometryScores* g) {
  const double c = o.rmsz_grid_m;
  const std::optional<eval::GridSpan> span = eval::SpanGrid(result, truth, c);
  if (!span) return;
  const auto gr = eval::RasteriseRoofs(result, span->origin, c, span->cols, span->rows,
                                       o.planes.vertical_roof_deg);
  const auto gt = eval::RasteriseRoofs(truth, span->origin, c, span->cols, span->rows,
                                       o.planes.vertical_roof_deg);
  const auto h = eval::CompareHeights(gr, gt);
  g->rmsz_cells = h.cells_both;
  g->rmsz_cells_result_only = h.cells_result;
  g->rmsz_cells_reference_only = h.cells_reference;
  if (h.cells_both > 0) {
    g->rmsz_m = h.rms;
    g->dz_mean_m = h.mean;
  }
}

void ScoreBuildings(const CityModel& result, const CityModel& truth, const EvalOptions& o,
                    EvalResult* out) {
  std::vector<MultiPolygon2> fr, ft;
  for (const auto& b : result.buildings) fr.push_back(eval::BuildingFootprint(b, o.planes));
  for (const auto& b : truth.buildings) ft.push_back(eval::BuildingFootprint(b, o.planes));
  auto regions = [](const std::vector<MultiPolygon2>& f) {
    std::vector<Region> r;
    for (const auto& m : f) r.push_back({&m, eval::BoundsOf(m), eval::Area(m), {0, 0, 1}});
    return r;
  };
  const auto rr = regions(fr), rt = regions(ft);
  const auto overlaps = Overlaps(rr, rt);
  const double f = o.building_overlap_fraction;
  // Footprints carry no normal: the angle test is switched off (180°).
  const SideMatch mr = MatchSide(
      rr, rt, overlaps, f, 180.0, [](const Overlap& x) { return x.res; },
      [](const Overlap& x) { return x.ref; });
  const SideMatch mt = MatchSide(
      rt, rr, overlaps, f, 180.0, [](const Overlap& x) { return x.ref; },
      [](const Overlap& x) { return x.res; });
  BuildingScores& s = out->buildings;
  s.n_result = static_cast<int>(rr.size());
  s.n_reference = static_cast<int>(rt.size());
  s.tp_result = mr.tp;
  s.tp_reference = mt.tp;
  s.completeness = Ratio(mt.tp, s.n_reference);
  s.correctness = Ratio(mr.tp, s.n_result);
  s.quality = Ratio(mt.tp, s.n_reference + s.n_result - mr.tp);
  double top_sq = 0;
  for (int j = 0; j < s.n_reference; ++j) {
    out->reference_building_matched.push_back(mt.best[j] >= 0);
    if (mt.best[j] < 0) continue;
    const double dz = result.buildings[mt.best[j]].RoofTopZ() - truth.buildings[j].RoofTopZ();
    if (std::isfinite(dz)) {
      ++s.top_compared;
      s.top_off += std::abs(dz) > o.building_top_tolerance_m;
      top_sq += dz * dz;
    }
    if (truth.buildings[j].roof_type == roof_type::kUnknown) continue;
    ++s.roof_type_compared;
    s.roof_type_same += result.buildings[mt.best[j]].roof_type == truth.buildings[j].roof_type;
    ++s.roof_type_pairs[{truth.buildings[j].roof_type, result.buildings[mt.best[j]].roof_type}];
  }
  for (int i = 0; i < s.n_result; ++i) out->result_building_matched.push_back(mr.best[i] >= 0);
  s.roof_type_agreement = Ratio(s.roof_type_same, s.roof_type_compared);
  if (s.top_compared > 0) s.top_rms_m = std::sqrt(top_sq / s.top_compared);
}

}  // namespace

const char* VertexPlaceName(VertexPlace place) {
  switch (place) {
    case VertexPlace::kOnOutline:
      return "on the outline";
    case VertexPlace::kInside:
      return "inside, face cut short";
    case VertexPlace::kOverAnotherRoof:
      return "past it, over another roof";
    case VertexPlace::kOverNoRoof:
      return "past it, over no roof";
  }
  return "?";
}

const char* UnmatchedKindKey(UnmatchedKind kind) {
  switch (kind) {
    case UnmatchedKind::kUncovered:
      return "uncovered";
    case UnmatchedKind::kOtherSlope:
      return "other_slope";
    case UnmatchedKind::kSeveralAtItsSlope:
      return "several_at_its_slope";
    case UnmatchedKind::kSeveral:
      return "several";
  }
  return "?";
}

const char* UnmatchedKindName(UnmatchedKind kind, bool result_plane) {
  switch (kind) {
    case UnmatchedKind::kUncovered:
      return result_plane ? "off the reference roofs" : "not covered by the result";
    case UnmatchedKind::kOtherSlope:
      return "at another slope";
    case UnmatchedKind::kSeveralAtItsSlope:
      return result_plane ? "across planes at its slope" : "in pieces at its slope";
    case UnmatchedKind::kSeveral:
      return result_plane ? "across reference planes" : "in pieces of result planes";
  }
  return "?";
}

EvalResult Evaluate(const CityModel& result, const CityModel& truth, const EvalOptions& options,
                    const std::vector<Segment3>* lines,
                    const std::vector<Segment3>* extra_reference_segments,
                    const std::vector<Segment3>* clutter_segments) {
  auto has_parts = [](const CityModel& m) {
    return std::any_of(m.buildings.begin(), m.buildings.end(),
                       [](const Building& b) { return !b.parts.empty(); });
  };
  if (has_parts(result) || has_parts(truth)) {
    CityModel r = result, t = truth;
    MergeBuildingParts(&r);
    MergeBuildingParts(&t);
    return Evaluate(r, t, options, lines, extra_reference_segments);
  }
  CheckOptions(options);
  EvalResult out;
  out.options = options;
  const eval::RoofPlaneSet res = eval::ExtractRoofPlanes(result, options.planes);
  const eval::RoofPlaneSet ref = eval::ExtractRoofPlanes(truth, options.planes);
  out.result_input = Counts(res);
  out.reference_input = Counts(ref);
  const std::vector<Region> rr = Regions(res), rt = Regions(ref);
  const std::vector<Overlap> overlaps = Overlaps(rr, rt);

  const SideMatch mr = MatchSide(
      rr, rt, overlaps, options.plane_overlap_fraction, options.max_normal_angle_deg,
      [](const Overlap& x) { return x.res; }, [](const Overlap& x) { return x.ref; });
  const SideMatch mt = MatchSide(
      rt, rr, overlaps, options.plane_overlap_fraction, options.max_normal_angle_deg,
      [](const Overlap& x) { return x.ref; }, [](const Overlap& x) { return x.res; });
  RoofPlaneScores& s = out.roof_planes;
  s.n_result = static_cast<int>(rr.size());
  s.n_reference = static_cast<int>(rt.size());
  s.tp_result = mr.tp;
  s.tp_reference = mt.tp;
  s.completeness = Ratio(mt.tp, s.n_reference);
  s.correctness = Ratio(mr.tp, s.n_result);
  s.quality = Ratio(mt.tp, s.n_reference + s.n_result - mr.tp);
  ScoreSegmentation(rr, rt, overlaps, options.segmentation_overlap_fraction, &s);
  out.result_planes = Records(res, result, mr, rt, options.plane_overlap_fraction);
  out.reference_planes = Records(ref, truth, mt, rr, options.plane_overlap_fraction);
  auto count_unmatched = [](const std::vector<PlaneRecord>& planes, UnmatchedPlanes* u) {
    for (const PlaneRecord& p : planes) {
      if (p.true_positive) continue;
      ++u->count[static_cast<int>(p.unmatched)];
      u->area_m2[static_cast<int>(p.unmatched)] += p.plan_area;
    }
  };
  count_unmatched(out.result_planes, &s.false_result);
  count_unmatched(out.reference_planes, &s.missed_reference);
  auto count_large = [&](const std::vector<PlaneRecord>& planes, int* n, int* tp) {
    for (const PlaneRecord& p : planes)
      if (p.plan_area >= options.large_plane_m2) ++*n, *tp += p.true_positive;
  };
  count_large(out.reference_planes, &s.n_reference_large, &s.tp_reference_large);
  count_large(out.result_planes, &s.n_result_large, &s.tp_result_large);
  s.completeness_large = Ratio(s.tp_reference_large, s.n_reference_large);
  s.correctness_large = Ratio(s.tp_result_large, s.n_result_large);

  ScoreGeometry(res, ref, result, mt, rr, rt, options, &out.geometry,
                options.keep_vertices ? &out.vertices : nullptr);
  ScoreHeights(result, truth, options, &out.geometry);
  ScoreBuildings(result, truth, options, &out);

  if (lines) {
    const auto edges = eval::RoofEdges(truth, options.lines);
    static const std::vector<Segment3> kNone;
    Lines3dScores& l = out.lines3d;
    l.evaluated = true;
    std::vector<Polygon3> surfaces;
    for (const auto& b : truth.buildings)
      for (const auto& sf : b.surfaces)
        surfaces.insert(surfaces.end(), sf.polygons.begin(), sf.polygons.end());
    l.raw = eval::EvaluateLines(*lines, edges,
                                extra_reference_segments ? *extra_reference_segments : kNone,
                                options.lines, &surfaces, clutter_segments);
    if (clutter_segments) l.on_clutter = Ratio(l.raw.result_on_clutter_m, l.raw.result_length_m);
    l.on_surface = Ratio(l.raw.result_on_surface_m, l.raw.result_length_m);
    l.off_surface =
        Ratio(l.raw.result_length_m - l.raw.result_on_reference_m - l.raw.result_on_surface_m,
              l.raw.result_length_m);
    l.precision = Ratio(l.raw.result_on_reference_m, l.raw.result_length_m);
    l.completeness = Ratio(l.raw.reference_covered_m, l.raw.reference_length_m);
    l.roof_edge_completeness = Ratio(l.raw.roof_edge_covered_m, l.raw.roof_edge_length_m);
  }
  return out;
}

}  // namespace roofsweep
