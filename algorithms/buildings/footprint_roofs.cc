#include "algorithms/buildings/footprint_roofs.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/core/format.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180;

// The plane z = h + tan(slope) (w_max - w . p): falling towards w, its
// eaves (z = h) where w . p is largest.
Eigen::Vector4d Falling(const Eigen::Vector2d& w, double w_max, double slope_deg) {
  const double k = std::tan(slope_deg * kDeg);
  // z = a x + b y + c with (a, b) = -k w, c = k w_max.
  const Eigen::Vector4d p(k * w.x(), k * w.y(), 1.0, -k * w_max);
  return p / p.head<3>().norm();
}

double MaxAlong(const Ring2& ring, const Eigen::Vector2d& w) {
  double m = -std::numeric_limits<double>::infinity();
  for (const auto& q : ring) m = std::max(m, w.dot(q));
  return m;
}

// Compass name of a plan direction (x east, y north).
const char* Towards(const Eigen::Vector2d& w) {
  static const char* const kNames[8] = {"east", "north-east", "north", "north-west",
                                        "west", "south-west", "south", "south-east"};
  const double a = std::atan2(w.y(), w.x());
  const int k = static_cast<int>(std::lround(a / (M_PI / 4))) & 7;
  return kNames[k];
}

}  // namespace

std::vector<RoofModel> RoofModelsOver(const Footprint& footprint, const RoofModelOptions& o) {
  const Ring2 hull = ConvexHull(footprint.outline);
  std::vector<RoofModel> out;
  if (hull.size() < 3) return out;
  out.push_back({"flat", {{hull, Eigen::Vector4d(0, 0, 1, 0)}}});
  // The rectangle of least area with a side along a hull edge: its sides
  // are the directions a roof over the footprint falls towards.
  Eigen::Vector2d t = Eigen::Vector2d::UnitX();
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d e = hull[(i + 1) % hull.size()] - hull[i];
    if (e.norm() < 1e-9) continue;
    const Eigen::Vector2d u = e.normalized(), v(-u.y(), u.x());
    const double area =
        (MaxAlong(hull, u) + MaxAlong(hull, -u)) * (MaxAlong(hull, v) + MaxAlong(hull, -v));
    if (area < best) best = area, t = u;
  }
  const Eigen::Vector2d n(-t.y(), t.x());
  auto big_enough = [&](const Ring2& r) {
    return r.size() >= 3 && std::abs(SignedArea(r)) >= o.min_face_m2;
  };
  for (const double s : o.shed_slopes_deg)
    for (const Eigen::Vector2d& w : {t, Eigen::Vector2d(-t), n, Eigen::Vector2d(-n)})
      out.push_back({StrFormat("shed %.0f° falling %s", s, Towards(w)),
                     {{hull, Falling(w, MaxAlong(hull, w), s)}}});
  for (const double s : o.gable_slopes_deg)
    for (const Eigen::Vector2d& across : {n, t}) {
      // The ridge halfway across; each side falls away from it.
      const double hi = MaxAlong(hull, across), lo = -MaxAlong(hull, -across);
      const double c = 0.5 * (hi + lo);
      // across . p >= c, falling towards +across; and the other side.
      const Ring2 a = ClipHalfPlane(hull, -across.x(), -across.y(), c);
      const Ring2 b = ClipHalfPlane(hull, across.x(), across.y(), -c);
      if (!big_enough(a) || !big_enough(b)) continue;
      const Eigen::Vector2d along(-across.y(), across.x());
      out.push_back({StrFormat("gable %.0f° with the ridge towards %s", s, Towards(along)),
                     {{a, Falling(across, hi, s)}, {b, Falling(-across, -lo, s)}}});
    }
  // Hipped: each side's face is where its plane lies lowest (the roof is
  // the lower envelope of the four), so its patch is the hull cut by the
  // bisectors with the other three; at one slope for all four sides the
  // patches do not depend on it.
  if (o.hip_slopes_deg.empty()) return out;
  const Eigen::Vector2d sides[4] = {t, -t, n, -n};
  double reach[4];
  for (int i = 0; i < 4; ++i) reach[i] = MaxAlong(hull, sides[i]);
  std::vector<Ring2> patches;
  for (int i = 0; i < 4; ++i) {
    Ring2 patch = hull;
    for (int j = 0; j < 4 && patch.size() >= 3; ++j) {
      if (j == i) continue;
      // Lower than face j: reach_i - w_i . p <= reach_j - w_j . p.
      const Eigen::Vector2d d = sides[j] - sides[i];
      patch = ClipHalfPlane(patch, d.x(), d.y(), reach[i] - reach[j]);
    }
    if (!big_enough(patch)) return out;
    patches.push_back(std::move(patch));
  }
  for (const double s : o.hip_slopes_deg) {
    RoofModel hip{StrFormat("hipped %.0f°", s), {}};
    for (int i = 0; i < 4; ++i) hip.faces.push_back({patches[i], Falling(sides[i], reach[i], s)});
    out.push_back(std::move(hip));
  }
  return out;
}

RoofPlaneHypothesis RoofModelFaceAt(const Footprint& footprint, const RoofModel& model, size_t face,
                                    double h) {
  const RoofModelFace& f = model.faces.at(face);
  RoofPlaneHypothesis p;
  p.plane = f.plane;
  // z + h: the plane n . X + d = 0 moves up by h when d decreases by n_z h.
  p.plane[3] -= f.plane[2] * h;
  p.patch = f.patch;
  p.derived = true;
  const Ring2& r = footprint.outline;
  for (size_t i = 0; i < r.size(); ++i)
    p.longest_line_m = std::max(p.longest_line_m, (r[(i + 1) % r.size()] - r[i]).norm());
  p.id = model.faces.size() == 1
             ? StrFormat("%s roof over footprint %s", model.name.c_str(), footprint.id.c_str())
             : StrFormat("%s roof over footprint %s, face %zu", model.name.c_str(),
                         footprint.id.c_str(), face + 1);
  return p;
}

}  // namespace roofsweep
