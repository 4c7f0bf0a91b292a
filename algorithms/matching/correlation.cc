#include "algorithms/matching/correlation.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

namespace roofsweep {
namespace {

// NCC from the centred sums of squares and products of n samples.
double NccFromMoments(double n, double saa, double sbb, double sab) {
  // Quantisation-level variance is no texture to correlate.
  if (saa < 1e-6 * n || sbb < 1e-6 * n) return 0;
  return sab / std::sqrt(saa * sbb);
}

}  // namespace

double Ncc(const float* a, const float* b, int n) {
  if (n < 2) return 0;
  double sa = 0, sb = 0;
  for (int i = 0; i < n; ++i) {
    sa += a[i];
    sb += b[i];
  }
  const double ma = sa / n, mb = sb / n;
  double saa = 0, sbb = 0, sab = 0;
  for (int i = 0; i < n; ++i) {
    const double da = a[i] - ma, db = b[i] - mb;
    saa += da * da;
    sbb += db * db;
    sab += da * db;
  }
  return NccFromMoments(n, saa, sbb, sab);
}

namespace {

struct Strip {
  int cols = 0, rows = 0;
  // Bands (a*, b*, L*) or (L*, L*, L*); b3 is empty unless
  // MatchOptions::correlate_lightness.
  std::vector<float> b1, b2, b3;
  std::vector<char> valid;
};

// Per column u, the epipolar direction at p(u) scaled to unit distance
// across the segment; zero where it runs nearly along the segment (no
// usable area). The same for every scale tried, so computed once per side.
std::vector<Eigen::Vector2d> AcrossSteps(const std::vector<Eigen::Vector2d>& pts,
                                         const Eigen::Vector2d& normal,
                                         const Eigen::Vector3d& epipole) {
  std::vector<Eigen::Vector2d> steps(pts.size(), Eigen::Vector2d::Zero());
  for (size_t u = 0; u < pts.size(); ++u) {
    Eigen::Vector2d d = EpipolarDirection(epipole, pts[u]);
    double c = d.dot(normal);
    if (c < 0) {
      d = -d;
      c = -c;
    }
    if (c >= 0.2) steps[u] = d / c;
  }
  return steps;
}

void ResetStrip(int cols, const MatchOptions& o, Strip* st) {
  st->cols = cols;
  st->rows = std::max(1, static_cast<int>(std::lround(o.region_width)));
  st->b1.assign(st->cols * st->rows, 0.f);
  st->b2.assign(st->cols * st->rows, 0.f);
  if (o.correlate_lightness)
    st->b3.assign(st->cols * st->rows, 0.f);
  else
    st->b3.clear();
  st->valid.assign(st->cols * st->rows, 0);
}

// Stores a sample at strip index idx: a*, b*, L* (L* thrice in a grey view),
// unless its L* lies outside the side's inlier band [lo, hi].
void Store(const ViewFeatures& v, const SideColour& attr, double lo, double hi, const float* lab,
           int idx, Strip* st) {
  if (attr.valid && (lab[0] < lo || lab[0] > hi)) return;
  st->b1[idx] = v.grey ? lab[0] : lab[1];
  st->b2[idx] = v.grey ? lab[0] : lab[2];
  if (!st->b3.empty()) st->b3[idx] = lab[0];
  st->valid[idx] = 1;
}

// Samples the parallelogram of one side: column u at point p(u) on the
// segment, row m at perpendicular distance offset + 0.5 + m, stepping along
// the epipolar direction. Columns stop at another contour.
void SampleSide(const ViewFeatures& v, const std::vector<Eigen::Vector2d>& pts,
                const std::vector<Eigen::Vector2d>& across, int seg_id, const SideColour& attr,
                const MatchOptions& o, Strip* st) {
  ResetStrip(static_cast<int>(pts.size()), o, st);
  const double lo = attr.l_location - o.l_outlier_sigmas * attr.l_scale;
  const double hi = attr.l_location + o.l_outlier_sigmas * attr.l_scale;
  for (int u = 0; u < st->cols; ++u) {
    if (across[u].x() == 0 && across[u].y() == 0) continue;
    const Eigen::Vector2d& step = across[u];
    for (int m = 0; m < st->rows; ++m) {
      const Eigen::Vector2d p = v.ToImage(pts[u] + (o.region_offset + 0.5 + m) * step);
      if (!v.Inside(p)) break;
      const int l = v.labels.at<int>(static_cast<int>(p.y()), static_cast<int>(p.x()));
      if (l >= 0 && l != seg_id) break;
      float lab[3];
      if (!SampleBilinear(v.lab, p, lab)) break;
      Store(v, attr, lo, hi, lab, m * st->cols + u, st);
    }
  }
}

// The second view's side, sampled once for all scales: per column, L*a*b*
// at distances t0, t0 + dt, ... along the epipolar step up to the farthest
// row of the largest scale, and how far the column reaches before another
// contour or the image border. Each scale's rows then interpolate between
// these (the scale search reads the image once instead of scale_steps
// times).
struct FineColumns {
  double t0 = 0, dt = 0.5;
  int samples = 0;
  std::vector<float> lab;  // [u][k][3]
  std::vector<int> reach;  // per column: samples before the first contour
};

void SampleFine(const ViewFeatures& v, const std::vector<Eigen::Vector2d>& pts,
                const std::vector<Eigen::Vector2d>& across, int seg_id, double t_min, double t_max,
                FineColumns* fc) {
  fc->t0 = t_min;
  fc->samples = static_cast<int>(std::ceil((t_max - t_min) / fc->dt)) + 2;
  const int cols = static_cast<int>(pts.size());
  fc->lab.assign(static_cast<size_t>(cols) * fc->samples * 3, 0.f);
  fc->reach.assign(cols, 0);
  for (int u = 0; u < cols; ++u) {
    if (across[u].x() == 0 && across[u].y() == 0) continue;
    for (int k = 0; k < fc->samples; ++k) {
      const Eigen::Vector2d p = v.ToImage(pts[u] + (fc->t0 + k * fc->dt) * across[u]);
      if (!v.Inside(p)) break;
      const int l = v.labels.at<int>(static_cast<int>(p.y()), static_cast<int>(p.x()));
      if (l >= 0 && l != seg_id) break;
      if (!SampleBilinear(v.lab, p, &fc->lab[(static_cast<size_t>(u) * fc->samples + k) * 3]))
        break;
      fc->reach[u] = k + 1;
    }
  }
}

// SampleSide's strip at one scale, from the fine columns.
void StripFromFine(const FineColumns& fc, const ViewFeatures& v, double scale,
                   const SideColour& attr, const MatchOptions& o, Strip* st) {
  ResetStrip(static_cast<int>(fc.reach.size()), o, st);
  const double lo = attr.l_location - o.l_outlier_sigmas * attr.l_scale;
  const double hi = attr.l_location + o.l_outlier_sigmas * attr.l_scale;
  for (int u = 0; u < st->cols; ++u) {
    const float* col = &fc.lab[static_cast<size_t>(u) * fc.samples * 3];
    for (int m = 0; m < st->rows; ++m) {
      const double x = ((o.region_offset + 0.5 + m) * scale - fc.t0) / fc.dt;
      const int k = static_cast<int>(std::floor(x));
      if (k < 0 || k + 1 >= fc.reach[u]) break;
      const float f = static_cast<float>(x - k);
      float lab[3];
      for (int c = 0; c < 3; ++c)
        lab[c] = col[k * 3 + c] + f * (col[(k + 1) * 3 + c] - col[k * 3 + c]);
      Store(v, attr, lo, hi, lab, m * st->cols + u, st);
    }
  }
}

}  // namespace

double SideCorrelation(const ViewFeatures& vi, const ViewFeatures& vj, const PairGeometry& g,
                       const PairHypothesis& h, int side, const MatchOptions& o) {
  const Segment2D& s = vi.ideal[h.si];
  const Segment2D& t = vj.ideal[h.sj];
  const double len = (h.lb - h.la) * s.Length();
  const int n = std::max(2, static_cast<int>(len / o.sample_step) + 1);
  std::vector<Eigen::Vector2d> pi, pj;
  pi.reserve(n);
  pj.reserve(n);
  for (int k = 0; k < n; ++k) {
    const double lam = h.la + (h.lb - h.la) * (k + 0.5) / n;
    const Eigen::Vector2d p = s.p0 + lam * (s.p1 - s.p0);
    const auto q = EpipolarTransfer(g, p, t);
    if (!q) return -9;
    pi.push_back(p);
    pj.push_back(*q);
  }
  const int side_i = side == 0 ? 1 : -1;
  const int side_j = h.reversed ? -side_i : side_i;
  const Eigen::Vector2d ni = s.LeftNormal() * side_i;
  const Eigen::Vector2d nj = t.LeftNormal() * side_j;
  const SideColour& ai = vi.sides[h.si][side];
  const SideColour& aj = vj.sides[h.sj][(side_j == side_i) ? side : 1 - side];
  Strip a, b;
  SampleSide(vi, pi, AcrossSteps(pi, ni, g.e_i), h.si, ai, o, &a);
  const std::vector<Eigen::Vector2d> across_j = AcrossSteps(pj, nj, g.e_j);
  const int rows = std::max(1, static_cast<int>(std::lround(o.region_width)));
  FineColumns fine;
  const double widest = std::max(o.max_scale, 1.0 / o.max_scale);
  SampleFine(vj, pj, across_j, h.sj, (o.region_offset + 0.5) / widest,
             (o.region_offset + 0.5 + rows - 1) * widest, &fine);
  const int half = std::max(1, static_cast<int>(std::lround(o.ncc_window / o.sample_step / 2)));
  const bool grey = vi.grey || vj.grey;
  // Per column the sums of both bands over the rows valid in both strips,
  // accumulated over the columns: each window's sums are then a difference
  // (the windows overlap by half, and the gather into per-window arrays
  // cost more than the correlation itself).
  enum {
    kN,
    kX1,
    kY1,
    kX1X1,
    kY1Y1,
    kX1Y1,
    kX2,
    kY2,
    kX2X2,
    kY2Y2,
    kX2Y2,
    kX3,
    kY3,
    kX3X3,
    kY3Y3,
    kX3Y3,
    kSums
  };
  const bool with_l = o.correlate_lightness;
  auto ncc = [](double n, double sx, double sy, double sxx, double syy, double sxy) {
    return NccFromMoments(n, sxx - sx * sx / n, syy - sy * sy / n, sxy - sx * sy / n);
  };
  std::vector<std::array<double, kSums>> prefix(a.cols + 1);
  double best = -9;
  const int steps = std::max(1, o.scale_steps);
  for (int k = 0; k < steps; ++k) {
    // Geometric series from 1/max_scale to max_scale.
    const double e = steps == 1 ? 0.0 : -1.0 + 2.0 * k / (steps - 1);
    const double scale = std::pow(o.max_scale, e);
    StripFromFine(fine, vj, scale, aj, o, &b);
    prefix[0].fill(0.0);
    for (int w = 0; w < a.cols; ++w) {
      std::array<double, kSums> c{};
      for (int m = 0; m < a.rows; ++m) {
        const int idx = m * a.cols + w;
        if (!a.valid[idx] || !b.valid[idx]) continue;
        const double x1 = a.b1[idx], y1 = b.b1[idx], x2 = a.b2[idx], y2 = b.b2[idx];
        c[kN] += 1;
        c[kX1] += x1, c[kY1] += y1, c[kX1X1] += x1 * x1, c[kY1Y1] += y1 * y1, c[kX1Y1] += x1 * y1;
        c[kX2] += x2, c[kY2] += y2, c[kX2X2] += x2 * x2, c[kY2Y2] += y2 * y2, c[kX2Y2] += x2 * y2;
        if (with_l) {
          const double x3 = a.b3[idx], y3 = b.b3[idx];
          c[kX3] += x3, c[kY3] += y3, c[kX3X3] += x3 * x3, c[kY3Y3] += y3 * y3, c[kX3Y3] += x3 * y3;
        }
      }
      for (int q = 0; q < kSums; ++q) prefix[w + 1][q] = prefix[w][q] + c[q];
    }
    double sum = 0;
    int windows = 0;
    for (int u = 0; u < a.cols; u += std::max(1, half)) {
      const auto& hi = prefix[std::min(a.cols - 1, u + half) + 1];
      const auto& lo = prefix[std::max(0, u - half)];
      double t[kSums];
      for (int q = 0; q < kSums; ++q) t[q] = hi[q] - lo[q];
      if (t[kN] < 10) continue;
      const double c1 = ncc(t[kN], t[kX1], t[kY1], t[kX1X1], t[kY1Y1], t[kX1Y1]);
      if (grey) {
        sum += 2.0 * c1;
      } else if (with_l) {
        sum += (2.0 / 3.0) * (c1 + ncc(t[kN], t[kX2], t[kY2], t[kX2X2], t[kY2Y2], t[kX2Y2]) +
                              ncc(t[kN], t[kX3], t[kY3], t[kX3X3], t[kY3Y3], t[kX3Y3]));
      } else {
        sum += c1 + ncc(t[kN], t[kX2], t[kY2], t[kX2X2], t[kY2Y2], t[kX2Y2]);
      }
      ++windows;
    }
    if (windows > 0) best = std::max(best, sum / windows);
  }
  return best;
}

}  // namespace roofsweep
