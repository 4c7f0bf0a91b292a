#include "algorithms/buildings/city_model.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "algorithms/buildings/convex_polygon2.h"

namespace roofsweep {

const char* SurfaceTypeName(SurfaceType t) {
  switch (t) {
    case SurfaceType::kRoof:
      return "RoofSurface";
    case SurfaceType::kWall:
      return "WallSurface";
    case SurfaceType::kGround:
      return "GroundSurface";
    case SurfaceType::kClosure:
      return "ClosureSurface";
  }
  return "?";
}

const char* RoofTypeName(int code) {
  switch (code) {
    case roof_type::kFlat:
      return "flat";
    case roof_type::kMonopitch:
      return "monopitch";
    case roof_type::kDualPent:
      return "dual-pent";
    case roof_type::kGabled:
      return "gabled";
    case roof_type::kHipped:
      return "hipped";
    case roof_type::kHalfHipped:
      return "half-hipped";
    case roof_type::kMansard:
      return "mansard";
    case roof_type::kPavilion:
      return "pavilion";
    case roof_type::kCone:
      return "cone";
    case roof_type::kCupola:
      return "cupola";
    case roof_type::kSawtooth:
      return "sawtooth";
    case roof_type::kArch:
      return "arch";
    case roof_type::kPyramidalBroach:
      return "pyramidal-broach";
    case roof_type::kCombination:
      return "combination";
    default:
      return "unknown";
  }
}

namespace {
bool RingContainsXY(const std::vector<Eigen::Vector3d>& ring, const Eigen::Vector2d& p) {
  bool in = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Eigen::Vector3d &a = ring[i], &b = ring[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

Eigen::Vector3d NewellSum(const std::vector<Eigen::Vector3d>& ring) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  const size_t m = ring.size();
  for (size_t i = 0; i < m; ++i) n += ring[i].cross(ring[(i + 1) % m]);
  return n;  // twice the vector area
}
}  // namespace

Eigen::Vector3d Polygon3::Normal() const {
  const Eigen::Vector3d n = NewellSum(exterior);
  const double len = n.norm();
  return len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
}

double Polygon3::Area() const {
  const Eigen::Vector3d n = Normal();
  double a = 0.5 * n.dot(NewellSum(exterior));
  for (const auto& h : holes) a -= std::abs(0.5 * n.dot(NewellSum(h)));
  return a;
}

bool Polygon3::ContainsXY(const Eigen::Vector2d& p) const {
  if (exterior.empty() || !RingContainsXY(exterior, p)) return false;
  for (const auto& h : holes)
    if (!h.empty() && RingContainsXY(h, p)) return false;
  return true;
}

double Building::GroundZ() const {
  double z = std::numeric_limits<double>::infinity();
  for (const Building* b : Solids())
    for (const auto& s : b->surfaces)
      if (s.type == SurfaceType::kGround)
        for (const auto& p : s.polygons)
          for (const auto& v : p.exterior) z = std::min(z, v.z());
  return std::isinf(z) ? std::numeric_limits<double>::quiet_NaN() : z;
}

double Building::RoofTopZ() const {
  double z = -std::numeric_limits<double>::infinity();
  for (const Building* b : Solids())
    for (const auto& s : b->surfaces)
      if (s.type == SurfaceType::kRoof)
        for (const auto& p : s.polygons)
          for (const auto& v : p.exterior) z = std::max(z, v.z());
  return std::isinf(z) ? std::numeric_limits<double>::quiet_NaN() : z;
}

std::optional<Eigen::Vector2d> Building::PlanCentroid() const {
  // A ground polygon faces down, so its exterior runs clockwise in plan and
  // its holes anticlockwise: the exterior's sign turns each polygon's sums
  // positive, holes included.
  double area = 0;
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  const auto plan = [](const std::vector<Eigen::Vector3d>& ring) {
    Ring2 r;
    for (const Eigen::Vector3d& v : ring) r.push_back(v.head<2>());
    return r;
  };
  for (const Building* b : Solids())
    for (const auto& s : b->surfaces) {
      if (s.type != SurfaceType::kGround) continue;
      for (const auto& poly : s.polygons) {
        const Ring2 outer = plan(poly.exterior);
        double a = SignedArea(outer);
        Eigen::Vector2d m = FirstMoment(outer);
        const double sign = a < 0 ? -1.0 : 1.0;
        for (const auto& h : poly.holes) {
          const Ring2 hole = plan(h);
          a += SignedArea(hole);
          m += FirstMoment(hole);
        }
        area += sign * a;
        moment += sign * m;
      }
    }
  if (!(area > 1e-12)) return std::nullopt;
  return Eigen::Vector2d(moment / area);
}

std::vector<const Building*> Building::Solids() const {
  std::vector<const Building*> out;
  if (!surfaces.empty()) out.push_back(this);
  for (const Building& p : parts) {
    const std::vector<const Building*> sub = p.Solids();
    out.insert(out.end(), sub.begin(), sub.end());
  }
  return out;
}

std::vector<Building*> Building::Solids() {
  std::vector<Building*> out;
  for (const Building* b : static_cast<const Building*>(this)->Solids())
    out.push_back(const_cast<Building*>(b));
  return out;
}

namespace {
void MergeParts(Building* b) {
  // The whole is LoD2 when any of its solids is (the evaluation counts it
  // among the LoD2 buildings), LoD1 when all are.
  bool any_lod2 = b->lod >= 2 && !b->surfaces.empty();
  bool any_solid = !b->surfaces.empty();
  for (Building& p : b->parts) {
    MergeParts(&p);
    any_solid |= !p.surfaces.empty();
    any_lod2 |= p.lod >= 2 && !p.surfaces.empty();
    for (Surface& s : p.surfaces) b->surfaces.push_back(std::move(s));
  }
  if (!b->parts.empty() && any_solid) b->lod = any_lod2 ? 2 : 1;
  b->parts.clear();
}
}  // namespace

void MergeBuildingParts(CityModel* model) {
  for (Building& b : model->buildings) MergeParts(&b);
}

Eigen::Matrix<double, 6, 1> CityModel::Bounds() const {
  const double inf = std::numeric_limits<double>::infinity();
  Eigen::Matrix<double, 6, 1> b;
  b << inf, inf, inf, -inf, -inf, -inf;
  for (const auto& bl : buildings)
    for (const Building* solid : bl.Solids())
      for (const auto& s : solid->surfaces)
        for (const auto& p : s.polygons)
          for (const auto& v : p.exterior) {
            b.head<3>() = b.head<3>().cwiseMin(v);
            b.tail<3>() = b.tail<3>().cwiseMax(v);
          }
  return b;
}

}  // namespace roofsweep
