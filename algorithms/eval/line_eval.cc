#include "algorithms/eval/line_eval.h"

#include <cmath>
#include <string>
#include <unordered_map>

#include "algorithms/core/error.h"

namespace roofsweep::eval {
namespace {

// Buckets ids by the xy cells their (tolerance-grown) bounding boxes touch,
// so a sample point only meets the few segments or polygons near it. A
// hand-made grid because the query is "all within d of a point" in 3D,
// which OpenCV/Eigen do not offer, and CGAL's AABB tree would put CGAL
// compile costs into this file for no gain at these sizes.
class CellBuckets {
 public:
  explicit CellBuckets(double cell) : cell_(cell) {}

  void Add(int id, Eigen::Vector2d lo, Eigen::Vector2d hi, double margin, const char* what) {
    const long long x0 = Cell(lo.x() - margin), x1 = Cell(hi.x() + margin);
    const long long y0 = Cell(lo.y() - margin), y1 = Cell(hi.y() + margin);
    if ((x1 - x0 + 1) * (y1 - y0 + 1) > 1000000)
      throw Error(std::string("3D line evaluation: a ") + what +
                  " spans more than 10^6 grid cells");
    for (long long x = x0; x <= x1; ++x)
      for (long long y = y0; y <= y1; ++y) cells_[Key(x, y)].push_back(id);
  }

  // The ids whose boxes touch p's cell (hash collisions only add
  // candidates; the caller's distance test decides); null when none.
  const std::vector<int>* At(const Eigen::Vector3d& p) const {
    const auto it = cells_.find(Key(Cell(p.x()), Cell(p.y())));
    return it == cells_.end() ? nullptr : &it->second;
  }

 private:
  long long Cell(double v) const { return static_cast<long long>(std::floor(v / cell_)); }
  static long long Key(long long x, long long y) { return x * 73856093LL ^ y * 19349663LL; }

  double cell_;
  std::unordered_map<long long, std::vector<int>> cells_;
};

class SegmentGrid {
 public:
  SegmentGrid(const std::vector<const Segment3*>& segments, double margin, double cell)
      : segments_(segments), buckets_(cell) {
    for (int i = 0; i < static_cast<int>(segments.size()); ++i) {
      const Segment3& s = *segments[i];
      buckets_.Add(i, s.a.head<2>().cwiseMin(s.b.head<2>()), s.a.head<2>().cwiseMax(s.b.head<2>()),
                   margin, "segment");
    }
  }

  // True when a segment within `dist` of p has a direction within the angle.
  bool Near(const Eigen::Vector3d& p, const Eigen::Vector3d& dir, double dist,
            double cos_angle) const {
    const std::vector<int>* ids = buckets_.At(p);
    if (!ids) return false;
    for (int i : *ids) {
      const Segment3& s = *segments_[i];
      if (std::abs(s.Direction().dot(dir)) < cos_angle) continue;
      if (s.Distance(p) <= dist) return true;
    }
    return false;
  }

 private:
  std::vector<const Segment3*> segments_;
  CellBuckets buckets_;
};

// Reference polygons, for "is p within d of a surface": plane distance, then
// the even-odd test in the plane's projection onto the axis plane it is
// least inclined to.
class PolygonGrid {
 public:
  PolygonGrid(const std::vector<Polygon3>& polygons, double margin, double cell) : buckets_(cell) {
    for (const Polygon3& p : polygons) {
      if (p.exterior.size() < 3) continue;
      Entry e;
      e.n = p.Normal();
      if (e.n.norm() < 0.5) continue;  // degenerate ring
      e.d = -e.n.dot(p.exterior[0]);
      int drop = 0;
      e.n.cwiseAbs().maxCoeff(&drop);
      e.u = drop == 0 ? 1 : 0;
      e.v = drop == 2 ? 1 : 2;
      auto flat = [&](const std::vector<Eigen::Vector3d>& ring) {
        std::vector<Eigen::Vector2d> r;
        for (const auto& q : ring) r.emplace_back(q[e.u], q[e.v]);
        return r;
      };
      e.rings.push_back(flat(p.exterior));
      for (const auto& h : p.holes) e.rings.push_back(flat(h));
      Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
      for (const auto& q : p.exterior) {
        lo = lo.cwiseMin(q.head<2>());
        hi = hi.cwiseMax(q.head<2>());
      }
      buckets_.Add(static_cast<int>(entries_.size()), lo, hi, margin, "surface");
      entries_.push_back(std::move(e));
    }
  }

  bool Near(const Eigen::Vector3d& p, double dist) const {
    const std::vector<int>* ids = buckets_.At(p);
    if (!ids) return false;
    for (int i : *ids) {
      const Entry& e = entries_[i];
      if (std::abs(e.n.dot(p) + e.d) > dist) continue;
      const Eigen::Vector2d q(p[e.u], p[e.v]);
      bool inside = false;
      for (const auto& ring : e.rings)
        for (size_t k = 0, j = ring.size() - 1; k < ring.size(); j = k++)
          if ((ring[k].y() > q.y()) != (ring[j].y() > q.y()) &&
              q.x() < (ring[j].x() - ring[k].x()) * (q.y() - ring[k].y()) /
                              (ring[j].y() - ring[k].y()) +
                          ring[k].x())
            inside = !inside;
      if (inside) return true;
    }
    return false;
  }

 private:
  struct Entry {
    Eigen::Vector3d n;
    double d = 0;
    int u = 0, v = 1;
    std::vector<std::vector<Eigen::Vector2d>> rings;
  };
  std::vector<Entry> entries_;
  CellBuckets buckets_;
};

// Calls f(point, direction) at the centres of the n equal pieces of s, at
// most step apart; returns n (0 for a zero-length segment).
template <typename F>
int ForEachSample(const Segment3& s, double step, F f) {
  const double len = s.Length();
  if (len <= 0) return 0;
  const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
  const Eigen::Vector3d dir = s.Direction();
  for (int k = 0; k < n; ++k) f(s.At((k + 0.5) / n), dir);
  return n;
}

// Length of `s` whose sample points satisfy `grid.Near`.
double CoveredLength(const Segment3& s, const SegmentGrid& grid, const LineEvalOptions& o,
                     double cos_angle) {
  int hits = 0;
  const int n =
      ForEachSample(s, o.sample_step_m, [&](const Eigen::Vector3d& p, const Eigen::Vector3d& dir) {
        if (grid.Near(p, dir, o.distance_m, cos_angle)) ++hits;
      });
  return n > 0 ? s.Length() * hits / n : 0.0;
}

}  // namespace

std::vector<Segment3> RoofEdges(const CityModel& model, const LineEvalOptions& options) {
  const double cos_coplanar = std::cos(options.coplanar_angle_deg * M_PI / 180.0);
  std::vector<Segment3> out;
  for (const auto& b : model.buildings) {
    struct Entry {
      Segment3 seg;
      Eigen::Vector3d normal;  // of the polygon it came from
      bool drop = false;
      bool duplicate = false;
    };
    std::vector<Entry> entries;
    for (const auto& s : b.surfaces) {
      if (s.type != SurfaceType::kRoof) continue;
      for (const auto& p : s.polygons) {
        Eigen::Vector3d n = p.Normal();
        if (n.z() < 0) n = -n;
        auto add = [&](const std::vector<Eigen::Vector3d>& ring) {
          for (size_t i = 0; i < ring.size(); ++i) {
            Segment3 seg{ring[i], ring[(i + 1) % ring.size()]};
            if (seg.Length() > options.merge_m) entries.push_back({seg, n});
          }
        };
        add(p.exterior);
        for (const auto& h : p.holes) add(h);
      }
    }
    // Quadratic in the edges of one building, which are few.
    for (size_t i = 0; i < entries.size(); ++i) {
      if (entries[i].duplicate) continue;
      for (size_t j = i + 1; j < entries.size(); ++j) {
        const Segment3& u = entries[i].seg;
        const Segment3& v = entries[j].seg;
        const bool same =
            ((u.a - v.a).norm() <= options.merge_m && (u.b - v.b).norm() <= options.merge_m) ||
            ((u.a - v.b).norm() <= options.merge_m && (u.b - v.a).norm() <= options.merge_m);
        if (!same) continue;
        entries[j].duplicate = true;
        if (std::abs(entries[i].normal.dot(entries[j].normal)) >= cos_coplanar)
          entries[i].drop = true;
      }
    }
    for (const auto& e : entries)
      if (!e.duplicate && !e.drop) out.push_back(e.seg);
  }
  return out;
}

LineScores EvaluateLines(const std::vector<Segment3>& result,
                         const std::vector<Segment3>& roof_edges,
                         const std::vector<Segment3>& extra_reference,
                         const LineEvalOptions& options, const std::vector<Polygon3>* surfaces,
                         const std::vector<Segment3>* clutter) {
  if (!(options.distance_m >= 0) || !(options.sample_step_m > 0))
    throw Error("3D line evaluation: distance must be >= 0 and sample step > 0");
  const double cos_angle = std::cos(options.angle_deg * M_PI / 180.0);
  // Cells of a few tolerances: small enough to keep candidate lists short,
  // large enough that long segments do not touch too many cells.
  const double cell = std::max(1.0, 10 * options.distance_m);
  LineScores s;
  s.segments = static_cast<int>(result.size());
  std::vector<const Segment3*> res, ref;
  for (const auto& l : result) res.push_back(&l);
  for (const auto& l : roof_edges) ref.push_back(&l);
  for (const auto& l : extra_reference) ref.push_back(&l);
  const SegmentGrid res_grid(res, options.distance_m, cell);
  const SegmentGrid ref_grid(ref, options.distance_m, cell);
  std::vector<const Segment3*> clutter_lines;
  if (clutter)
    for (const auto& l : *clutter) clutter_lines.push_back(&l);
  const SegmentGrid clutter_grid(clutter_lines, options.distance_m, cell);
  const bool with_surfaces = surfaces != nullptr || options.ground.Known();
  static const std::vector<Polygon3> kNone;
  const PolygonGrid surface_grid(surfaces ? *surfaces : kNone, options.distance_m, cell);
  for (const auto& l : result) {
    const double len = l.Length();
    s.result_length_m += len;
    int on_edge = 0, on_clutter = 0, on_surface = 0;
    const int n = ForEachSample(
        l, options.sample_step_m, [&](const Eigen::Vector3d& p, const Eigen::Vector3d& dir) {
          if (ref_grid.Near(p, dir, options.distance_m, cos_angle)) {
            ++on_edge;
          } else if (!clutter_lines.empty() &&
                     clutter_grid.Near(p, dir, options.distance_m, cos_angle)) {
            ++on_clutter;
          } else if (with_surfaces && (std::abs(p.z() - options.ground.HeightAt(p.x(), p.y())) <=
                                           options.distance_m ||
                                       surface_grid.Near(p, options.distance_m))) {
            ++on_surface;
          }
        });
    if (n == 0) continue;
    s.result_on_reference_m += len * (on_edge + on_clutter) / n;
    s.result_on_clutter_m += len * on_clutter / n;
    s.result_on_surface_m += len * on_surface / n;
  }
  for (const auto& l : roof_edges) {
    const double c = CoveredLength(l, res_grid, options, cos_angle);
    s.roof_edge_length_m += l.Length();
    s.roof_edge_covered_m += c;
    s.reference_covered_each_m.push_back(c);
  }
  s.reference_length_m = s.roof_edge_length_m;
  s.reference_covered_m = s.roof_edge_covered_m;
  for (const auto& l : extra_reference) {
    const double c = CoveredLength(l, res_grid, options, cos_angle);
    s.reference_length_m += l.Length();
    s.reference_covered_m += c;
    s.reference_covered_each_m.push_back(c);
  }
  return s;
}

}  // namespace roofsweep::eval
