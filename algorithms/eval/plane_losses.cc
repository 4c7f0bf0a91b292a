#include "algorithms/eval/plane_losses.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "algorithms/core/format.h"
#include "algorithms/core/reason_kind.h"
#include "algorithms/eval/plan_geometry.h"
#include "algorithms/eval/plan_view.h"

namespace roofsweep {
namespace {

// Newell's normal (upward) and the centroid of a planar ring.
bool PlaneOf(const std::vector<Eigen::Vector3d>& ring, Eigen::Vector3d* n, Eigen::Vector3d* c) {
  if (ring.size() < 3) return false;
  *n = Eigen::Vector3d::Zero();
  *c = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < ring.size(); ++i) {
    const Eigen::Vector3d& a = ring[i];
    const Eigen::Vector3d& b = ring[(i + 1) % ring.size()];
    *n += Eigen::Vector3d((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                          (a.x() - b.x()) * (a.y() + b.y()));
    *c += a;
  }
  *c /= static_cast<double>(ring.size());
  if (!(n->norm() > 1e-12)) return false;
  n->normalize();
  if (n->z() < 0) *n = -*n;
  return std::abs(n->z()) > 1e-6;
}

int Rank(const std::string& status) {
  return status == "built" ? 3 : status == "not built" ? 2 : status == "rejected" ? 1 : 0;
}

}  // namespace

PlaneLosses ClassifyMissedPlanes(const CityModel& truth, const EvalResult& eval,
                                 const std::vector<PlaneHypothesisRecord>& hypotheses,
                                 const PlaneLossOptions& o) {
  const eval::RoofPlaneSet ref = eval::ExtractRoofPlanes(truth, eval.options.planes);
  PlaneLosses out;
  out.stage.assign(ref.planes.size(), "");
  struct Hyp {
    Eigen::Vector3d n, c;
    eval::MultiPolygon2 plan;
    eval::Box2 box;
    double area = 0;
  };
  std::vector<Hyp> hyps(hypotheses.size());
  for (size_t k = 0; k < hypotheses.size(); ++k) {
    Hyp& h = hyps[k];
    if (!PlaneOf(hypotheses[k].patch, &h.n, &h.c)) continue;
    eval::Polygon2 p;
    for (const Eigen::Vector3d& v : hypotheses[k].patch) p.outer.push_back(v.head<2>());
    h.plan = eval::MakeRegion({p});
    h.box = eval::BoundsOf(h.plan);
    h.area = eval::Area(h.plan);
  }
  const double cos_max = std::cos(o.max_angle_deg * M_PI / 180);
  for (size_t r = 0; r < ref.planes.size() && r < eval.reference_planes.size(); ++r) {
    if (eval.reference_planes[r].true_positive) continue;
    const eval::RoofPlane& rp = ref.planes[r];
    std::vector<Eigen::Vector3d> vertices;
    const Building& b = truth.buildings[rp.building];
    for (const auto& [si, pi] : rp.polygons)
      for (const Eigen::Vector3d& v : b.surfaces[si].polygons[pi].exterior) vertices.push_back(v);
    int best = -1;
    double best_cover = 0;
    for (size_t k = 0; k < hyps.size(); ++k) {
      const Hyp& h = hyps[k];
      if (!(h.area > 0) || !h.box.Intersects(rp.box) || std::abs(h.n.dot(rp.normal)) < cos_max)
        continue;
      std::vector<double> dz;
      for (const Eigen::Vector3d& v : vertices) {
        const double z =
            h.c.z() - (h.n.x() * (v.x() - h.c.x()) + h.n.y() * (v.y() - h.c.y())) / h.n.z();
        dz.push_back(std::abs(z - v.z()));
      }
      if (dz.empty()) continue;
      std::nth_element(dz.begin(), dz.begin() + dz.size() / 2, dz.end());
      if (dz[dz.size() / 2] > o.max_height_m) continue;
      const double common = eval::IntersectionArea(h.plan, rp.plan);
      const double cover = rp.plan_area > 0 ? common / rp.plan_area : 0;
      if (cover < o.min_reference_overlap && common < o.min_own_overlap * h.area) continue;
      const bool better =
          best < 0 || Rank(hypotheses[k].status) > Rank(hypotheses[best].status) ||
          (Rank(hypotheses[k].status) == Rank(hypotheses[best].status) && cover > best_cover);
      if (better) best = static_cast<int>(k), best_cover = cover;
    }
    std::string stage = "no verified hypothesis";
    if (best >= 0) {
      const PlaneHypothesisRecord& h = hypotheses[best];
      if (h.status == "built")
        stage = "built, but not matched";
      else
        stage = h.status + ": " + ReasonKind(h.reason, /*has_subject=*/h.status == "not built");
    }
    out.stage[r] = stage;
    ++out.count[stage];
    out.area_m2[stage] += rp.plan_area;
  }
  return out;
}

std::string FormatPlaneLosses(const PlaneLosses& losses) {
  std::vector<std::pair<std::string, int>> rows(losses.count.begin(), losses.count.end());
  std::stable_sort(rows.begin(), rows.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  int total = 0;
  for (const auto& [s, n] : rows) total += n;
  std::string out =
      StrFormat("Missed reference roof planes by where they were lost (%d):\n", total);
  for (const auto& [s, n] : rows)
    out += StrFormat("  %5d  %8.0f m2  %s\n", n, losses.area_m2.at(s), s.c_str());
  return out;
}

}  // namespace roofsweep
