#include "algorithms/matching/epipolar.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace roofsweep {
namespace {
constexpr double kDeg = M_PI / 180.0;

Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

Eigen::Vector3d Line(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.homogeneous().cross(b.homogeneous());
}
}  // namespace

PairGeometry MakePairGeometry(const ViewFeatures& vi, const ViewFeatures& vj) {
  PairGeometry g;
  const Eigen::Vector3d t = vj.pose.R * (vi.pose.C - vj.pose.C);
  if (t.norm() < 1e-9) return g;
  const Eigen::Matrix3d R = vj.pose.R * vi.pose.R.transpose();
  const Eigen::Matrix3d Ki = vi.camera->K(), Kj = vj.camera->K();
  g.F = Kj.inverse().transpose() * Skew(t) * R * Ki.inverse();
  g.e_i = vi.P * vj.pose.C.homogeneous();
  g.e_j = vj.P * vi.pose.C.homogeneous();
  g.valid = true;
  return g;
}

Eigen::Vector2d EpipolarDirection(const Eigen::Vector3d& e, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d(e.x() - e.z() * p.x(), e.y() - e.z() * p.y());
  const double n = d.norm();
  return n > 0 ? Eigen::Vector2d(d / n) : Eigen::Vector2d(1, 0);
}

double EpipolarAngle(const Eigen::Vector3d& e, const Segment2D& s) {
  const Eigen::Vector2d d = EpipolarDirection(e, s.Midpoint());
  const double c = std::min(1.0, std::abs(d.dot(s.Direction())));
  return std::acos(c) / kDeg;
}

WorldRay RayThrough(const ViewFeatures& v, const Eigen::Vector2d& p) {
  const Eigen::Vector3d n = v.camera->K().inverse() * p.homogeneous();
  return {v.pose.C, v.pose.R.transpose() * n};
}

Eigen::Vector4d BackProjectLine(const ViewFeatures& v, const Eigen::Vector2d& a,
                                const Eigen::Vector2d& b) {
  return v.P.transpose() * Line(a, b);
}

std::optional<Eigen::Vector3d> IntersectPlane(const WorldRay& r, const Eigen::Vector4d& pl) {
  const double den = pl.head<3>().dot(r.direction);
  const double num = -(pl.head<3>().dot(r.origin) + pl.w());
  if (std::abs(den) < 1e-12 * pl.head<3>().norm() * r.direction.norm()) return std::nullopt;
  return Eigen::Vector3d(r.origin + (num / den) * r.direction);
}

std::optional<Eigen::Vector2d> ProjectIdeal(const ViewFeatures& v, const Eigen::Vector3d& X) {
  const Eigen::Vector3d x = v.P * X.homogeneous();
  if (!(x.z() > 0)) return std::nullopt;
  return Eigen::Vector2d(x.head<2>() / x.z());
}

std::optional<SceneHeights> SceneHeightRange(const Block& block, double margin) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  if (block.ground.grid) {
    for (float z : block.ground.grid->z)
      if (std::isfinite(z)) {
        lo = std::min<double>(lo, z);
        hi = std::max<double>(hi, z);
      }
  }
  if (block.ground.height) {
    lo = std::min(lo, *block.ground.height);
    hi = std::max(hi, *block.ground.height);
  }
  if (!std::isfinite(lo)) return std::nullopt;
  SceneHeights h;
  h.lo = lo - margin;
  h.hi = hi + block.max_building_height + margin;
  h.ground = &block.ground;
  h.above = block.max_building_height;
  h.margin = margin;
  return h;
}

bool SceneHeights::Contains(const Eigen::Vector3d& X) const {
  if (!(X.z() >= lo && X.z() <= hi)) return false;
  const double g = ground ? ground->HeightAt(X.x(), X.y()) : NAN;
  return !std::isfinite(g) || (X.z() >= g - margin && X.z() <= g + above + margin);
}

bool SceneHeights::Clip(Segment3* s, double step_m) const {
  if (Contains(s->a) && Contains(s->b)) return true;
  const int n = std::max(1, static_cast<int>(std::ceil(s->Length() / step_m)));
  auto at = [&](int i) -> Eigen::Vector3d { return s->a + (s->b - s->a) * (double(i) / n); };
  int first = 0, last = n;
  while (first <= n && !Contains(at(first))) ++first;
  if (first > n) return false;
  while (last > first && !Contains(at(last))) --last;
  const Eigen::Vector3d a = at(first), b = at(last);
  s->a = a;
  s->b = b;
  return true;
}

std::optional<Eigen::Vector2d> EpipolarTransfer(const PairGeometry& g, const Eigen::Vector2d& p,
                                                const Segment2D& t) {
  const Eigen::Vector3d l = g.F * p.homogeneous();
  const Eigen::Vector3d x = Line(t.p0, t.p1).cross(l);
  if (std::abs(x.z()) < 1e-12 * x.head<2>().norm()) return std::nullopt;
  return Eigen::Vector2d(x.head<2>() / x.z());
}

std::vector<PairHypothesis> GeometricCandidates(const ViewFeatures& vi, const ViewFeatures& vj,
                                                int i_index, int j_index, const PairGeometry& g,
                                                int si, const std::optional<SceneHeights>& z_range,
                                                const MatchOptions& o) {
  std::vector<PairHypothesis> out;
  const Segment2D& s = vi.ideal[si];
  const double len = s.Length();
  if (len < o.min_length || !g.valid) return out;
  if (EpipolarAngle(g.e_i, s) < o.min_epipolar_angle) return out;

  // Region of view j the strip can reach within the height range.
  Eigen::Vector2d lo(0, 0), hi(vj.lab.cols, vj.lab.rows);
  if (z_range) {
    Eigen::Vector2d blo(1e300, 1e300), bhi(-1e300, -1e300);
    bool ok = true;
    for (const Eigen::Vector2d& p : {s.p0, s.p1}) {
      const WorldRay r = RayThrough(vi, p);
      for (double z : {z_range->lo, z_range->hi}) {
        const auto X = IntersectPlane(r, Eigen::Vector4d(0, 0, 1, -z));
        const auto x = X ? ProjectIdeal(vj, *X) : std::nullopt;
        if (!X || (*X - r.origin).dot(r.direction) <= 0 || !x) {
          ok = false;
          continue;
        }
        blo = blo.cwiseMin(*x);
        bhi = bhi.cwiseMax(*x);
      }
    }
    if (ok) {
      lo = lo.cwiseMax((blo.array() - 2.0).matrix());
      hi = hi.cwiseMin((bhi.array() + 2.0).matrix());
    }
  }
  if (lo.x() > hi.x() || lo.y() > hi.y()) return out;

  const Eigen::Vector4d plane_i = BackProjectLine(vi, s.p0, s.p1);
  const Eigen::Vector3d line_i = Line(s.p0, s.p1);
  const double cos_max = std::cos(o.max_angle_deviation * kDeg);
  for (int sj : vj.index->InBox(lo, hi)) {
    const Segment2D& t = vj.ideal[sj];
    if (t.Length() < o.min_length) continue;
    if (std::abs(t.Direction().dot(s.Direction())) < cos_max) continue;
    if (EpipolarAngle(g.e_j, t) < o.min_epipolar_angle) continue;
    // Parameters on s of the points corresponding to t's endpoints.
    double lam[2];
    bool ok = true;
    for (int k = 0; k < 2; ++k) {
      const Eigen::Vector3d l = g.F.transpose() * (k == 0 ? t.p0 : t.p1).homogeneous();
      const Eigen::Vector3d x = line_i.cross(l);
      if (std::abs(x.z()) < 1e-12) {
        ok = false;
        break;
      }
      const Eigen::Vector2d q = x.head<2>() / x.z();
      lam[k] = (q - s.p0).dot(s.p1 - s.p0) / (len * len);
    }
    if (!ok) continue;
    PairHypothesis h;
    h.vi = i_index;
    h.vj = j_index;
    h.si = si;
    h.sj = sj;
    h.reversed = lam[0] > lam[1];
    h.la = std::max(0.0, std::min(lam[0], lam[1]));
    h.lb = std::min(1.0, std::max(lam[0], lam[1]));
    if ((h.lb - h.la) * len < o.min_common_length) continue;
    // 3D common part: rays of view i's common part against t's plane.
    const Eigen::Vector4d plane_j = BackProjectLine(vj, t.p0, t.p1);
    (void)plane_i;
    Eigen::Vector3d X[2];
    for (int k = 0; k < 2; ++k) {
      const Eigen::Vector2d p = s.p0 + (k == 0 ? h.la : h.lb) * (s.p1 - s.p0);
      const WorldRay r = RayThrough(vi, p);
      const auto Xk = IntersectPlane(r, plane_j);
      if (!Xk || (*Xk - r.origin).dot(r.direction) <= 0 ||
          (vj.pose.R * (*Xk - vj.pose.C)).z() <= 0) {
        ok = false;
        break;
      }
      if (z_range && !z_range->Contains(*Xk)) {
        ok = false;
        break;
      }
      X[k] = *Xk;
    }
    if (!ok) continue;
    h.line.a = X[0];
    h.line.b = X[1];
    out.push_back(h);
  }
  return out;
}

}  // namespace roofsweep
