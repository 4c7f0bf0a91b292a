#include "algorithms/geometry/block_overview.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

namespace roofsweep {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

// Point nearest (least squares) to all optical axes; empty when the axes are
// (nearly) parallel, as in a nadir block, where it is ill-defined.
bool NearestPointToAxes(const Block& block, Eigen::Vector3d* point) {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const View& v : block.views) {
    const Eigen::Vector3d d = v.pose.ViewingDirection();
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - d * d.transpose();
    A += P;
    b += P * v.pose.C;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(A);
  if (block.views.size() < 2 || es.eigenvalues()(0) < 1e-3 * es.eigenvalues()(2)) return false;
  *point = A.ldlt().solve(b);
  return true;
}

// The convergence point is a scene only if it lies in front of every camera,
// farther than half the spread of the cameras (else the axes diverge and
// merely pass close to each other near the cameras).
bool InFrontOfAll(const Block& block, const Eigen::Vector3d& p) {
  double spread = 0;
  for (const View& a : block.views)
    for (const View& b : block.views) spread = std::max(spread, (a.pose.C - b.pose.C).norm());
  for (const View& v : block.views) {
    if (v.pose.ToCamera(p).z() < 0.5 * spread) return false;
  }
  return true;
}

// Orthonormal 2D coordinates on the plane, for polygon overlap.
struct PlaneBasis {
  Eigen::Vector3d origin, u, v;
  cv::Point2f To2D(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d d = p - origin;
    return {static_cast<float>(d.dot(u)), static_cast<float>(d.dot(v))};
  }
};

PlaneBasis MakeBasis(const Eigen::Vector4d& plane, const Eigen::Vector3d& near) {
  const Eigen::Vector3d n = plane.head<3>();
  PlaneBasis b;
  b.origin = near - (n.dot(near) + plane(3)) * n;
  b.u = n.unitOrthogonal();
  b.v = n.cross(b.u);
  return b;
}

std::optional<Eigen::Vector3d> Intersect(const Ray& r, const Eigen::Vector4d& plane) {
  const double denom = plane.head<3>().dot(r.direction);
  if (std::abs(denom) < 1e-12) return std::nullopt;
  const double t = -(plane.head<3>().dot(r.origin) + plane(3)) / denom;
  if (!(t > 0)) return std::nullopt;
  return r.origin + t * r.direction;
}

}  // namespace

std::optional<std::string> SurfaceModelWarning(const GroundModel& ground, double min_step_m,
                                               double min_share) {
  if (!ground.grid) return std::nullopt;
  const GroundModel::Grid& g = *ground.grid;
  const double step = std::max(min_step_m, std::tan(60.0 / kRadToDeg) * std::min(g.dx, g.dy));
  long long pairs = 0, steps = 0;
  auto pair = [&](float a, float b) {
    if (!std::isfinite(a) || !std::isfinite(b)) return;
    ++pairs;
    steps += std::abs(a - b) > step;
  };
  for (int r = 0; r < g.rows; ++r) {
    const float* row = g.z.data() + static_cast<size_t>(r) * g.cols;
    for (int c = 0; c < g.cols; ++c) {
      if (c + 1 < g.cols) pair(row[c], row[c + 1]);
      if (r + 1 < g.rows) pair(row[c], row[c + g.cols]);
    }
  }
  if (pairs == 0 || steps <= min_share * static_cast<double>(pairs)) return std::nullopt;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "the DTM looks like a surface model: %.1f %% of neighbouring cells differ by more "
                "than %.1f m (walls, trees); roof lines would count as ground lines and walls "
                "would end at roof level: give a bare-earth DTM or a ground height",
                100.0 * static_cast<double>(steps) / static_cast<double>(pairs), step);
  return std::string(buf);
}

BlockOverview AnalyzeBlock(const Block& block, const BlockOverviewOptions& options) {
  BlockOverview out;
  if (const auto w = SurfaceModelWarning(block.ground)) out.warnings.push_back(*w);
  if (block.views.empty()) return out;

  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const View& v : block.views) centre += v.pose.C;
  centre /= static_cast<double>(block.views.size());

  if (block.ground.Known()) {
    const double z = block.ground.HeightAt(centre.x(), centre.y());
    out.plane = Eigen::Vector4d(0, 0, 1, -z);
    out.plane_is_ground = true;
  } else {
    Eigen::Vector3d mean_dir = Eigen::Vector3d::Zero();
    for (const View& v : block.views) mean_dir += v.pose.ViewingDirection();
    Eigen::Vector3d p;
    if (!NearestPointToAxes(block, &p) || !InFrontOfAll(block, p)) {
      // Parallel or diverging axes (nadir strips, drones looking outwards):
      // nothing tells the scene depth, and a guess would print a wrong GSD.
      out.warnings.push_back(
          "ground unknown and the optical axes do not converge on a scene: GSD and overlaps not "
          "computed (give a ground height or DTM)");
      out.footprints.resize(block.views.size());
      return out;
    }
    const Eigen::Vector3d n = -mean_dir.normalized();  // facing the cameras
    out.plane = Eigen::Vector4d(n.x(), n.y(), n.z(), -n.dot(p));
  }
  const Eigen::Vector3d n = out.plane.head<3>();
  const PlaneBasis basis = MakeBasis(out.plane, centre);

  std::vector<std::vector<cv::Point2f>> polys(block.views.size());
  for (size_t i = 0; i < block.views.size(); ++i) {
    const View& view = block.views[i];
    const Camera& cam = block.CameraOf(view);
    ViewFootprint& fp = out.footprints.emplace_back();
    fp.height_above_plane_m = n.dot(view.pose.C) + out.plane(3);
    fp.off_nadir_deg =
        std::acos(std::clamp(-n.dot(view.pose.ViewingDirection()), -1.0, 1.0)) * kRadToDeg;
    if (fp.height_above_plane_m <= 0) {
      out.warnings.push_back("image '" + view.name + "': camera is " +
                             (out.plane_is_ground ? "below the ground" : "behind the scene plane") +
                             " (" + std::to_string(fp.height_above_plane_m) + " m)");
      continue;
    }
    // GSD where the optical axis meets the plane: a one-pixel step there.
    const Eigen::Vector2d pp(cam.cx, cam.cy);
    const auto g0 = Intersect(BackProject(cam, view.pose, pp), out.plane);
    const auto g1 = Intersect(BackProject(cam, view.pose, pp + Eigen::Vector2d(1, 0)), out.plane);
    const auto g2 = Intersect(BackProject(cam, view.pose, pp + Eigen::Vector2d(0, 1)), out.plane);
    if (g0 && g1 && g2) {
      fp.gsd_m = std::sqrt((*g1 - *g0).norm() * (*g2 - *g0).norm());
      fp.distance_m = (*g0 - view.pose.C).norm();
    }
    // Footprint: border rays, each cut at max range.
    const double max_range = options.max_range_factor * fp.height_above_plane_m;
    std::vector<cv::Point2f> pts;
    const int s = std::max(2, options.border_samples);
    for (int side = 0; side < 4; ++side) {
      for (int k = 0; k < s; ++k) {
        const double t = static_cast<double>(k) / s;
        const double W = cam.width, H = cam.height;
        const Eigen::Vector2d px = side == 0   ? Eigen::Vector2d(t * W, 0)
                                   : side == 1 ? Eigen::Vector2d(W, t * H)
                                   : side == 2 ? Eigen::Vector2d(W - t * W, H)
                                               : Eigen::Vector2d(0, H - t * H);
        const Ray r = BackProject(cam, view.pose, px);
        auto hit = Intersect(r, out.plane);
        if (!hit || (*hit - r.origin).norm() > max_range) {
          // Beyond the horizon or too far: clip where the ray passes max range.
          const Eigen::Vector3d far = r.origin + r.direction * max_range;
          hit = far - (n.dot(far) + out.plane(3)) * n;
        }
        pts.push_back(basis.To2D(*hit));
      }
    }
    std::vector<cv::Point2f> hull;
    cv::convexHull(pts, hull);
    fp.area_m2 = cv::contourArea(hull);
    fp.valid = hull.size() >= 3 && fp.area_m2 > 0;
    for (const auto& p : hull) {
      fp.outline.push_back(basis.origin + basis.u * p.x + basis.v * p.y);
    }
    polys[i] = hull;
  }

  std::vector<int> degree(block.views.size(), 0);
  for (size_t a = 0; a < block.views.size(); ++a) {
    for (size_t b = a + 1; b < block.views.size(); ++b) {
      if (!out.footprints[a].valid || !out.footprints[b].valid) continue;
      std::vector<cv::Point2f> inter;
      const float area = cv::intersectConvexConvex(polys[a], polys[b], inter, true);
      const double smaller = std::min(out.footprints[a].area_m2, out.footprints[b].area_m2);
      const double f = smaller > 0 ? area / smaller : 0;
      if (f > options.min_overlap) {
        out.overlaps.push_back({static_cast<int>(a), static_cast<int>(b), f});
        ++degree[a];
        ++degree[b];
      }
    }
  }
  if (block.views.size() > 1) {
    for (size_t i = 0; i < block.views.size(); ++i) {
      if (degree[i] == 0 && out.footprints[i].valid) {
        out.warnings.push_back("image '" + block.views[i].name + "' overlaps no other image");
      }
    }
  }
  return out;
}

}  // namespace roofsweep
