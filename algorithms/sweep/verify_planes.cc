#include "algorithms/sweep/verify_planes.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <unordered_map>
#include <utility>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/core/error.h"
#include "algorithms/geometry/view.h"
#include "algorithms/sweep/plane_fit.h"
#include "algorithms/sweep/side_similarity.h"

namespace roofsweep {
namespace {

// Lifts a reference pixel onto the plane.
bool OnPlane(const Camera& cam, const Pose& pose, const Eigen::Vector4d& pl,
             const Eigen::Vector2d& px, Eigen::Vector3d* x) {
  const Ray ray = BackProject(cam, pose, px);
  const double d = pl.head<3>().dot(ray.direction);
  if (std::abs(d) < 1e-9) return false;
  const double t = -(pl.head<3>().dot(ray.origin) + pl[3]) / d;
  if (t <= 0) return false;
  *x = ray.origin + t * ray.direction;
  return true;
}

// Image motion (px) per metre of height at X in each view that sees it,
// relative to the view nearest in plan, with the plan direction of the
// baseline to that view (zero for the nearest view itself).
struct Parallax {
  Eigen::Vector2d motion, baseline;
};

std::vector<Parallax> RelativeParallax(const Block& block, const Eigen::Vector3d& X) {
  const Eigen::Vector3d up(0, 0, 1);
  int ref = -1;
  double best = std::numeric_limits<double>::infinity();
  std::vector<Parallax> out;
  std::vector<Eigen::Vector2d> centres;
  for (int v = 0; v < static_cast<int>(block.views.size()); ++v) {
    const View& view = block.views[v];
    const Camera& cam = block.CameraOf(view);
    const auto p0 = Project(cam, view.pose, X);
    const auto p1 = Project(cam, view.pose, X + up);
    if (!p0 || !p1 || p0->x() < 0 || p0->y() < 0 || p0->x() > cam.width || p0->y() > cam.height)
      continue;
    out.push_back({*p1 - *p0, Eigen::Vector2d::Zero()});
    centres.push_back(view.pose.C.head<2>());
    const double d = (view.pose.C - X).head<2>().norm();
    if (d < best) best = d, ref = static_cast<int>(out.size()) - 1;
  }
  if (ref < 0) return out;
  const Eigen::Vector2d m0 = out[ref].motion;
  for (size_t i = 0; i < out.size(); ++i) {
    out[i].motion -= m0;
    const Eigen::Vector2d b = centres[i] - centres[ref];
    if (b.norm() > 1e-9) out[i].baseline = b.normalized();
  }
  return out;
}

// The view of largest parallax; nullptr when none sees the point.
const Parallax* Widest(const std::vector<Parallax>& views) {
  const Parallax* widest = nullptr;
  for (const Parallax& p : views)
    if (!widest || p.motion.norm() > widest->motion.norm()) widest = &p;
  return widest;
}

// Parallax (px) per metre of height between the view nearest in plan and
// the view where it is largest.
double ParallaxPerMetre(const std::vector<Parallax>& views) {
  const Parallax* widest = Widest(views);
  return widest ? widest->motion.norm() : 0.0;
}

// The same, counting only the part of each view's motion that moves the
// texture across itself: `texture` is the windows' structure tensor in plan
// coordinates, and the image motion of a height change runs along the
// baseline (the epipolar direction, for near-nadir views).
double ParallaxAcrossTexture(const std::vector<Parallax>& views, const Eigen::Matrix2d& texture) {
  if (!(texture.trace() > 0)) return 0;
  double k = 0;
  for (const Parallax& p : views)
    k = std::max(
        k, p.motion.norm() *
               std::sqrt(std::max(0.0, p.baseline.dot(texture * p.baseline)) / texture.trace()));
  return k;
}

// True when one of the plane's lines of at least min_length_m crosses the
// baseline of largest parallax at min_angle_deg or more.
bool LineCrossesBaseline(const std::vector<Parallax>& views,
                         const std::vector<std::array<Eigen::Vector2d, 2>>& lines,
                         double min_length_m, double min_angle_deg) {
  const Parallax* widest = Widest(views);
  if (!widest || widest->baseline.isZero()) return false;
  const double min_sin = std::sin(min_angle_deg * M_PI / 180);
  for (const auto& l : lines) {
    const Eigen::Vector2d d = l[1] - l[0];
    if (d.norm() < min_length_m) continue;
    const Eigen::Vector2d u = d.normalized();
    if (std::abs(u.x() * widest->baseline.y() - u.y() * widest->baseline.x()) >= min_sin)
      return true;
  }
  return false;
}

struct Scores {
  double sum = 0;
  int n = 0;
  // Per textured sample: its index in the samples and its Cor+, so that two
  // planes can be compared on the same samples.
  std::vector<std::pair<size_t, double>> values;
  // With ScorePlane's `texture`: the sum over the samples of their
  // reference windows' structure tensors in plan coordinates, each
  // normalised to trace 1 (which way the texture varies).
  Eigen::Matrix2d texture = Eigen::Matrix2d::Zero();
  // Samples visited (up to the one that reached max_samples), and how many
  // of them at least two views see, textured or not.
  int visited = 0, seen = 0;
};

// Structure tensor (sum of gradient outer products) of a w x w window,
// carried into plan coordinates at X through the view's local mapping.
Eigen::Matrix2d PlanStructureTensor(const std::vector<float>& win, int w, const Camera& cam,
                                    const Pose& pose, const Eigen::Vector3d& X) {
  Eigen::Matrix2d t = Eigen::Matrix2d::Zero();
  for (int y = 1; y < w - 1; ++y)
    for (int x = 1; x < w - 1; ++x) {
      const Eigen::Vector2d g(0.5 * (win[y * w + x + 1] - win[y * w + x - 1]),
                              0.5 * (win[(y + 1) * w + x] - win[(y - 1) * w + x]));
      t += g * g.transpose();
    }
  const double h = 0.1;
  const auto p0 = Project(cam, pose, X);
  const auto px = Project(cam, pose, X + Eigen::Vector3d(h, 0, 0));
  const auto py = Project(cam, pose, X + Eigen::Vector3d(0, h, 0));
  if (!p0 || !px || !py) return Eigen::Matrix2d::Zero();
  Eigen::Matrix2d J;  // image px per plan metre
  J.col(0) = (*px - *p0) / h;
  J.col(1) = (*py - *p0) / h;
  return J.transpose() * t * J;
}

// Mean Cor+ of the samples for one plane; samples whose reference window
// is flat are skipped.
Scores ScorePlane(const Block& block, const std::vector<cv::Mat>& grey,
                  const std::vector<Eigen::Vector3d>& samples, const Eigen::Vector4d& pl,
                  const VerifyOptions& o, bool texture = false) {
  Scores s;
  const int r = o.ncc_radius, w = 2 * r + 1;
  const int n_views = static_cast<int>(block.views.size());
  std::vector<float> ref(w * w), other(w * w);
  // Beyond a few hundred textured samples the mean no longer changes, only
  // the time: the samples are visited in a scattered order (a stride of
  // about 0.618 n, coprime to n) so that the first max_samples textured
  // ones spread over the whole patch.
  const size_t n_samples = samples.size();
  size_t stride = std::max<size_t>(1, static_cast<size_t>(0.618034 * n_samples));
  while (n_samples > 1 && std::gcd(stride, n_samples) != 1) ++stride;
  for (size_t j = 0; j < n_samples && s.n < o.max_samples; ++j, ++s.visited) {
    const Eigen::Vector3d& X0 = samples[(j * stride) % n_samples];
    const Eigen::Vector3d X(X0.x(), X0.y(), PlaneZ(pl, X0.x(), X0.y()));
    // Reference: the view whose centre is nearest in plan (least
    // perspective distortion of the roof).
    std::vector<std::pair<int, Eigen::Vector2d>> seen;
    int refv = -1;
    double best = std::numeric_limits<double>::infinity();
    for (int v = 0; v < n_views; ++v) {
      const View& view = block.views[v];
      const Camera& cam = block.CameraOf(view);
      const auto p = Project(cam, view.pose, X);
      const double m = r + 2;
      if (!p || p->x() < m || p->y() < m || p->x() > cam.width - m || p->y() > cam.height - m)
        continue;
      seen.emplace_back(v, *p);
      const double d = (view.pose.C - X).head<2>().norm();
      if (d < best) best = d, refv = static_cast<int>(seen.size()) - 1;
    }
    if (seen.size() < 2) continue;
    ++s.seen;
    const int rv = seen[refv].first;
    const Camera& rcam = block.CameraOf(block.views[rv]);
    const Pose& rpose = block.views[rv].pose;
    // Only the five probes of the window are lifted onto the plane (once,
    // reused for every view): the other views map the window affinely from
    // them. The corners are lifted too, as a check that the whole window
    // sees the plane in front of the camera.
    std::vector<Eigen::Vector3d> lifted(w * w);
    const std::array<int, 5> probe = AffineWindow::Probes(r);
    bool ok = true;
    for (int k :
         {probe[0], probe[1], probe[2], probe[3], probe[4], 0, w - 1, w * (w - 1), w * w - 1}) {
      const Eigen::Vector2d px = seen[refv].second + Eigen::Vector2d(k % w - r, k / w - r);
      ok = ok && OnPlane(rcam, rpose, pl, px, &lifted[k]);
    }
    double mean = 0;
    for (int dy = -r, k = 0; dy <= r && ok; ++dy)
      for (int dx = -r; dx <= r; ++dx, ++k) {
        const Eigen::Vector2d px = seen[refv].second + Eigen::Vector2d(dx, dy);
        float val;
        ok = SampleBilinear(grey[rv], px.x() - 0.5, px.y() - 0.5, &val);
        if (!ok) break;
        ref[k] = val;
        mean += val;
      }
    if (!ok) continue;
    mean /= w * w;
    double var = 0;
    for (float& v : ref) v -= static_cast<float>(mean), var += v * v;
    if (std::sqrt(var / (w * w)) < o.min_texture) continue;
    if (texture) {
      const Eigen::Matrix2d t = PlanStructureTensor(ref, w, rcam, rpose, lifted[probe[0]]);
      if (t.trace() > 0) s.texture += t / t.trace();
    }
    double point_sum = 0;
    int point_n = 0;
    for (size_t i = 0; i < seen.size(); ++i) {
      if (static_cast<int>(i) == refv) continue;
      const int v = seen[i].first;
      const Camera& cam = block.CameraOf(block.views[v]);
      const Pose& pose = block.views[v].pose;
      // Exactly at five pixels, affinely in between, as in the sweep.
      std::array<Eigen::Vector2d, 5> q;
      bool inside = true;
      for (int j = 0; j < 5 && inside; ++j) {
        const auto p = Project(cam, pose, lifted[probe[j]]);
        inside = p.has_value();
        if (inside) q[j] = *p;
      }
      inside = inside && AffineWindow(q, r).Sample(grey[v], other.data());
      if (!inside) continue;
      // ref is zero-mean but not unit-norm.
      const double ncc =
          var > 0 ? ZeroMeanCorrelation(ref.data(), other.data(), w * w) / std::sqrt(var) : 0.0;
      point_sum += std::max(0.0, ncc);
      ++point_n;
    }
    if (point_n == 0) continue;
    s.sum += point_sum / point_n;
    ++s.n;
    s.values.emplace_back((j * stride) % n_samples, point_sum / point_n);
  }
  return s;
}

// Mean and standard error of Cor+(a) - Cor+(b) over the samples both
// scored; with fewer than two in common, the difference of the two means
// (each over its own samples) with standard error 0.
void PairedDifference(const Scores& a, const Scores& b, double* mean, double* se) {
  std::unordered_map<size_t, double> of_b;
  for (const auto& [j, c] : b.values) of_b.emplace(j, c);
  double sum = 0, sum2 = 0;
  int n = 0;
  for (const auto& [j, c] : a.values) {
    const auto it = of_b.find(j);
    if (it == of_b.end()) continue;
    const double d = c - it->second;
    sum += d, sum2 += d * d, ++n;
  }
  if (n < 2) {
    *mean = (a.n ? a.sum / a.n : 0.0) - (b.n ? b.sum / b.n : 0.0);
    *se = 0;
    return;
  }
  *mean = sum / n;
  *se = std::sqrt(std::max(0.0, (sum2 - n * *mean * *mean) / (n - 1)) / n);
}

std::vector<cv::Mat> GreyImages(const std::vector<cv::Mat>& images) {
  std::vector<cv::Mat> grey(images.size());
  tbb::parallel_for(size_t{0}, images.size(), [&](size_t v) {
    if (images[v].channels() == 3)
      cv::cvtColor(images[v], grey[v], cv::COLOR_RGB2GRAY);
    else
      grey[v] = images[v];
  });
  return grey;
}

// Plan-view grid points inside a convex patch, each with its grid cell.
struct SampleGrid {
  std::vector<Eigen::Vector3d> points;  // z = 0
  std::vector<int> cell;                // ix + iy * nx of each point
  double spacing = 0;
  int nx = 0, ny = 0;
};

// The grid of a patch, refined for small patches (see
// VerifyOptions::min_spacing_m).
SampleGrid PatchSamples(const Ring2& patch, const VerifyOptions& o, double first_spacing = 0) {
  // A grid finer than 1 cm adds no pixels at any aerial GSD, only time.
  const double min_spacing = std::max(o.min_spacing_m, 0.01);
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& q : patch)
    x0 = std::min(x0, q.x()), y0 = std::min(y0, q.y()), x1 = std::max(x1, q.x()),
    y1 = std::max(y1, q.y());
  SampleGrid g;
  std::vector<std::pair<int, int>> at;
  for (double spacing = first_spacing > 0 ? first_spacing : o.spacing_m;; spacing *= 0.5) {
    g.points.clear();
    at.clear();
    g.nx = g.ny = 0;
    for (double y = y0 + 0.5 * spacing; y < y1; y += spacing, ++g.ny) {
      int ix = 0;
      for (double x = x0 + 0.5 * spacing; x < x1; x += spacing, ++ix)
        if (InsideConvex(patch, {x, y}))
          g.points.emplace_back(x, y, 0.0), at.emplace_back(ix, g.ny);
      g.nx = std::max(g.nx, ix);
    }
    if (static_cast<int>(g.points.size()) >= 4 * o.min_samples ||
        0.5 * spacing < min_spacing * (1 - 1e-9)) {
      g.spacing = spacing;
      break;
    }
  }
  g.cell.reserve(at.size());
  for (const auto& [ix, iy] : at) g.cell.push_back(ix + iy * g.nx);
  return g;
}

// The samples marked `inside`, lifted onto `plane` and carried along the
// ray of the view whose centre is nearest in plan (ScorePlane's reference
// rule, without its visibility test) down to the plane `ground`: the same
// reference windows on the ground, not the ground below the plane, which
// other views see beside a roof.
std::vector<Eigen::Vector3d> SamplesOnTheGround(const Block& block,
                                                const std::vector<Eigen::Vector3d>& samples,
                                                const std::vector<char>& inside,
                                                const Eigen::Vector4d& plane,
                                                const Eigen::Vector4d& ground) {
  std::vector<Eigen::Vector3d> down;
  for (size_t k = 0; k < samples.size(); ++k) {
    if (!inside[k]) continue;
    const Eigen::Vector3d X(samples[k].x(), samples[k].y(),
                            PlaneZ(plane, samples[k].x(), samples[k].y()));
    const View* ref = nullptr;
    double best = std::numeric_limits<double>::infinity();
    for (const View& view : block.views) {
      const double d = (view.pose.C - X).head<2>().norm();
      if (d < best) best = d, ref = &view;
    }
    if (!ref) continue;
    const Eigen::Vector3d C = ref->pose.C;
    const double along = ground.head<3>().dot(X - C);
    if (!(std::abs(along) > 1e-6)) continue;
    down.push_back(C - (ground.head<3>().dot(C) + ground[3]) / along * (X - C));
  }
  return down;
}

// The patch cut back to where the images do not refute the plane (see
// VerifyOptions::trim_patch); empty when nothing is cut. Each sample votes
// with its neighbours within trim_vote_radius_m: Cor+ below
// trim_max_score refutes, above supports, untextured or unvisited samples
// abstain. The samples the vote keeps, each as its grid cell, and the
// plane's lines span the trimmed patch.
Ring2 TrimmedPatch(const Ring2& patch, const SampleGrid& g, const Scores& at,
                   const std::vector<std::array<Eigen::Vector2d, 2>>& lines,
                   const VerifyOptions& o) {
  if (g.points.empty() || !(g.spacing > 0)) return {};
  std::vector<signed char> vote(static_cast<size_t>(g.nx) * g.ny, 0);
  bool refuted = false;
  for (const auto& [k, cor] : at.values) {
    vote[g.cell[k]] = cor < o.trim_max_score ? -1 : 1;
    refuted = refuted || cor < o.trim_max_score;
  }
  if (!refuted) return {};
  const int r = std::max(0, static_cast<int>(std::floor(o.trim_vote_radius_m / g.spacing)));
  std::vector<int> at_cell(vote.size(), -1);  // grid point of each kept cell
  bool dropped = false;
  for (size_t i = 0; i < g.points.size(); ++i) {
    const int cx = g.cell[i] % g.nx, cy = g.cell[i] / g.nx;
    int sum = 0;
    for (int y = std::max(0, cy - r); y <= std::min(g.ny - 1, cy + r); ++y)
      for (int x = std::max(0, cx - r); x <= std::min(g.nx - 1, cx + r); ++x)
        if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) sum += vote[y * g.nx + x];
    if (sum < 0)
      dropped = true;
    else
      at_cell[g.cell[i]] = static_cast<int>(i);
  }
  // A face runs on from its lines: kept cells cut off from them by refuted
  // ones are texture that happens to correlate at the wrong height (a few
  // ground cells 2 m past an eave widened the hull back to the whole
  // overshoot). Only the kept cells connected to the cells nearest each
  // line stay; without lines, all of them.
  std::vector<char> reached(vote.size(), lines.empty() || !o.trim_connected ? 1 : 0);
  std::vector<int> stack;
  std::vector<double> dist(at_cell.size());
  for (const auto& l : lines) {
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t c = 0; c < at_cell.size(); ++c)
      if (at_cell[c] >= 0)
        nearest = std::min(
            nearest, dist[c] = PointSegmentDistance(g.points[at_cell[c]].head<2>(), l[0], l[1]));
    for (size_t c = 0; c < at_cell.size(); ++c)
      if (at_cell[c] >= 0 && !reached[c] && dist[c] <= nearest + 1.5 * g.spacing)
        reached[c] = 1, stack.push_back(static_cast<int>(c));
  }
  while (!stack.empty()) {
    const int c = stack.back();
    stack.pop_back();
    const int cx = c % g.nx, cy = c / g.nx;
    for (int y = std::max(0, cy - 1); y <= std::min(g.ny - 1, cy + 1); ++y)
      for (int x = std::max(0, cx - 1); x <= std::min(g.nx - 1, cx + 1); ++x) {
        const int n = y * g.nx + x;
        if (at_cell[n] >= 0 && !reached[n]) reached[n] = 1, stack.push_back(n);
      }
  }
  std::vector<Eigen::Vector2d> kept;
  for (size_t c = 0; c < at_cell.size(); ++c) {
    if (at_cell[c] < 0) continue;
    if (!reached[c]) {
      dropped = true;
      continue;
    }
    const Eigen::Vector3d& q = g.points[at_cell[c]];
    for (const double dx : {-0.5, 0.5})
      for (const double dy : {-0.5, 0.5})
        kept.emplace_back(q.x() + dx * g.spacing, q.y() + dy * g.spacing);
  }
  if (!dropped) return {};
  for (const auto& l : lines) kept.insert(kept.end(), l.begin(), l.end());
  const Ring2 trimmed = IntersectConvex(ConvexHull(std::move(kept)), patch);
  // A cut that leaves (nearly) all of the patch only rounds its corners to
  // the grid.
  const double area = std::abs(SignedArea(patch));
  if (trimmed.size() < 3 || std::abs(SignedArea(trimmed)) >= (1 - 1e-3) * area) return {};
  return trimmed;
}

// Pixels per plan metre at X in the view nearest in plan (the reference
// view of ScorePlane); 0 when no view sees X.
double PixelsPerMetre(const Block& block, const Eigen::Vector3d& X) {
  double best = std::numeric_limits<double>::infinity(), k = 0;
  for (const View& view : block.views) {
    const Camera& cam = block.CameraOf(view);
    const auto p0 = Project(cam, view.pose, X);
    const auto px = Project(cam, view.pose, X + Eigen::Vector3d(1, 0, 0));
    const auto py = Project(cam, view.pose, X + Eigen::Vector3d(0, 1, 0));
    if (!p0 || !px || !py) continue;
    const double d = (view.pose.C - X).head<2>().norm();
    if (d < best) best = d, k = 0.5 * ((*px - *p0).norm() + (*py - *p0).norm());
  }
  return k;
}

// The grid points farther than band_m (plan) from every line, with their
// cells.
SampleGrid OffLines(const SampleGrid& g, const std::vector<std::array<Eigen::Vector2d, 2>>& lines,
                    double band_m) {
  SampleGrid out;
  out.spacing = g.spacing, out.nx = g.nx, out.ny = g.ny;
  for (size_t i = 0; i < g.points.size(); ++i) {
    const Eigen::Vector2d q = g.points[i].head<2>();
    bool near = false;
    for (const auto& l : lines)
      if ((near = PointSegmentDistance(q, l[0], l[1]) <= band_m)) break;
    if (near) continue;
    out.points.push_back(g.points[i]);
    out.cell.push_back(g.cell[i]);
  }
  return out;
}

// Why the plane is refused on its samples away from its lines (see
// VerifyOptions::verify_off_lines); empty when it is not, or when too few
// samples lie away from them to tell. `centre` is the patch centre on the
// plane, `score` the plane's mean Cor+ over all its samples.
std::string OffLineRefusal(const Block& block, const std::vector<cv::Mat>& grey,
                           const SampleGrid& grid, const RoofPlaneHypothesis& p,
                           const Eigen::Vector3d& centre, double score, const VerifyOptions& o) {
  if (p.lines_xy.empty()) return {};
  const double ppm = PixelsPerMetre(block, centre);
  if (!(ppm > 0)) return {};
  const SampleGrid off = OffLines(grid, p.lines_xy, o.off_line_band_px / ppm);
  if (static_cast<int>(off.points.size()) < o.min_samples) return {};
  const Scores away = ScorePlane(block, grey, off.points, p.plane, o);
  if (away.n < o.min_samples) return {};
  const double away_score = away.sum / away.n;
  if (away_score >= o.min_score || score - away_score < o.off_line_min_drop) return {};
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "photometric score away from its lines %.2f < %.2f over %d samples (%.2f with "
                "the samples on them)",
                away_score, o.min_score, away.n, score);
  return buf;
}

// The line in plan on which all `lines` lie (each endpoint within
// max_offset_m of the longest one's line): a point on it and its unit
// normal. None when the lines span a face, or there are none.
std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> HingeOf(
    const std::vector<std::array<Eigen::Vector2d, 2>>& lines, double max_offset_m) {
  const std::array<Eigen::Vector2d, 2>* longest = nullptr;
  for (const auto& l : lines)
    if (!longest || (l[1] - l[0]).norm() > ((*longest)[1] - (*longest)[0]).norm()) longest = &l;
  if (!longest) return std::nullopt;
  const Eigen::Vector2d d = (*longest)[1] - (*longest)[0];
  if (d.norm() < 1e-3) return std::nullopt;
  const Eigen::Vector2d q0 = (*longest)[0];
  const Eigen::Vector2d m = Eigen::Vector2d(-d.y(), d.x()).normalized();
  for (const auto& l : lines)
    for (const Eigen::Vector2d& q : l)
      if (std::abs(m.dot(q - q0)) > max_offset_m) return std::nullopt;
  return std::make_pair(q0, m);
}

// See VerifyOptions::height_from_outline.
bool DrawnByItsLines(const RoofPlaneHypothesis& p, const VerifyOptions& o) {
  if (CountRightCorners(p.lines_xy, o.outline_corners) < o.outline_min_corners) return false;
  double drawn = 0, perimeter = 0;
  for (const auto& l : p.lines_xy) {
    const double length = (l[1] - l[0]).norm();
    if (length > o.outline_max_line_m) return false;
    drawn += length;
  }
  for (size_t k = 0; k < p.patch.size(); ++k)
    perimeter += (p.patch[(k + 1) % p.patch.size()] - p.patch[k]).norm();
  return drawn >= o.outline_min_fraction * perimeter;
}

}  // namespace

std::vector<ModelHeight> BestModelHeights(const Block& block, const std::vector<cv::Mat>& images,
                                          const std::vector<ModelHeightSearch>& searches,
                                          const VerifyOptions& o, int max_steps) {
  std::vector<ModelHeight> out(searches.size());
  if (searches.empty() || !(o.spacing_m > 0) || max_steps < 1) return out;
  const std::vector<cv::Mat> grey = GreyImages(images);
  tbb::parallel_for(size_t{0}, searches.size(), [&](size_t i) {
    const ModelHeightSearch& m = searches[i];
    if (m.patches.empty() || m.patches.size() != m.planes.size() || !(m.h_hi > m.h_lo)) return;
    std::vector<std::vector<Eigen::Vector3d>> samples;
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    size_t corners = 0;
    for (const Ring2& patch : m.patches) {
      if (patch.size() < 3) return;
      samples.push_back(PatchSamples(patch, o).points);
      for (const auto& q : patch) c += q, ++corners;
    }
    c /= static_cast<double>(corners);
    const double z0 = PlaneZ(m.planes[0], c.x(), c.y());
    double k =
        ParallaxPerMetre(RelativeParallax(block, {c.x(), c.y(), z0 + 0.5 * (m.h_lo + m.h_hi)}));
    // The middle of a flat roof's window lies half the block's maximum
    // building height up, and near the block's edge a point that high leaves
    // all views but one: a garden shed there went without a roof. The
    // parallax per metre changes little with height; at the window's
    // bottom, nearest the ground, the most views see it.
    if (!(k > 0)) k = ParallaxPerMetre(RelativeParallax(block, {c.x(), c.y(), z0 + m.h_lo}));
    if (!(k > 0)) return;
    // The coarse pass needs only the profile's peak: a quarter of the
    // samples find it as well at a quarter of the cost.
    VerifyOptions coarse_o = o;
    coarse_o.max_samples = std::max(o.min_samples, o.max_samples / 4);
    struct Tried {
      double h, score, seen_share;
    };
    auto score = [&](double h, const VerifyOptions& so) {
      double sum = 0;
      int n = 0, visited = 0, seen = 0;
      for (size_t f = 0; f < m.planes.size(); ++f) {
        Eigen::Vector4d pl = m.planes[f];
        pl[3] -= pl[2] * h;
        const Scores s = ScorePlane(block, grey, samples[f], pl, so);
        sum += s.sum, n += s.n, visited += s.visited, seen += s.seen;
      }
      return Tried{h, n >= o.min_samples ? sum / n : -1.0,
                   visited > 0 ? static_cast<double>(seen) / visited : 0.0};
    };
    const double step = std::max(2.0 / k, (m.h_hi - m.h_lo) / max_steps);
    std::vector<Tried> coarse;
    double max_share = 0;
    for (double h = m.h_lo; h <= m.h_hi + 1e-9; h += step) {
      coarse.push_back(score(h, coarse_o));
      max_share = std::max(max_share, coarse.back().seen_share);
    }
    const double min_share = o.model_min_seen_share * max_share;
    Tried best{std::numeric_limits<double>::quiet_NaN(), -1, 0};
    for (const Tried& t : coarse)
      if (t.seen_share >= min_share && t.score > best.score) best = t;
    if (!(best.score > 0)) return;
    const double centre = best.h;
    best.score = -1;
    for (double h = centre - step; h <= centre + step + 1e-9; h += 0.5 / k) {
      const Tried t = score(h, o);
      if (t.seen_share >= min_share && t.score > best.score) best = t;
    }
    if (!(best.score > 0)) return;
    out[i] = {best.h, best.score};
  });
  return out;
}

std::vector<PlaneVerification> VerifyPlanes(const Block& block, const std::vector<cv::Mat>& images,
                                            const std::vector<RoofPlaneHypothesis>& planes,
                                            const VerifyOptions& o, Progress& progress) {
  const std::vector<cv::Mat> grey = GreyImages(images);
  if (!(o.spacing_m > 0) || !std::isfinite(o.spacing_m))
    throw Error("VerifyOptions: spacing_m must be > 0");
  std::vector<PlaneVerification> out(planes.size());
  ReportOrCancel(progress, 0.0, "verifying planes");
  tbb::parallel_for(size_t{0}, planes.size(), [&](size_t i) {
    const RoofPlaneHypothesis& p = planes[i];
    PlaneVerification& v = out[i];
    if (p.patch.size() < 3 || !(std::abs(p.plane[2]) > 1e-3)) {
      v.reason = "degenerate patch";
      v.failed = PlaneVerification::Test::kPatch;
      return;
    }
    // Small faces (dormers, hip ends, porches) hold few grid points at
    // spacing_m: the grid is refined for them, so that the texture, not the
    // grid, decides whether a face can be verified.
    SampleGrid grid = PatchSamples(p.patch, o);
    Scores at = ScorePlane(block, grey, grid.points, p.plane, o,
                           /*texture=*/o.height_from_crossing_lines);
    // Texture in part of the patch only (a steep face in shade, a flat
    // roof with a textured rim): a finer grid takes more of it, as for
    // small patches, before the face is called unverifiable.
    while (o.refine_for_texture && at.n < o.min_samples &&
           0.5 * grid.spacing >= o.min_spacing_m * (1 - 1e-9)) {
      grid = PatchSamples(p.patch, o, 0.5 * grid.spacing);
      at = ScorePlane(block, grey, grid.points, p.plane, o,
                      /*texture=*/o.height_from_crossing_lines);
    }
    const std::vector<Eigen::Vector3d>& samples = grid.points;
    v.samples = at.n;
    if (at.n < o.min_samples) {
      v.score = std::numeric_limits<double>::quiet_NaN();
      char buf[120];
      std::snprintf(buf, sizeof buf, "cannot be verified: %d textured samples < %d", at.n,
                    o.min_samples);
      v.reason = buf;
      v.failed = PlaneVerification::Test::kSamples;
      return;
    }
    v.score = at.sum / at.n;
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (const auto& q : p.patch) c += q;
    c /= static_cast<double>(p.patch.size());
    const std::vector<Parallax> parallax =
        RelativeParallax(block, {c.x(), c.y(), PlaneZ(p.plane, c.x(), c.y())});
    const double k = ParallaxPerMetre(parallax);
    v.offset_m = std::clamp(k > 0 ? o.offset_parallax_px / k : o.max_offset_m, o.min_offset_m,
                            o.max_offset_m);
    Eigen::Vector4d below = p.plane, above = p.plane;
    // z = -(a x + b y + d) / c: moving z by +h changes d by -c h.
    below[3] += p.plane[2] * v.offset_m;
    above[3] -= p.plane[2] * v.offset_m;
    const Scores lo = ScorePlane(block, grey, samples, below, o);
    const Scores hi = ScorePlane(block, grey, samples, above, o);
    v.score_below = lo.n ? lo.sum / lo.n : 0.0;
    v.score_above = hi.n ? hi.sum / hi.n : 0.0;
    PairedDifference(at, lo, &v.below_difference, &v.below_se);
    PairedDifference(at, hi, &v.above_difference, &v.above_se);
    // Tilted alternatives: the plane turned about the patch centre so that
    // the patch's farthest point along x (then y) moves by the offset; they
    // catch a wrong slope that a height shift cannot.
    const double zc = PlaneZ(p.plane, c.x(), c.y());
    Scores best_tilt;
    const double alpha = -p.plane[0] / p.plane[2], beta = -p.plane[1] / p.plane[2];
    // The plane z = alpha x + beta y + ..., turned so that it passes through
    // `pivot` with the gradient (a, b).
    auto try_tilted = [&](double a, double b, const Eigen::Vector3d& pivot) {
      Eigen::Vector3d n(-a, -b, 1);
      n.normalize();
      const Eigen::Vector4d tilted(n.x(), n.y(), n.z(), -n.dot(pivot));
      Scores t = ScorePlane(block, grey, samples, tilted, o);
      const double ts = t.n ? t.sum / t.n : 0.0;
      if (ts > v.score_tilted || best_tilt.values.empty()) best_tilt = std::move(t);
      v.score_tilted = std::max(v.score_tilted, ts);
    };
    for (int axis = 0; axis < 2; ++axis) {
      double reach = 0;
      for (const auto& q : p.patch) reach = std::max(reach, std::abs(q[axis] - c[axis]));
      if (reach < 1e-3) continue;
      for (int sign : {-1, 1})
        try_tilted(alpha + (axis == 0 ? sign * v.offset_m / reach : 0.0),
                   beta + (axis == 1 ? sign * v.offset_m / reach : 0.0), {c.x(), c.y(), zc});
    }
    // A plane whose lines all lie on one line in plan is hinged on it: the
    // sweep chose its slope about that line, and the samples along the line
    // confirm any slope about it. Turned about the patch centre, the
    // alternatives move the line off its edge, and its own samples vote
    // for the plane; turned about the hinge, only the face away from it
    // votes (see VerifyOptions::hinge_tilt).
    if (const auto hinge =
            o.hinge_tilt ? HingeOf(p.lines_xy, o.hinge_max_offset_m) : std::nullopt) {
      const auto& [q0, m] = *hinge;  // a point on it, and the unit normal in plan
      double reach = 0;
      for (const auto& q : p.patch) reach = std::max(reach, std::abs(m.dot(q - q0)));
      if (reach > 1e-3)
        for (int sign : {-1, 1})
          try_tilted(alpha + sign * v.offset_m / reach * m.x(),
                     beta + sign * v.offset_m / reach * m.y(),
                     {q0.x(), q0.y(), PlaneZ(p.plane, q0.x(), q0.y())});
    }
    // The best tilted plane against this one on the samples both scored:
    // each plane's own textured samples differ a little (the reference
    // window moves with the plane), and the difference of two noisy means
    // over different samples refused true planes on a tie.
    PairedDifference(at, best_tilt, &v.tilt_difference, &v.tilt_se);
    // Where the offset cannot move the texture across itself by the
    // window's half-width, the moved planes correlate as well as this one
    // whatever its height: its lines decide, if one of them crosses the
    // baselines (see VerifyOptions::height_from_crossing_lines).
    const bool height_fails =
        o.height_test && v.score < std::max(v.score_below, v.score_above) + o.min_margin;
    const bool on_lines =
        height_fails &&
        LineCrossesBaseline(parallax, p.lines_xy, o.crossing_line_min_length_m,
                            o.crossing_line_min_angle_deg) &&
        ((o.height_from_crossing_lines &&
          v.offset_m * ParallaxAcrossTexture(parallax, at.texture) < o.ncc_radius) ||
         (o.height_from_outline && v.below_difference > 0 && v.above_difference > 0 &&
          DrawnByItsLines(p, o)) ||
         (o.flat_from_lines > 0 && static_cast<int>(p.lines_xy.size()) >= o.flat_from_lines &&
          p.plane[2] >= std::cos(o.flat_max_slope_deg * M_PI / 180) &&
          v.below_difference > -o.flat_tie_z * v.below_se &&
          v.above_difference > -o.flat_tie_z * v.above_se));
    char buf[200];
    if (v.score < o.min_score) {
      std::snprintf(buf, sizeof buf, "photometric score %.2f < %.2f over %d samples", v.score,
                    o.min_score, v.samples);
      v.reason = buf;
      v.failed = PlaneVerification::Test::kScore;
    } else if (height_fails && !on_lines) {
      std::snprintf(buf, sizeof buf,
                    "height not confirmed: score %.2f, %.1f m %s %.2f (margin %.2f needed)",
                    v.score, v.offset_m, v.score_below > v.score_above ? "lower" : "higher",
                    std::max(v.score_below, v.score_above), o.min_margin);
      v.reason = buf;
      v.failed = PlaneVerification::Test::kHeight;
    } else if (v.tilt_difference < o.min_tilt_margin - o.tilt_z * v.tilt_se) {
      std::snprintf(buf, sizeof buf,
                    "slope not confirmed: score %.2f, tilted by %.1f m at the edge %.2f (on the "
                    "same samples %+.3f, standard error %.3f)",
                    v.score, v.offset_m, v.score_tilted, v.tilt_difference, v.tilt_se);
      v.reason = buf;
      v.failed = PlaneVerification::Test::kSlope;
    } else if (o.verify_off_lines && !height_fails) {
      v.reason = OffLineRefusal(block, grey, grid, p, {c.x(), c.y(), zc}, v.score, o);
      if (!v.reason.empty()) v.failed = PlaneVerification::Test::kOffLines;
    }
    // The trimmed patch first: the ground test weighs the evidence where
    // the plane is seen, not the overshoot past its eaves, which is ground.
    Ring2 trimmed;
    if (v.reason.empty() && o.trim_patch) trimmed = TrimmedPatch(p.patch, grid, at, p.lines_xy, o);
    if (v.reason.empty() && (!height_fails || o.ground_on_lines) && o.ground_alternative &&
        block.ground.Known()) {
      const double zg = block.ground.HeightAt(c.x(), c.y());
      if (std::isfinite(zg) && zc - zg > o.ground_min_offsets * v.offset_m) {
        // The ground under the patch, sloping as the DTM does across it.
        const Ring2& seen = trimmed.size() >= 3 ? trimmed : p.patch;
        double radius = 0;
        for (const Eigen::Vector2d& q : seen) radius = std::max(radius, (q - c).norm());
        const Eigen::Vector4d ground = block.ground.PlaneAt(c.x(), c.y(), radius);
        // The same image evidence on the ground: the samples inside the
        // trimmed patch (SamplesOnTheGround).
        std::vector<char> inside(samples.size(), 1);
        if (trimmed.size() >= 3)
          for (size_t k = 0; k < samples.size(); ++k)
            inside[k] = InsideConvex(trimmed, samples[k].head<2>());
        double plane_sum = 0;
        int plane_n = 0;
        for (const auto& [k, value] : at.values)
          if (inside[k]) plane_sum += value, ++plane_n;
        const std::vector<Eigen::Vector3d> down =
            SamplesOnTheGround(block, samples, inside, p.plane, ground);
        const Scores g = ScorePlane(block, grey, down, ground, o);
        if (plane_n > 0 && g.n > 0) {
          const double plane_score = plane_sum / plane_n;
          v.score_ground = g.sum / g.n;
          if (plane_score < v.score_ground + o.ground_margin) {
            std::snprintf(buf, sizeof buf,
                          "the ground explains the images as well: score %.2f, %.2f on the ground "
                          "%.1f m lower",
                          plane_score, v.score_ground, zc - zg);
            v.reason = buf;
            v.failed = PlaneVerification::Test::kGround;
          }
        }
      }
    }
    if (v.reason.empty()) {
      v.accepted = true;
      v.height_confirmed = !height_fails;
      v.patch = std::move(trimmed);
    }
  });
  return out;
}

}  // namespace roofsweep
