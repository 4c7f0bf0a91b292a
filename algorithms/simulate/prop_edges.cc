#include "algorithms/simulate/prop_edges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace roofsweep {
namespace sim {

namespace {

using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

// A roof face with its plan bounds, for a quick rejection.
struct Face {
  const RoofPlane* roof;
  V2 lo, hi;
};

// Height of the highest solid surface over a plan point: the terrain or a
// roof (buildings are solid below their roofs).
double SurfaceZ(const GroundLayout& ground, const std::vector<Face>& faces, const V2& p) {
  double z = ground.HeightAt(p);
  for (const Face& f : faces) {
    if (p.x() < f.lo.x() || p.y() < f.lo.y() || p.x() > f.hi.x() || p.y() > f.hi.y()) continue;
    const Eigen::Vector4d& pl = f.roof->plane;
    // Walls and near-vertical faces have no height over a point.
    if (std::abs(pl.z()) < 0.05) continue;
    if (!f.roof->polygon.ContainsXY(p)) continue;
    z = std::max(z, -(pl.x() * p.x() + pl.y() * p.y() + pl.w()) / pl.z());
  }
  return z;
}

}  // namespace

std::vector<TrueEdge> PropEdges(const Scene& scene, const std::vector<RoofPlane>& roof_planes) {
  std::vector<Face> faces;
  for (const RoofPlane& r : roof_planes) {
    if (r.polygon.exterior.size() < 3) continue;
    Face f{&r, V2::Constant(std::numeric_limits<double>::infinity()),
           V2::Constant(-std::numeric_limits<double>::infinity())};
    for (const V3& v : r.polygon.exterior)
      f.lo = f.lo.cwiseMin(v.head<2>()), f.hi = f.hi.cwiseMax(v.head<2>());
    faces.push_back(f);
  }
  // An edge point at most this far below the surface is the box's line of
  // contact with it (a hedge's foot), which the images see; deeper, it is
  // buried (a chimney's foot, a roof window's underside 4 cm below its
  // roof). 2 cm steps keep each cut well within the 10 cm the line
  // evaluation allows.
  const double contact = 0.02, step = 0.02, min_length = 0.1;
  std::vector<TrueEdge> out;
  for (const Prop& prop : scene.props) {
    std::array<V3, 8> corner;
    for (int k = 0; k < 8; ++k) {
      const V3 s((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
      corner[k] = prop.center + prop.axes * s.cwiseProduct(prop.half);
    }
    // The twelve edges join corners that differ in one sign.
    for (int a = 0; a < 8; ++a)
      for (int bit : {1, 2, 4}) {
        const int b = a | bit;
        if (b == a) continue;
        const V3 p0 = corner[a], p1 = corner[b];
        const double len = (p1 - p0).norm();
        const int steps = std::max(1, static_cast<int>(std::ceil(len / step)));
        double run_start = -1;
        auto flush = [&](double t0, double t1) {
          if ((t1 - t0) * len < min_length) return;
          TrueEdge e;
          e.a = p0 + t0 * (p1 - p0);
          e.b = p0 + t1 * (p1 - p0);
          e.kind = EdgeKind::kProp;
          out.push_back(e);
        };
        for (int i = 0; i <= steps; ++i) {
          const double t = static_cast<double>(i) / steps;
          const V3 p = p0 + t * (p1 - p0);
          const bool open = p.z() >= SurfaceZ(scene.ground, faces, p.head<2>()) - contact;
          if (open && run_start < 0) run_start = t;
          if (!open && run_start >= 0) {
            flush(run_start, static_cast<double>(i - 1) / steps);
            run_start = -1;
          }
        }
        if (run_start >= 0) flush(run_start, 1.0);
      }
  }
  return out;
}

}  // namespace sim
}  // namespace roofsweep
