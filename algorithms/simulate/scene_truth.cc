#include "algorithms/simulate/scene_truth.h"

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <tuple>

namespace roofsweep {
namespace sim {

const char* EdgeKindName(EdgeKind k) {
  switch (k) {
    case EdgeKind::kRidge:
      return "ridge";
    case EdgeKind::kHip:
      return "hip";
    case EdgeKind::kValley:
      return "valley";
    case EdgeKind::kBreak:
      return "break";
    case EdgeKind::kEave:
      return "eave";
    case EdgeKind::kVerge:
      return "verge";
    case EdgeKind::kWallTop:
      return "wall_top";
    case EdgeKind::kStep:
      return "step";
    case EdgeKind::kParty:
      return "party";
    case EdgeKind::kRoofOther:
      return "roof_other";
    case EdgeKind::kWallCorner:
      return "wall_corner";
    case EdgeKind::kFootprint:
      return "footprint";
    case EdgeKind::kGroundMarking:
      return "ground_marking";
    case EdgeKind::kProp:
      return "prop";
  }
  return "?";
}

std::optional<EdgeKind> EdgeKindFromName(const std::string& name) {
  for (int k = 0; k <= static_cast<int>(EdgeKind::kProp); ++k)
    if (name == EdgeKindName(static_cast<EdgeKind>(k))) return static_cast<EdgeKind>(k);
  return std::nullopt;
}

bool IsRoofEdge(EdgeKind k) {
  return static_cast<int>(k) <= static_cast<int>(EdgeKind::kRoofOther);
}

namespace {

using V3 = Eigen::Vector3d;

struct FaceRef {
  SurfaceType type;
  V3 normal;
  V3 centroid;
  const Polygon3* poly;
};

using Key = std::tuple<long long, long long, long long>;
Key Quantise(const V3& p, double tol) {
  return {std::llround(p.x() / tol), std::llround(p.y() / tol), std::llround(p.z() / tol)};
}

V3 Centroid(const std::vector<V3>& ring) {
  V3 c = V3::Zero();
  for (const V3& p : ring) c += p;
  return c / std::max<size_t>(1, ring.size());
}

bool Horizontal(const V3& d) { return std::abs(d.z()) < 0.02 * d.norm(); }

// `inward_b`: unit vector in B's plane, perpendicular to the edge, pointing
// into B.
EdgeKind Classify(const FaceRef& A, const FaceRef& B, const V3& a, const V3& b, const V3& inward_a,
                  const V3& inward_b, bool* skip) {
  *skip = false;
  const V3 d = b - a;
  if (A.normal.dot(B.normal) > 1 - 1e-8) {
    *skip = true;  // coplanar pieces of one face
    return EdgeKind::kRoofOther;
  }
  const bool ra = A.type == SurfaceType::kRoof, rb = B.type == SurfaceType::kRoof;
  const bool wa = A.type == SurfaceType::kWall, wb = B.type == SurfaceType::kWall;
  const bool ga = A.type == SurfaceType::kGround, gb = B.type == SurfaceType::kGround;
  if (ra && rb) {
    const bool convex = A.normal.dot(inward_b) < 0;
    if (!convex) return EdgeKind::kValley;
    if (!Horizontal(d)) return EdgeKind::kHip;
    const Eigen::Vector2d ha = A.normal.head<2>(), hb = B.normal.head<2>();
    return ha.dot(hb) < -1e-6 ? EdgeKind::kRidge : EdgeKind::kBreak;
  }
  if ((ra && wb) || (wa && rb)) {
    const FaceRef& roof = ra ? A : B;
    const FaceRef& wall = ra ? B : A;
    const V3& wall_inward = ra ? inward_b : inward_a;
    if (wall_inward.z() > 0.5) return EdgeKind::kStep;  // the wall rises from the edge
    if (!Horizontal(d)) return EdgeKind::kVerge;
    return roof.normal.dot(wall.normal) > 1e-3 ? EdgeKind::kEave : EdgeKind::kWallTop;
  }
  if ((ra && gb) || (ga && rb)) return EdgeKind::kEave;
  if ((wa && gb) || (ga && wb)) return EdgeKind::kFootprint;
  if (wa && wb) return EdgeKind::kWallCorner;
  *skip = true;
  return EdgeKind::kRoofOther;
}

// Whether p lies on polygon `poly` (within tol of its plane). Sets
// *on_boundary when it is within tol of the ring.
bool OnPolygon(const Polygon3& poly, const V3& p, double tol, bool* on_boundary) {
  const V3 n = poly.Normal();
  if (n.isZero() || std::abs(n.dot(p - poly.exterior[0])) > tol) return false;
  int ax = 0;
  n.cwiseAbs().maxCoeff(&ax);
  const int i0 = (ax + 1) % 3, i1 = (ax + 2) % 3;
  const auto& r = poly.exterior;
  bool inside = false;
  *on_boundary = false;
  for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
    const V3 e = r[i] - r[j];
    const double t = std::clamp(e.dot(p - r[j]) / std::max(e.squaredNorm(), 1e-30), 0.0, 1.0);
    if ((r[j] + t * e - p).norm() < tol) *on_boundary = true;
    if ((r[i][i1] > p[i1]) != (r[j][i1] > p[i1])) {
      const double x =
          r[j][i0] + (p[i1] - r[j][i1]) / (r[i][i1] - r[j][i1]) * (r[i][i0] - r[j][i0]);
      if (p[i0] < x) inside = !inside;
    }
  }
  return inside || *on_boundary;
}

}  // namespace

std::vector<TrueEdge> ExtractBuildingEdges(const CityModel& city, double tolerance) {
  std::vector<TrueEdge> out;
  for (size_t bi = 0; bi < city.buildings.size(); ++bi) {
    const Building& bld = city.buildings[bi];
    std::vector<FaceRef> faces;
    for (const Surface& s : bld.surfaces)
      for (const Polygon3& p : s.polygons)
        if (p.exterior.size() >= 3) faces.push_back({s.type, p.Normal(), Centroid(p.exterior), &p});
    // Undirected edge -> incident faces, in first-seen order (deterministic).
    std::map<std::pair<Key, Key>, std::vector<int>> incident;
    std::map<std::pair<Key, Key>, std::vector<V3>> inward;  // per incident face
    std::vector<std::pair<Key, Key>> order;
    std::map<std::pair<Key, Key>, std::pair<V3, V3>> coords;
    for (size_t fi = 0; fi < faces.size(); ++fi) {
      auto add_ring = [&](const std::vector<V3>& ring) {
        for (size_t i = 0; i < ring.size(); ++i) {
          const V3& a = ring[i];
          const V3& b = ring[(i + 1) % ring.size()];
          Key ka = Quantise(a, tolerance), kb = Quantise(b, tolerance);
          if (ka == kb) continue;
          auto key = ka < kb ? std::make_pair(ka, kb) : std::make_pair(kb, ka);
          auto& list = incident[key];
          if (list.empty()) {
            order.push_back(key);
            coords[key] = {a, b};
          }
          list.push_back(static_cast<int>(fi));
          // Rings are counter-clockwise seen from outside: the face lies to
          // the left of its edges.
          inward[key].push_back(faces[fi].normal.cross(b - a).normalized());
        }
      };
      add_ring(faces[fi].poly->exterior);
      for (const auto& h : faces[fi].poly->holes) add_ring(h);
    }
    for (const auto& key : order) {
      const auto& list = incident[key];
      const auto [a, b] = coords[key];
      TrueEdge e{a, b, EdgeKind::kRoofOther, static_cast<int>(bi)};
      if (list.size() >= 2) {
        bool skip = false;
        e.kind =
            Classify(faces[list[0]], faces[list[1]], a, b, inward[key][0], inward[key][1], &skip);
        if (skip) continue;
      } else {
        const SurfaceType t = faces[list[0]].type;
        if (t == SurfaceType::kGround) continue;
        e.kind = t == SurfaceType::kRoof ? EdgeKind::kRoofOther : EdgeKind::kWallCorner;
      }
      out.push_back(e);
    }
  }
  // Roof outline edges on a neighbour's wall: a step where the neighbour's
  // wall continues above, a flush party edge where it ends there.
  std::vector<Eigen::Matrix<double, 6, 1>> boxes;
  for (const Building& b : city.buildings) {
    CityModel one;
    one.buildings.push_back(b);
    boxes.push_back(one.Bounds());
  }
  const double tol = 0.01;
  for (TrueEdge& e : out) {
    if (e.kind != EdgeKind::kEave && e.kind != EdgeKind::kVerge && e.kind != EdgeKind::kWallTop)
      continue;
    const V3 mid = 0.5 * (e.a + e.b);
    for (size_t bj = 0; bj < city.buildings.size(); ++bj) {
      if (static_cast<int>(bj) == e.building) continue;
      const auto& bx = boxes[bj];
      if ((mid.array() < bx.head<3>().array() - tol).any() ||
          (mid.array() > bx.tail<3>().array() + tol).any())
        continue;
      for (const Surface& s : city.buildings[bj].surfaces) {
        if (s.type != SurfaceType::kWall) continue;
        for (const Polygon3& p : s.polygons) {
          bool boundary = false;
          if (!OnPolygon(p, mid, tol, &boundary)) continue;
          e.kind = boundary ? EdgeKind::kParty : EdgeKind::kStep;
        }
      }
    }
  }
  return out;
}

std::vector<RoofPlane> ExtractRoofPlanes(const CityModel& city) {
  std::vector<RoofPlane> out;
  for (size_t bi = 0; bi < city.buildings.size(); ++bi) {
    const Building& b = city.buildings[bi];
    for (size_t si = 0; si < b.surfaces.size(); ++si) {
      if (b.surfaces[si].type != SurfaceType::kRoof) continue;
      for (const Polygon3& p : b.surfaces[si].polygons) {
        const V3 n = p.Normal();
        if (n.isZero()) continue;
        RoofPlane rp;
        rp.building = static_cast<int>(bi);
        rp.surface = static_cast<int>(si);
        rp.plane << n, -n.dot(Centroid(p.exterior));
        rp.polygon = p;
        out.push_back(std::move(rp));
      }
    }
  }
  return out;
}

}  // namespace sim
}  // namespace roofsweep
