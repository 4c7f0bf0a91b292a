#include "algorithms/edges/line_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace roofsweep {
namespace {

constexpr double kPi = 3.14159265358979323846;

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Cosine of the angle between two vectors (1 for zero ones): a turn
// measure that, unlike atan2, costs no transcendental call per point.
double CosBetween(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const double n = std::sqrt(a.squaredNorm() * b.squaredNorm());
  return n > 0 ? a.dot(b) / n : 1.0;
}

// Index in [first, last) of the point farthest from the chord between the
// range's end points (first interior point when all are on the chord).
int FarthestFromChord(const Points2& p, int first, int last) {
  const Eigen::Vector2d a = p[first];
  Eigen::Vector2d d = p[last - 1] - a;
  const double len = d.norm();
  int best = first + (last - first) / 2;
  if (len == 0) return best;
  d /= len;
  double best_dist = -1;
  for (int i = first + 1; i < last - 1; ++i) {
    const double dist = std::fabs(Cross(d, p[i] - a));
    if (dist > best_dist) {
      best_dist = dist;
      best = i;
    }
  }
  return best;
}

// Drops up to end_trim_points points from each end of [first, last) while
// they lie more than end_trim_distance from the line through the inner
// points. Smoothing rounds corners and junctions, so the last few edge
// points before one bend away; left in, that hook looks like curvature and
// gets a straight edge split in the middle.
std::pair<int, int> TrimEnds(const Points2& p, int first, int last, const EdgeOptions& o) {
  const int k = o.end_trim_points;
  if (k <= 0 || last - first - 2 * k < std::max(2, o.min_support)) return {first, last};
  const LineFit inner = FitLine(p.data() + first + k, last - 2 * k - first);
  const Eigen::Vector2d n = inner.Normal();
  auto off = [&](int i) { return std::fabs((p[i] - inner.centroid).dot(n)); };
  // Trim from the outside in, so a far point beyond a near one still goes.
  int new_first = first;
  for (int i = first; i < first + k; ++i) {
    if (off(i) > o.end_trim_distance) new_first = i + 1;
  }
  int new_last = last;
  for (int i = last - 1; i >= last - k; --i) {
    if (off(i) > o.end_trim_distance) new_last = std::min(new_last, i);
  }
  return {new_first, new_last};
}

}  // namespace

LineFit FitLine(const Eigen::Vector2d* points, int count) {
  LineFit f;
  const double n = static_cast<double>(count);
  if (count <= 0) return f;
  for (int i = 0; i < count; ++i) f.centroid += points[i];
  f.centroid /= n;
  double sxx = 0, sxy = 0, syy = 0;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector2d& q = points[i];
    const Eigen::Vector2d e = q - f.centroid;
    sxx += e.x() * e.x();
    sxy += e.x() * e.y();
    syy += e.y() * e.y();
  }
  // The major axis of the scatter ellipse makes angle 0.5 atan2(2 sxy, sxx - syy).
  const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
  f.direction = {std::cos(angle), std::sin(angle)};
  const Eigen::Vector2d normal = f.Normal();
  double sum2 = 0;
  f.t_min = 1e300;
  f.t_max = -1e300;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector2d& q = points[i];
    const Eigen::Vector2d e = q - f.centroid;
    const double r = e.dot(normal);
    const double t = e.dot(f.direction);
    sum2 += r * r;
    f.max_deviation = std::max(f.max_deviation, std::fabs(r));
    f.t_min = std::min(f.t_min, t);
    f.t_max = std::max(f.t_max, t);
  }
  f.rms = std::sqrt(sum2 / n);
  return f;
}

bool IsCurved(const Eigen::Vector2d* points, int count, const LineFit& fit, double max_sagitta,
              double min_explained) {
  const int n = count;
  if (n < 6 || fit.Length() <= 0) return false;
  const double mid = 0.5 * (fit.t_min + fit.t_max);
  const double half = 0.5 * fit.Length();
  const Eigen::Vector2d normal = fit.Normal();
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  // Scratch kept per thread: most calls are on short pieces, where two
  // allocations would cost as much as the fit.
  thread_local std::vector<double> us, rs;
  us.resize(n);
  rs.resize(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d e = points[i] - fit.centroid;
    const double u = (e.dot(fit.direction) - mid) / half;
    const double r = e.dot(normal);
    const Eigen::Vector3d row(1, u, u * u);
    ata += row * row.transpose();
    atb += row * r;
    us[i] = u;
    rs[i] = r;
  }
  const Eigen::Matrix3d inv = ata.inverse();
  if (!inv.allFinite()) return false;
  const Eigen::Vector3d coef = inv * atb;
  const double sagitta = std::fabs(coef.z());
  if (sagitta <= max_sagitta) return false;
  double sse = 0;
  for (int i = 0; i < n; ++i) {
    const double e = rs[i] - (coef.x() + coef.y() * us[i] + coef.z() * us[i] * us[i]);
    sse += e * e;
  }
  double sse_line = 0;
  for (int i = 0; i < n; ++i) sse_line += rs[i] * rs[i];
  // An arc's residuals are a parabola; a straight edge of a real image
  // wiggles (texture, JPEG blocks, noise) and a parabola explains only part
  // of that wiggle even where its sagitta is large.
  const double explained = sse_line > 0 ? 1 - sse / sse_line : 0;
  const double se = std::sqrt(sse / (n - 3) * inv(2, 2));
  return sagitta > 3 * se && explained >= min_explained;
}

std::vector<StraightRun> SplitIntoStraightPieces(const Points2& p, const EdgeOptions& o) {
  const int n = static_cast<int>(p.size());
  const int min_support = std::max(2, o.min_support);
  std::vector<StraightRun> out;
  if (n < min_support) return out;

  // 1. Tangent discontinuities.
  std::vector<std::pair<int, int>> ranges;
  const int k = std::max(1, o.tangent_window);
  const double min_cos = std::cos(o.split_tangent_angle * kPi / 180.0);
  int start = 0;
  int i = k;
  while (i < n - k) {
    const double turn = CosBetween(p[i] - p[i - k], p[i + k] - p[i]);
    if (turn >= min_cos) {
      ++i;
      continue;
    }
    // Cut at the sharpest point of the run of over-threshold turns.
    int sharpest = i;
    double sharpest_turn = turn;
    int j = i + 1;
    for (; j < n - k; ++j) {
      const double tj = CosBetween(p[j] - p[j - k], p[j + k] - p[j]);
      if (tj >= min_cos) break;
      if (tj < sharpest_turn) {
        sharpest_turn = tj;
        sharpest = j;
      }
    }
    ranges.emplace_back(start, sharpest);
    start = sharpest + 1;
    i = j;
  }
  ranges.emplace_back(start, n);

  // 2. Recursive split.
  std::vector<std::pair<int, int>> stack(ranges.rbegin(), ranges.rend());
  while (!stack.empty()) {
    const std::pair<int, int> range = stack.back();
    stack.pop_back();
    if (range.second - range.first < min_support) continue;
    const auto [first, last] = TrimEnds(p, range.first, range.second, o);
    const LineFit fit = FitLine(p.data() + first, last - first);
    if (fit.max_deviation <= o.fit_max_deviation &&
        !IsCurved(p.data() + first, last - first, fit, o.fit_max_sagitta,
                  o.fit_curve_min_explained)) {
      out.push_back({first, last, fit});
      continue;
    }
    const int cut = FarthestFromChord(p, first, last);
    // Pushed in reverse so that pieces come out in chain order.
    stack.emplace_back(cut + 1, last);
    stack.emplace_back(first, cut);
  }
  return out;
}

}  // namespace roofsweep
