#include "algorithms/buildings/solid_check.h"

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <unordered_map>

namespace roofsweep {

const char* SolidErrorName(SolidError e) {
  switch (e) {
    case SolidError::kTooFewPoints:
      return "TOO_FEW_POINTS";
    case SolidError::kConsecutivePointsSame:
      return "CONSECUTIVE_POINTS_SAME";
    case SolidError::kRingSelfIntersection:
      return "RING_SELF_INTERSECTION";
    case SolidError::kNonPlanar:
      return "NON_PLANAR_POLYGON_DISTANCE_PLANE";
    case SolidError::kShellNotClosed:
      return "SHELL_NOT_CLOSED";
    case SolidError::kNonManifoldEdge:
      return "NON_MANIFOLD_CASE";
    case SolidError::kPolygonWrongOrientation:
      return "POLYGON_WRONG_ORIENTATION";
    case SolidError::kAllPolygonsWronglyOriented:
      return "ALL_POLYGONS_WRONGLY_ORIENTED";
    case SolidError::kEmpty:
      return "EMPTY_PRIMITIVE";
  }
  return "UNKNOWN";
}

std::string SolidCheckResult::Summary() const {
  if (violations.empty()) return "valid";
  std::map<int, int> counts;
  for (const auto& v : violations) ++counts[static_cast<int>(v.code)];
  std::string s;
  for (const auto& [code, n] : counts) {
    if (!s.empty()) s += "; ";
    s += std::to_string(code) + " " + SolidErrorName(static_cast<SolidError>(code));
    if (n > 1) s += " x" + std::to_string(n);
  }
  return s;
}

namespace {

using Ring = std::vector<Eigen::Vector3d>;

// Merges vertices closer than `tol` into one id. A hash grid with cell size
// `tol` and a search of the 27 neighbouring cells keeps it exact (no
// dependence on where the grid boundaries fall) and deterministic (the first
// vertex seen becomes the representative).
class VertexWelder {
 public:
  explicit VertexWelder(double tol) : tol_(tol > 0 ? tol : 1e-9) {}

  int Id(const Eigen::Vector3d& p) {
    const std::array<long long, 3> c = Cell(p);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          auto it = grid_.find(Key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == grid_.end()) continue;
          for (int id : it->second)
            if ((points_[id] - p).norm() <= tol_) return id;
        }
    const int id = static_cast<int>(points_.size());
    points_.push_back(p);
    grid_[Key(c)].push_back(id);
    return id;
  }
  const Eigen::Vector3d& Point(int id) const { return points_[id]; }

 private:
  std::array<long long, 3> Cell(const Eigen::Vector3d& p) const {
    return {static_cast<long long>(std::floor(p.x() / tol_)),
            static_cast<long long>(std::floor(p.y() / tol_)),
            static_cast<long long>(std::floor(p.z() / tol_))};
  }
  static std::string Key(const std::array<long long, 3>& c) {
    return std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]);
  }
  double tol_;
  std::vector<Eigen::Vector3d> points_;
  std::unordered_map<std::string, std::vector<int>> grid_;
};

std::string Fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// Least-squares plane through all ring vertices: centroid and unit normal
// (the eigenvector of the smallest covariance eigenvalue), oriented like the
// exterior ring's Newell normal.
void FitPlane(const Polygon3& poly, Eigen::Vector3d* centroid, Eigen::Vector3d* normal) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  size_t n = 0;
  auto add = [&](const Ring& r) {
    for (const auto& p : r) c += p, ++n;
  };
  add(poly.exterior);
  for (const auto& h : poly.holes) add(h);
  c /= static_cast<double>(n);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  auto acc = [&](const Ring& r) {
    for (const auto& p : r) cov += (p - c) * (p - c).transpose();
  };
  acc(poly.exterior);
  for (const auto& h : poly.holes) acc(h);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
  Eigen::Vector3d nrm = es.eigenvectors().col(0);
  if (nrm.dot(poly.Normal()) < 0) nrm = -nrm;
  *centroid = c;
  *normal = nrm;
}

double Orient(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

double PointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                            const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double l2 = ab.squaredNorm();
  double t = l2 > 0 ? (p - a).dot(ab) / l2 : 0;
  t = std::max(0.0, std::min(1.0, t));
  return (a + t * ab - p).norm();
}

// True when the segments cross properly, or (touch = true) when one endpoint
// lies within `tol` of the other segment.
bool SegmentsIntersect(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                       const Eigen::Vector2d& d, bool touch, double tol) {
  const double o1 = Orient(a, b, c), o2 = Orient(a, b, d);
  const double o3 = Orient(c, d, a), o4 = Orient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  if (!touch) return false;
  return PointSegmentDistance(c, a, b) < tol || PointSegmentDistance(d, a, b) < tol ||
         PointSegmentDistance(a, c, d) < tol || PointSegmentDistance(b, c, d) < tol;
}

// Self-intersection of the polygon's rings in its own plane. O(n²) in the
// number of edges, which is fine for building faces (tens of vertices).
bool RingsSelfIntersect(const Polygon3& poly, const Eigen::Vector3d& c, const Eigen::Vector3d& n,
                        double tol) {
  const Eigen::Vector3d u = n.unitOrthogonal();
  const Eigen::Vector3d v = n.cross(u);
  std::vector<std::vector<Eigen::Vector2d>> rings;
  auto proj = [&](const Ring& r) {
    std::vector<Eigen::Vector2d> out;
    for (const auto& p : r) out.emplace_back((p - c).dot(u), (p - c).dot(v));
    rings.push_back(out);
  };
  proj(poly.exterior);
  for (const auto& h : poly.holes) proj(h);
  for (size_t r1 = 0; r1 < rings.size(); ++r1) {
    const auto& A = rings[r1];
    const size_t na = A.size();
    for (size_t i = 0; i < na; ++i) {
      for (size_t r2 = r1; r2 < rings.size(); ++r2) {
        const auto& B = rings[r2];
        const size_t nb = B.size();
        for (size_t j = (r1 == r2 ? i + 1 : 0); j < nb; ++j) {
          const bool same = r1 == r2;
          // Neighbouring edges of one ring share a vertex by construction.
          if (same && (j == i + 1 || (i == 0 && j == na - 1))) continue;
          if (SegmentsIntersect(A[i], A[(i + 1) % na], B[j], B[(j + 1) % nb], same, tol))
            return true;
        }
      }
    }
  }
  return false;
}

struct EdgeUse {
  int forward = 0;  // traversed from the smaller to the larger vertex id
  int backward = 0;
  std::vector<std::pair<int, int>> polygons;  // (surface, polygon)
};

}  // namespace

SolidCheckResult CheckBuildingSolid(const Building& building, const SolidCheckOptions& options) {
  SolidCheckResult result;
  auto& out = result.violations;
  VertexWelder welder(options.weld_tolerance);
  std::map<std::pair<int, int>, EdgeUse> edges;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  bool have_origin = false;
  double six_volume = 0;
  size_t polygon_count = 0;

  for (size_t si = 0; si < building.surfaces.size(); ++si) {
    const auto& surface = building.surfaces[si];
    for (size_t pi = 0; pi < surface.polygons.size(); ++pi) {
      const Polygon3& poly = surface.polygons[pi];
      const int s = static_cast<int>(si), p = static_cast<int>(pi);
      ++polygon_count;
      bool rings_ok = true;
      std::vector<const Ring*> rings{&poly.exterior};
      for (const auto& h : poly.holes) rings.push_back(&h);
      std::vector<std::vector<int>> ids(rings.size());
      for (size_t r = 0; r < rings.size(); ++r) {
        const Ring& ring = *rings[r];
        bool dup = false;
        for (const auto& q : ring) {
          const int id = welder.Id(q);
          if (!ids[r].empty() && ids[r].back() == id) {
            dup = true;
            continue;
          }
          ids[r].push_back(id);
        }
        if (ids[r].size() > 1 && ids[r].front() == ids[r].back()) {
          dup = true;  // a repeated closing vertex: rings must not repeat it here
          ids[r].pop_back();
        }
        if (dup)
          out.push_back({SolidError::kConsecutivePointsSame, s, p,
                         r == 0 ? "exterior ring" : "interior ring " + std::to_string(r - 1)});
        if (ids[r].size() < 3) {
          out.push_back({SolidError::kTooFewPoints, s, p,
                         std::to_string(ids[r].size()) + " distinct vertices"});
          rings_ok = false;
        }
      }
      if (!rings_ok) continue;

      Eigen::Vector3d c, n;
      FitPlane(poly, &c, &n);
      double worst = 0;
      for (const Ring* r : rings)
        for (const auto& q : *r) worst = std::max(worst, std::abs((q - c).dot(n)));
      if (worst > options.planarity_tolerance)
        out.push_back({SolidError::kNonPlanar, s, p, "distance " + Fmt("%.4f", worst) + " m"});
      if (RingsSelfIntersect(poly, c, n, options.weld_tolerance))
        out.push_back({SolidError::kRingSelfIntersection, s, p, ""});

      if (!have_origin) origin = poly.exterior.front(), have_origin = true;
      for (size_t r = 0; r < rings.size(); ++r) {
        const Ring& ring = *rings[r];
        // Fan triangles from the ring's first vertex: signed volume is exact
        // for non-convex rings, and clockwise holes subtract themselves.
        for (size_t k = 1; k + 1 < ring.size(); ++k)
          six_volume += (ring[0] - origin).dot((ring[k] - origin).cross(ring[k + 1] - origin));
        const auto& rid = ids[r];
        for (size_t k = 0; k < rid.size(); ++k) {
          const int a = rid[k], b = rid[(k + 1) % rid.size()];
          EdgeUse& e = edges[{std::min(a, b), std::max(a, b)}];
          (a < b ? e.forward : e.backward)++;
          e.polygons.emplace_back(s, p);
        }
      }
    }
  }
  result.signed_volume = six_volume / 6.0;
  if (polygon_count == 0) {
    out.push_back({SolidError::kEmpty, -1, -1, "no polygons"});
    return result;
  }

  // Edge problems are counted per polygon so that one flipped wall is one
  // violation (not one per edge): a polygon is blamed for wrong orientation
  // when most of its shared edges run the same way as their neighbour's.
  std::map<std::pair<int, int>, std::array<int, 3>> per_polygon;  // free, conflicting, total
  bool topology_error = false;
  for (const auto& [key, e] : edges) {
    const int uses = e.forward + e.backward;
    for (const auto& sp : e.polygons) per_polygon[sp][2]++;
    if (uses == 1) {
      per_polygon[e.polygons.front()][0]++;
      topology_error = true;
    } else if (uses > 2) {
      const Eigen::Vector3d& a = welder.Point(key.first);
      const Eigen::Vector3d& b = welder.Point(key.second);
      char buf[160];
      std::snprintf(buf, sizeof buf, "edge (%.3f %.3f %.3f)-(%.3f %.3f %.3f) used %d times", a.x(),
                    a.y(), a.z(), b.x(), b.y(), b.z(), uses);
      out.push_back({SolidError::kNonManifoldEdge, -1, -1, buf});
      topology_error = true;
    } else if (e.forward == 2 || e.backward == 2) {
      for (const auto& sp : e.polygons) per_polygon[sp][1]++;
      topology_error = true;
    }
  }
  for (const auto& [sp, c] : per_polygon)
    if (c[0] > 0)
      out.push_back({SolidError::kShellNotClosed, sp.first, sp.second,
                     std::to_string(c[0]) + " free edge(s)"});
  bool any_majority = false;
  for (const auto& kv : per_polygon) any_majority |= 2 * kv.second[1] > kv.second[2];
  for (const auto& [sp, c] : per_polygon)
    if (c[1] > 0 && (!any_majority || 2 * c[1] > c[2]))
      out.push_back({SolidError::kPolygonWrongOrientation, sp.first, sp.second,
                     std::to_string(c[1]) + " edge(s) run the same way as a neighbour's"});
  if (!topology_error && result.signed_volume < 0)
    out.push_back({SolidError::kAllPolygonsWronglyOriented, -1, -1,
                   "signed volume " + Fmt("%.3f", result.signed_volume) + " m3"});
  return result;
}

}  // namespace roofsweep
