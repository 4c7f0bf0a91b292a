#include "algorithms/buildings/assemble_buildings.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/solid_check.h"
#include "algorithms/core/format.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

double PlaneZ(const Eigen::Vector4d& pl, const Eigen::Vector2d& p) {
  return -(pl[0] * p.x() + pl[1] * p.y() + pl[3]) / pl[2];
}

Eigen::Vector2d Centroid(const Ring2& r) {
  const double a = SignedArea(r);
  if (std::abs(a) < 1e-12) {
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (const auto& p : r) c += p;
    return r.empty() ? c : Eigen::Vector2d(c / r.size());
  }
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (size_t i = 0, n = r.size(); i < n; ++i) {
    const auto& p = r[i];
    const auto& q = r[(i + 1) % n];
    const double w = p.x() * q.y() - q.x() * p.y();
    c += (p + q) * w;
  }
  return c / (6 * a);
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int Find(int i) { return parent[i] == i ? i : parent[i] = Find(parent[i]); }
  void Join(int a, int b) {
    a = Find(a), b = Find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Region of plane `i` in the lower envelope of `active` over `outline`.
Ring2 EnvelopeRegion(const std::vector<RoofPlaneHypothesis>& planes, const std::vector<int>& active,
                     int i, const Ring2& outline) {
  Ring2 r = outline;
  const Eigen::Vector4d& pi = planes[i].plane;
  // z_i = -(a_i x + b_i y + d_i) / c_i; z_i - z_j <= 0 is linear in x, y.
  const Eigen::Vector3d fi(-pi[0] / pi[2], -pi[1] / pi[2], -pi[3] / pi[2]);
  for (int j : active) {
    if (j == i || r.size() < 3) continue;
    const Eigen::Vector4d& pj = planes[j].plane;
    const Eigen::Vector3d fj(-pj[0] / pj[2], -pj[1] / pj[2], -pj[3] / pj[2]);
    const Eigen::Vector3d f = fi - fj;
    // Ties (the same plane twice) go to the lower index.
    if (f.head<2>().norm() < 1e-12 && std::abs(f[2]) < 1e-9 && j > i) continue;
    r = ClipHalfPlane(r, f[0], f[1], f[2]);
  }
  return r.size() >= 3 && SignedArea(r) > 1e-9 ? r : Ring2{};
}

// Welds plan-view vertices closer than `tol`; returns the representative
// of each input point.
class Welder {
 public:
  explicit Welder(double tol) : tol_(tol) {}
  int Add(const Eigen::Vector2d& p) {
    for (size_t i = 0; i < pts_.size(); ++i)
      if ((pts_[i] - p).norm() <= tol_) return static_cast<int>(i);
    pts_.push_back(p);
    return static_cast<int>(pts_.size()) - 1;
  }
  const std::vector<Eigen::Vector2d>& points() const { return pts_; }
  // Welded vertices strictly inside segment u -> v (within tol), ordered
  // from u to v.
  std::vector<int> OnSegment(int u, int v) const {
    const Eigen::Vector2d a = pts_[u], b = pts_[v];
    const double len2 = (b - a).squaredNorm();
    std::vector<std::pair<double, int>> hits;
    for (size_t k = 0; k < pts_.size(); ++k) {
      if (static_cast<int>(k) == u || static_cast<int>(k) == v || len2 <= 0) continue;
      const double t = (pts_[k] - a).dot(b - a) / len2;
      if (t <= 0 || t >= 1) continue;
      if (PointSegmentDistance(pts_[k], a, b) <= tol_) hits.emplace_back(t, static_cast<int>(k));
    }
    std::sort(hits.begin(), hits.end());
    std::vector<int> out;
    for (const auto& h : hits) out.push_back(h.second);
    return out;
  }

 private:
  double tol_;
  std::vector<Eigen::Vector2d> pts_;
};

// A ring of welded ids with the T-junction vertices inserted and repeated
// ids removed.
std::vector<int> CloseRing(const Welder& w, const std::vector<int>& ids) {
  std::vector<int> ring;
  for (size_t k = 0; k < ids.size(); ++k) {
    const int u = ids[k], v = ids[(k + 1) % ids.size()];
    if (u == v) continue;
    ring.push_back(u);
    for (int m : w.OnSegment(u, v)) ring.push_back(m);
  }
  std::vector<int> out;
  for (int id : ring)
    if (out.empty() || out.back() != id) out.push_back(id);
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

}  // namespace

int ClassifyRoofType(const std::vector<Polygon3>& faces) {
  double total = 0;
  for (const Polygon3& f : faces) total += f.Area();
  if (total <= 0) return roof_type::kUnknown;
  struct Face {
    double tilt_deg, azimuth_deg, area;
    size_t vertices;
  };
  std::vector<Face> big;
  for (const Polygon3& f : faces) {
    const double a = f.Area();
    if (a < 0.05 * total) continue;
    const Eigen::Vector3d n = f.Normal();
    big.push_back({std::acos(std::clamp(n.z(), -1.0, 1.0)) / kDeg, std::atan2(n.y(), n.x()) / kDeg,
                   a, f.exterior.size()});
  }
  int tilted = 0;
  for (const Face& f : big) tilted += f.tilt_deg >= 5.0;
  if (tilted == 0) return roof_type::kFlat;
  if (big.size() == 1) return roof_type::kMonopitch;
  auto azimuth_gap = [](double a, double b) {
    const double d = std::fmod(std::abs(a - b), 360.0);
    return std::min(d, 360.0 - d);
  };
  if (big.size() == 2 && tilted == 2 &&
      std::abs(azimuth_gap(big[0].azimuth_deg, big[1].azimuth_deg) - 180.0) < 20.0)
    return roof_type::kGabled;
  if (big.size() == 4 && tilted == 4) {
    // Four slopes facing four directions roughly 90 degrees apart.
    std::vector<double> az;
    for (const Face& f : big) az.push_back(f.azimuth_deg);
    std::sort(az.begin(), az.end());
    bool quad = true;
    for (size_t k = 0; k < 4; ++k)
      quad = quad && std::abs(azimuth_gap(az[k], az[(k + 1) % 4]) - 90.0) < 25.0;
    if (quad) {
      int triangles = 0;
      for (const Face& f : big) triangles += f.vertices == 3;
      return triangles == 4 ? roof_type::kPavilion : roof_type::kHipped;
    }
  }
  return roof_type::kCombination;
}

AssemblyResult AssembleBuildings(const std::vector<RoofPlaneHypothesis>& planes,
                                 const GroundModel& ground, const AssemblyOptions& o) {
  AssemblyResult res;
  res.planes_in = static_cast<int>(planes.size());
  const int n = static_cast<int>(planes.size());
  auto name = [&](int i) { return planes[i].id.empty() ? StrFormat("plane %d", i) : planes[i].id; };

  // 1. Plausible roof planes.
  std::vector<int> keep;
  for (int i = 0; i < n; ++i) {
    const RoofPlaneHypothesis& p = planes[i];
    const Eigen::Vector3d nrm = p.plane.head<3>();
    if (p.patch.size() < 3 || !(std::abs(SignedArea(p.patch)) > 0) || !nrm.allFinite() ||
        std::abs(nrm.norm() - 1) > 1e-6) {
      res.rejected.push_back(name(i) + ": degenerate plane or patch");
      continue;
    }
    if (p.longest_line_m < o.min_line_length_m) {
      res.rejected.push_back(name(i) + StrFormat(": longest supporting line %.2f m < %.2f m",
                                                 p.longest_line_m, o.min_line_length_m));
      continue;
    }
    const double slope = std::acos(std::clamp(nrm.z(), -1.0, 1.0)) / kDeg;
    if (slope > o.max_roof_slope_deg) {
      res.rejected.push_back(name(i) + StrFormat(": slope %.1f deg > %.1f deg (a wall?)", slope,
                                                 o.max_roof_slope_deg));
      continue;
    }
    const Eigen::Vector2d c = Centroid(p.patch);
    const double g = ground.HeightAt(c.x(), c.y());
    if (!std::isfinite(g)) {
      res.rejected.push_back(name(i) + ": no ground height there");
      continue;
    }
    const double h = PlaneZ(p.plane, c) - g;
    if (h < o.min_height_m) {
      res.rejected.push_back(name(i) +
                             StrFormat(": %.2f m above the ground < %.2f m", h, o.min_height_m));
      continue;
    }
    keep.push_back(i);
  }

  // 2. Buildings: patches that touch and whose planes meet there.
  UnionFind uf(n), parts(n);
  std::vector<Ring2> grown(n);
  for (int i : keep) grown[i] = GrowConvex(planes[i].patch, o.adjacency_gap_m);
  for (size_t a = 0; a < keep.size(); ++a)
    for (size_t b = a + 1; b < keep.size(); ++b) {
      const int i = keep[a], j = keep[b];
      if (ConvexDistance(planes[i].patch, planes[j].patch) > o.adjacency_gap_m) continue;
      const Ring2 meet = IntersectConvex(grown[i], grown[j]);
      if (meet.empty()) continue;
      const Eigen::Vector2d c = Centroid(meet);
      if (std::abs(PlaneZ(planes[i].plane, c) - PlaneZ(planes[j].plane, c)) > o.max_step_m)
        continue;
      uf.Join(i, j);
      // A ridge or hip (each plane lies below the other's extension over
      // its own patch) keeps both planes in one convex part; a valley
      // (each lies above) separates parts, whose lower envelopes are built
      // apart: one envelope over both would cut the higher wing away.
      const Eigen::Vector2d ci = Centroid(planes[i].patch), cj = Centroid(planes[j].patch);
      const bool convex =
          PlaneZ(planes[i].plane, ci) <= PlaneZ(planes[j].plane, ci) + o.max_step_m &&
          PlaneZ(planes[j].plane, cj) <= PlaneZ(planes[i].plane, cj) + o.max_step_m;
      if (convex || !o.split_at_valleys) parts.Join(i, j);
    }
  std::map<int, std::vector<int>> groups;
  for (int i : keep) groups[parts.Find(i)].push_back(i);
  res.hypotheses = static_cast<int>(groups.size());

  int building_no = 0;
  for (auto& [root, members] : groups) {
    ++building_no;
    const std::string bname = StrFormat("building hypothesis %d", building_no);
    std::vector<int> active = members;
    Ring2 outline;
    std::vector<Ring2> regions;
    double ground_z = 0;
    // 3. Lower envelope, dropping planes that bound the roof where the
    // images did not see them, until every face is supported.
    for (;;) {
      std::vector<Eigen::Vector2d> all;
      for (int i : active) all.insert(all.end(), planes[i].patch.begin(), planes[i].patch.end());
      outline = ConvexHull(all);
      if (outline.size() < 3) break;
      ground_z = std::numeric_limits<double>::infinity();
      for (const auto& p : outline) ground_z = std::min(ground_z, ground.HeightAt(p.x(), p.y()));
      regions.assign(active.size(), Ring2{});
      int worst = -1;
      double worst_value = std::numeric_limits<double>::infinity();
      std::string worst_reason;
      for (size_t k = 0; k < active.size(); ++k) {
        const int i = active[k];
        regions[k] = EnvelopeRegion(planes, active, i, outline);
        const double area = regions[k].empty() ? 0.0 : SignedArea(regions[k]);
        const Ring2 inside = IntersectConvex(regions[k], grown[i]);
        const double support = area > 0 && !inside.empty() ? SignedArea(inside) / area : 0.0;
        double low = std::numeric_limits<double>::infinity();
        for (const auto& p : regions[k]) low = std::min(low, PlaneZ(planes[i].plane, p));
        // Rank failures by how little evidence the face has.
        double value = std::numeric_limits<double>::infinity();
        std::string why;
        if (area < o.min_face_area_m2) {
          value = area;
          why = StrFormat(": roof face of %.2f m2 < %.2f m2 (%s)", area, o.min_face_area_m2,
                          area == 0 ? "above the roof everywhere" : "sliver");
        } else if (support < o.min_support) {
          value = support;
          why = StrFormat(": only %.0f %% of its roof face lies where the images saw the plane",
                          100 * support);
        } else if (low - ground_z < 0.5 * o.min_height_m) {
          value = -1;  // a roof below the walls' minimum height is never right
          why = StrFormat(": its roof face comes down to %.2f m above the ground", low - ground_z);
        }
        if (value < worst_value ||
            (value == worst_value && worst >= 0 && planes[i].score < planes[active[worst]].score)) {
          worst_value = value;
          worst = static_cast<int>(k);
          worst_reason = why;
        }
      }
      if (worst < 0 || worst_reason.empty()) break;
      res.rejected.push_back(name(active[worst]) + worst_reason);
      active.erase(active.begin() + worst);
      if (active.empty()) break;
    }
    if (active.empty() || outline.size() < 3) {
      res.rejected.push_back(bname + ": no roof plane left");
      continue;
    }
    const double footprint = SignedArea(outline);
    if (footprint < o.min_footprint_m2) {
      res.rejected.push_back(
          bname + StrFormat(": footprint %.1f m2 < %.1f m2", footprint, o.min_footprint_m2));
      continue;
    }
    if (!std::isfinite(ground_z)) {
      res.rejected.push_back(bname + ": no ground height under the outline");
      continue;
    }

    // 4. Shared vertices: weld, then build faces from welded ids so that
    // neighbouring faces and the walls use the very same coordinates.
    Welder welder(o.weld_m);
    std::vector<std::vector<int>> region_ids(active.size());
    for (size_t k = 0; k < active.size(); ++k)
      for (const auto& p : regions[k]) region_ids[k].push_back(welder.Add(p));
    std::vector<int> outline_ids;
    for (const auto& p : outline) outline_ids.push_back(welder.Add(p));
    auto roof_z = [&](int id) {
      double z = std::numeric_limits<double>::infinity();
      for (int i : active) z = std::min(z, PlaneZ(planes[i].plane, welder.points()[id]));
      return z;
    };
    auto top = [&](int id) {
      const Eigen::Vector2d& p = welder.points()[id];
      return Eigen::Vector3d(p.x(), p.y(), roof_z(id));
    };

    Building b;
    b.id = StrFormat("rs_b%04d", static_cast<int>(res.model.buildings.size()) + 1);
    Surface roof{SurfaceType::kRoof, "", {}};
    double lines = 0, sim = 0, score = 0;
    std::vector<Polygon3> roof_faces;
    for (size_t k = 0; k < active.size(); ++k) {
      const std::vector<int> ring = CloseRing(welder, region_ids[k]);
      if (ring.size() < 3) continue;
      Polygon3 poly;
      for (int id : ring) poly.exterior.push_back(top(id));
      roof.polygons.push_back(poly);
      const RoofPlaneHypothesis& p = planes[active[k]];
      lines += p.lines;
      sim += p.similarity;
      score += p.score;
    }
    roof_faces = roof.polygons;
    std::vector<Surface> walls;
    const std::vector<int> ring = CloseRing(welder, outline_ids);
    // Outline vertices in the welded ring order, for the walls' corners.
    std::vector<size_t> corners;
    for (size_t k = 0; k < ring.size(); ++k)
      if (std::find(outline_ids.begin(), outline_ids.end(), ring[k]) != outline_ids.end())
        corners.push_back(k);
    for (size_t c = 0; c < corners.size(); ++c) {
      const size_t from = corners[c], to = corners[(c + 1) % corners.size()];
      std::vector<int> chain;
      for (size_t k = from;; k = (k + 1) % ring.size()) {
        chain.push_back(ring[k]);
        if (k == to) break;
      }
      const Eigen::Vector2d& p = welder.points()[chain.front()];
      const Eigen::Vector2d& q = welder.points()[chain.back()];
      Polygon3 wall;
      wall.exterior.emplace_back(p.x(), p.y(), ground_z);
      wall.exterior.emplace_back(q.x(), q.y(), ground_z);
      for (auto it = chain.rbegin(); it != chain.rend(); ++it) wall.exterior.push_back(top(*it));
      walls.push_back({SurfaceType::kWall, "", {wall}});
    }
    Polygon3 floor;
    for (auto it = corners.rbegin(); it != corners.rend(); ++it) {
      const Eigen::Vector2d& p = welder.points()[ring[*it]];
      floor.exterior.emplace_back(p.x(), p.y(), ground_z);
    }
    b.surfaces.push_back({SurfaceType::kGround, "", {floor}});
    for (Polygon3& r : roof.polygons) b.surfaces.push_back({SurfaceType::kRoof, "", {r}});
    for (Surface& w : walls) b.surfaces.push_back(std::move(w));
    b.roof_type = ClassifyRoofType(roof_faces);
    double top_z = -std::numeric_limits<double>::infinity();
    for (const Polygon3& r : roof_faces)
      for (const auto& v : r.exterior) top_z = std::max(top_z, v.z());
    b.measured_height = top_z - ground_z;
    b.double_attributes["roof_planes"] = static_cast<double>(roof_faces.size());
    b.double_attributes["supporting_lines"] = lines;
    b.double_attributes["photometric_score"] = roof_faces.empty() ? 0.0 : sim / roof_faces.size();
    b.double_attributes["reliability"] = score;
    b.double_attributes["footprint_m2"] = footprint;
    // Convex parts of one building (split at valleys) share this number.
    b.double_attributes["building_group"] = static_cast<double>(uf.Find(root));

    const SolidCheckResult check = CheckBuildingSolid(b);
    if (!check.Valid()) {
      res.rejected.push_back(bname + ": solid not valid (" + check.Summary() + ")");
      continue;
    }
    res.planes_used += static_cast<int>(active.size());
    res.model.buildings.push_back(std::move(b));
  }
  return res;
}

}  // namespace roofsweep
