#include "algorithms/matching/view_support.h"

#include <algorithm>
#include <cmath>

#include "algorithms/matching/epipolar.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Mean over the projection of the strongest L* gradient within 1 px across it.
double GradientAlong(const ViewFeatures& v, const Segment2D& proj) {
  const Eigen::Vector2d d = proj.Direction(), n(-d.y(), d.x());
  const int steps = static_cast<int>(proj.Length());
  double sum = 0;
  int cnt = 0;
  for (int k = 0; k < steps; ++k) {
    double best = 0;
    bool any = false;
    for (double off : {-1.0, 0.0, 1.0}) {
      const Eigen::Vector2d p = v.ToImage(proj.p0 + (k + 0.5) * d + off * n);
      float g;
      if (SampleBilinear(v.gradient, p, &g)) {
        best = std::max(best, static_cast<double>(g));
        any = true;
      }
    }
    if (any) {
      sum += best;
      ++cnt;
    }
  }
  return cnt > 0 ? sum / cnt : 0;
}

}  // namespace

bool ViewSupport::Accepted(const MatchOptions& o) const {
  const double support = supporting + 0.5 * gradient_only;
  return seeing == 0 || (supporting >= std::min(o.min_support_segments, seeing) &&
                         support >= std::max(1.0, o.min_support_fraction * seeing));
}

int SupportingSegment(const ViewFeatures& v, const Segment2D& proj, const MatchOptions& o) {
  const Eigen::Vector2d d = proj.Direction(), n(-d.y(), d.x());
  const double len = proj.Length(), cos_max = std::cos(o.verify_max_angle * kDeg);
  int best = -1;
  double best_overlap = 0;
  for (int id : v.index->Near(proj, o.verify_distance)) {
    const Segment2D& s = v.ideal[id];
    if (s.Length() < 0.5 * o.min_length) continue;
    if (std::abs(s.Direction().dot(d)) < cos_max) continue;
    if (std::abs((s.p0 - proj.p0).dot(n)) > o.verify_distance ||
        std::abs((s.p1 - proj.p0).dot(n)) > o.verify_distance)
      continue;
    const double u0 = (s.p0 - proj.p0).dot(d), u1 = (s.p1 - proj.p0).dot(d);
    const double overlap = std::min(len, std::max(u0, u1)) - std::max(0.0, std::min(u0, u1));
    if (overlap > best_overlap) {
      best_overlap = overlap;
      best = id;
    }
  }
  return best_overlap >= std::min(o.verify_min_length, 0.5 * len) ? best : -1;
}

// Ideal coordinates are taken as image coordinates here: distortion only
// moves the border slightly.
bool ClipToImage(const ViewFeatures& v, Eigen::Vector2d* a, Eigen::Vector2d* b) {
  double t0 = 0, t1 = 1;
  const Eigen::Vector2d d = *b - *a;
  const double lo[2] = {0, 0},
               hi[2] = {static_cast<double>(v.lab.cols), static_cast<double>(v.lab.rows)};
  for (int k = 0; k < 2; ++k) {
    if (std::abs(d[k]) < 1e-12) {
      if ((*a)[k] < lo[k] || (*a)[k] > hi[k]) return false;
      continue;
    }
    double ta = (lo[k] - (*a)[k]) / d[k], tb = (hi[k] - (*a)[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (t0 >= t1) return false;
  const Eigen::Vector2d a0 = *a;
  *a = a0 + t0 * d;
  *b = a0 + t1 * d;
  return true;
}

ViewSupport SupportInViews(const std::vector<ViewFeatures>& views, const Segment3& line,
                           const std::vector<int>& exclude, const MatchOptions& o) {
  ViewSupport vs;
  for (int k = 0; k < static_cast<int>(views.size()); ++k) {
    if (std::find(exclude.begin(), exclude.end(), k) != exclude.end()) continue;
    auto a = ProjectIdeal(views[k], line.a), b = ProjectIdeal(views[k], line.b);
    if (!a || !b) continue;
    Eigen::Vector2d pa = *a, pb = *b;
    if (!ClipToImage(views[k], &pa, &pb) || (pb - pa).norm() < o.verify_min_length) continue;
    ++vs.seeing;
    Segment2D proj;
    proj.p0 = pa;
    proj.p1 = pb;
    const int sup = SupportingSegment(views[k], proj, o);
    if (sup >= 0) {
      vs.segments.emplace_back(k, sup);
      ++vs.supporting;
    } else if (o.verify_min_gradient > 0 &&
               GradientAlong(views[k], proj) >= o.verify_min_gradient) {
      ++vs.gradient_only;
    }
  }
  return vs;
}

}  // namespace roofsweep
