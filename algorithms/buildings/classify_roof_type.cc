#include "algorithms/buildings/classify_roof_type.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "algorithms/geometry/segment3.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Corners of a face outline: its vertices once those within merge_m of the
// last kept one are merged and those where the outline turns by less than
// min_turn_deg are dropped. The envelope leaves near-coincident and
// collinear vertices where faces were snapped together: the triangles of
// a pavilion roof came out with 5-6 vertices and edges of 0-0.1 m.
int CornerCount(const std::vector<Eigen::Vector3d>& ring, double merge_m, double min_turn_deg) {
  std::vector<Eigen::Vector3d> v;
  for (const Eigen::Vector3d& p : ring)
    if (v.empty() || (p - v.back()).norm() > merge_m) v.push_back(p);
  while (v.size() > 1 && (v.front() - v.back()).norm() <= merge_m) v.pop_back();
  const double min_cos = std::cos(min_turn_deg * kDeg);
  for (bool dropped = true; dropped && v.size() > 3;) {
    dropped = false;
    for (size_t i = 0; i < v.size() && v.size() > 3; ++i) {
      const Eigen::Vector3d a = v[i] - v[(i + v.size() - 1) % v.size()];
      const Eigen::Vector3d b = v[(i + 1) % v.size()] - v[i];
      if (a.norm() > 0 && b.norm() > 0 && a.normalized().dot(b.normalized()) >= min_cos) {
        v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
        dropped = true;
        break;
      }
    }
  }
  return static_cast<int>(v.size());
}

struct Face {
  const Polygon3* polygon = nullptr;
  double tilt_deg = 0, azimuth_deg = 0, area = 0, min_z = 0, max_z = 0;
  int corners = 0;
};

Face Describe(const Polygon3& p) {
  Face f;
  f.polygon = &p;
  f.area = p.Area();
  Eigen::Vector3d n = p.Normal();
  if (n.z() < 0) n = -n;
  f.tilt_deg = std::acos(std::clamp(n.z(), -1.0, 1.0)) / kDeg;
  f.azimuth_deg = std::atan2(n.y(), n.x()) / kDeg;
  f.min_z = std::numeric_limits<double>::infinity();
  f.max_z = -f.min_z;
  for (const Eigen::Vector3d& v : p.exterior) {
    f.min_z = std::min(f.min_z, v.z());
    f.max_z = std::max(f.max_z, v.z());
  }
  f.corners = CornerCount(p.exterior, 0.5, 15.0);
  return f;
}

double AzimuthGap(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

bool Opposite(const Face& a, const Face& b) {
  return std::abs(AzimuthGap(a.azimuth_deg, b.azimuth_deg) - 180.0) < 20.0;
}

double DistanceToRing(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& ring) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < ring.size(); ++i)
    best = std::min(best, Segment3{ring[i], ring[(i + 1) % ring.size()]}.Distance(p));
  return best;
}

// A mansard's break on one side: `upper` has the aspect of `lower`, is at
// least 20 deg shallower and starts along `lower`'s top edge (two of its
// top vertices, a metre apart or more, on `upper`'s outline). The shared
// edge keeps a shallow roof of a taller part beside a steep one apart. A
// flat upper face has no aspect (its azimuth is noise): no break.
bool BreaksInto(const Face& lower, const Face& upper) {
  if (upper.tilt_deg < 5.0) return false;
  if (AzimuthGap(lower.azimuth_deg, upper.azimuth_deg) >= 25.0) return false;
  if (lower.tilt_deg - upper.tilt_deg < 20.0) return false;
  if (upper.min_z < lower.max_z - 0.5 || upper.min_z < lower.min_z + 1.0) return false;
  std::vector<Eigen::Vector3d> shared;
  for (const Eigen::Vector3d& v : lower.polygon->exterior)
    if (v.z() >= lower.max_z - 0.5 && DistanceToRing(v, upper.polygon->exterior) <= 0.5)
      shared.push_back(v);
  for (size_t i = 0; i < shared.size(); ++i)
    for (size_t j = i + 1; j < shared.size(); ++j)
      if ((shared[i] - shared[j]).norm() >= 1.0) return true;
  return false;
}

// `big`: the faces of 5 % of the roof or more; `small`: the others of
// 0.5 m2 or more, which may be the upper faces of a small mansard (four
// 3 m2 faces on top of 15 m2 ones).
bool IsMansard(const std::vector<Face>& big, const std::vector<Face>& small) {
  std::vector<double> sides;  // azimuths of the faces that break
  for (const Face& lower : big) {
    for (const std::vector<Face>* uppers : {&big, &small})
      for (const Face& upper : *uppers)
        if (&lower != &upper && BreaksInto(lower, upper)) sides.push_back(lower.azimuth_deg);
  }
  for (size_t i = 0; i < sides.size(); ++i)
    for (size_t j = i + 1; j < sides.size(); ++j)
      if (AzimuthGap(sides[i], sides[j]) >= 155.0) return true;
  return false;
}

// An end face of a half-hip on the gable whose main faces are `a` and `b`:
// a triangle facing across them, its top at their ridge, that stops above
// their eaves by a fifth of the roof's height and 0.5 m at least (a hip's
// end face reaches the eaves).
bool IsHalfHipEnd(const Face& f, const Face& a, const Face& b) {
  const double eave = std::min(a.min_z, b.min_z);
  const double ridge = std::max(a.max_z, b.max_z);
  return f.tilt_deg >= 5.0 && f.corners == 3 &&
         std::abs(AzimuthGap(f.azimuth_deg, a.azimuth_deg) - 90.0) < 25.0 &&
         f.max_z >= ridge - 0.5 && f.min_z >= eave + std::max(0.5, 0.2 * (ridge - eave));
}

}  // namespace

int ClassifyRoofType(const std::vector<Polygon3>& roof_faces) {
  double total = 0;
  for (const Polygon3& f : roof_faces) total += f.Area();
  if (total <= 0) return roof_type::kUnknown;
  // Faces of 5 % of the roof and more; the smaller ones of 0.5 m2 and more
  // are looked at as half-hip ends and the top of a mansard only, which
  // are often smaller.
  std::vector<Face> big, small;
  for (const Polygon3& p : roof_faces) {
    const double a = p.Area();
    if (a >= 0.05 * total)
      big.push_back(Describe(p));
    else if (a >= 0.5)
      small.push_back(Describe(p));
  }
  int tilted = 0;
  for (const Face& f : big) tilted += f.tilt_deg >= 5.0;
  if (tilted == 0) return roof_type::kFlat;
  if (big.size() >= 2 && IsMansard(big, small)) return roof_type::kMansard;
  if (big.size() == 1) return roof_type::kMonopitch;
  if (tilted != static_cast<int>(big.size())) return roof_type::kCombination;

  // The two largest faces as the main faces of a gable or hipped roof.
  std::sort(big.begin(), big.end(), [](const Face& x, const Face& y) { return x.area > y.area; });
  const Face& a = big[0];
  const Face& b = big[1];
  const bool gable = Opposite(a, b);
  if (big.size() == 2) {
    if (!gable) return roof_type::kCombination;
    const bool ends = std::any_of(small.begin(), small.end(),
                                  [&](const Face& f) { return IsHalfHipEnd(f, a, b); });
    return ends ? roof_type::kHalfHipped : roof_type::kGabled;
  }
  // Half-hipped: every other face an end of the gable stopping above the
  // eaves (a missed or small second end does not change the type).
  if (gable && big.size() <= 4 &&
      std::all_of(big.begin() + 2, big.end(), [&](const Face& f) { return IsHalfHipEnd(f, a, b); }))
    return roof_type::kHalfHipped;
  if (big.size() == 4) {
    // Four slopes facing four directions roughly 90 degrees apart.
    std::vector<double> az;
    for (const Face& f : big) az.push_back(f.azimuth_deg);
    std::sort(az.begin(), az.end());
    bool quad = true;
    for (size_t k = 0; k < 4; ++k)
      quad = quad && std::abs(AzimuthGap(az[k], az[(k + 1) % 4]) - 90.0) < 25.0;
    if (quad) {
      int triangles = 0;
      for (const Face& f : big) triangles += f.corners == 3;
      // Four faces at right angles without end triangles are hipped too,
      // though a cross gable (an L or T-shaped house) has them: asking for
      // the triangles cost 14 of 38 hipped roofs from matched lines, whose
      // ends the envelope leaves as quadrilaterals.
      return triangles == 4 ? roof_type::kPavilion : roof_type::kHipped;
    }
  }
  return roof_type::kCombination;
}

}  // namespace roofsweep
