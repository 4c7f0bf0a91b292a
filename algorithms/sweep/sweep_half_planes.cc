#include "algorithms/sweep/sweep_half_planes.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/core/error.h"
#include "algorithms/geometry/view.h"
#include "algorithms/sweep/half_plane_family.h"
#include "algorithms/sweep/points_of_interest.h"
#include "algorithms/sweep/side_similarity.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

// The element at index size / 2 once sorted (the upper median); v non-empty.
double UpperMedian(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

struct Projected {
  bool front = false;      // both end points in front of the camera
  bool inside = false;     // a part of at least min_visible_px inside the image (with the margin)
  Eigen::Vector2d p0, p1;  // the whole line
  Eigen::Vector2d v0, v1;  // the part inside the image
};

std::string Format(const char* fmt, double a, double b) {
  char buf[160];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}

// True when the projection o comes within `reach` of me's bounding box:
// o may bound me's band.
bool NearBand(const Projected& me, const Projected& o, double reach) {
  if (!o.front) return false;
  return std::max(o.p0.x(), o.p1.x()) >= std::min(me.p0.x(), me.p1.x()) - reach &&
         std::min(o.p0.x(), o.p1.x()) <= std::max(me.p0.x(), me.p1.x()) + reach &&
         std::max(o.p0.y(), o.p1.y()) >= std::min(me.p0.y(), me.p1.y()) - reach &&
         std::min(o.p0.y(), o.p1.y()) <= std::max(me.p0.y(), me.p1.y()) + reach;
}

// Blockers of the band of line `self` in view `view`: the other lines'
// projections that come near it.
std::vector<Segment2> Blockers(const std::vector<std::vector<Projected>>& projected, int view,
                               int self, double reach) {
  std::vector<Segment2> out;
  const std::vector<Projected>& lines = projected[view];
  for (size_t i = 0; i < lines.size(); ++i)
    if (static_cast<int>(i) != self && NearBand(lines[self], lines[i], reach))
      out.emplace_back(lines[i].p0, lines[i].p1);
  return out;
}

// The face's reach from the line: the points that still correlate at theta
// (mean Cor+^2 >= options.extent_min_score over the views) are lifted onto
// the plane through the reference view, and the options.extent_quantile of
// their distances from the line is kept. A quantile, not the maximum, so
// that a few points correlating by chance beyond the face do not stretch it.
// `score`: each point's mean squared correlation at theta (Evaluate's
// per_point).
double FaceExtent(const Camera& camera, const Pose& pose, const HalfPlaneFamily& family,
                  double theta, const std::vector<double>& score,
                  const std::vector<BandPoint>& points, const SweepOptions& o,
                  std::vector<Eigen::Vector2d>* support) {
  const Eigen::Vector4d plane = family.Plane(theta);
  const Eigen::Vector3d w = family.Direction(theta);
  std::vector<double> reach;
  std::vector<Eigen::Vector3d> lifted;
  for (size_t i = 0; i < points.size() && i < score.size(); ++i) {
    if (score[i] < o.extent_min_score) continue;
    const Ray ray = BackProject(camera, pose, points[i].pixel);
    const double denom = plane.head<3>().dot(ray.direction);
    if (std::abs(denom) < 1e-9) continue;
    const double t = -(plane.head<3>().dot(ray.origin) + plane[3]) / denom;
    if (t <= 0) continue;
    const Eigen::Vector3d x = ray.origin + t * ray.direction;
    reach.push_back(std::max(0.0, (x - family.line().a).dot(w)));
    lifted.push_back(x);
  }
  if (reach.empty()) return 0.0;
  std::vector<double> sorted = reach;
  const size_t k = std::min(sorted.size() - 1,
                            static_cast<size_t>(o.extent_quantile * (sorted.size() - 1) + 0.5));
  std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
  const double extent = sorted[k];
  std::vector<Eigen::Vector2d> plan = {family.line().a.head<2>(), family.line().b.head<2>()};
  for (size_t i = 0; i < lifted.size(); ++i)
    if (reach[i] <= extent) plan.push_back(lifted[i].head<2>());
  *support = ConvexHull(std::move(plan));
  return extent;
}

HalfPlane SweepSide(const Block& block, const std::vector<ViewTexture>& textures,
                    const std::vector<std::vector<Projected>>& projected,
                    const std::vector<SweepLine>& lines, int line, int side,
                    const SweepOptions& o) {
  HalfPlane hp;
  hp.line = line;
  hp.side = side;
  const Segment3& seg = lines[line].segment;
  const auto family = HalfPlaneFamily::Make(seg, side, o.max_line_slope_deg);
  if (!family) {
    hp.reason = "degenerate or near-vertical line";
    return hp;
  }
  const int n_views = static_cast<int>(block.views.size());
  // The side's image side in each view, from the horizontal direction.
  const Eigen::Vector3d mid = seg.At(0.5);
  const Eigen::Vector3d off = mid + std::max(0.1, 0.1 * seg.Length()) * family->e();
  std::vector<int> image_side(n_views, 0);
  std::vector<int> seeing;
  for (int v = 0; v < n_views; ++v) {
    const Projected& p = projected[v][line];
    if (!p.inside) continue;
    const auto q = Project(block.CameraOf(block.views[v]), block.views[v].pose, off);
    if (!q) continue;
    image_side[v] = ImageSide(p.p0, p.p1, *q);
    if (image_side[v] != 0) seeing.push_back(v);
  }
  // Reference: the most textured view (most points of interest, §3.3).
  const std::vector<int>& supporting = lines[line].views;
  std::vector<BandPoint> best_points;
  for (int v : seeing) {
    if (!supporting.empty() &&
        std::find(supporting.begin(), supporting.end(), v) == supporting.end())
      continue;
    const Projected& p = projected[v][line];
    const std::vector<Segment2> blockers = o.clip_at_other_lines
                                               ? Blockers(projected, v, line, o.band_width_px)
                                               : std::vector<Segment2>();
    std::vector<BandPoint> pts = BandPoints(textures[v], p.v0, p.v1, image_side[v], blockers, o);
    if (hp.reference_view < 0 || pts.size() > best_points.size()) {
      hp.reference_view = v;
      best_points.swap(pts);
    }
  }
  hp.points_detected = static_cast<int>(best_points.size());
  if (hp.reference_view < 0) {
    hp.reason = "no view sees the line";
    return hp;
  }
  std::vector<int> others;
  for (int v : seeing)
    if (v != hp.reference_view) others.push_back(v);
  hp.views = static_cast<int>(others.size());
  if (hp.points_detected < o.min_points) {
    hp.reason =
        Format("too few points of interest (%.0f < %.0f)", hp.points_detected, o.min_points);
    return hp;
  }
  if (others.empty()) {
    hp.reason = "no second view";
    return hp;
  }

  SideSimilarity sim(block, textures, *family, hp.reference_view, others, best_points, o);
  hp.points = sim.ActiveCount();
  if (hp.points < o.min_points) {
    hp.reason = Format("too few textured points (%.0f < %.0f)", hp.points, o.min_points);
    return hp;
  }
  const double t_min = o.theta_min_deg * kDeg, t_max = o.theta_max_deg * kDeg;
  // The coarse grid spans the whole range, ends included, at no more than
  // the coarse step.
  const int samples = std::max(
      2, static_cast<int>(std::ceil((t_max - t_min) / (o.coarse_step_deg * kDeg) - 1e-9)) + 1);
  const double step = (t_max - t_min) / (samples - 1);
  hp.profile.resize(samples);
  // The coarse sweep only has to find the peak's bracket: an even subset of
  // the points does (Sim is a mean over points), at a fraction of the cost.
  const int n_points = sim.PointCount();
  if (o.coarse_max_points > 0 && n_points > o.coarse_max_points) {
    std::vector<bool> subset(n_points, false);
    for (int k = 0; k < o.coarse_max_points; ++k)
      subset[static_cast<size_t>(static_cast<long long>(k) * n_points / o.coarse_max_points)] =
          true;
    sim.SetActive(subset);
  }
  int k0 = 0;
  for (int k = 0; k < samples; ++k) {
    hp.profile[k] = sim.Evaluate(t_min + k * step);
    if (hp.profile[k] > hp.profile[k0]) k0 = k;
  }
  sim.SetActive(std::vector<bool>(n_points, true));
  double theta = std::min(t_min + k0 * step, t_max);

  // Outsiders, valid views and the refinement's start are all judged at
  // the coarse maximum: one pass over the images serves the three.
  const std::vector<double> at_coarse_max = sim.Correlations(theta);
  // Outsiders (§3.4): points that do not correlate at the coarse maximum,
  // e.g. occluded or off the plane; keep at least the better half.
  std::vector<double> score;
  sim.Reduce(at_coarse_max, &score);
  {
    // The median bounds the threshold so that at most half is dropped.
    const double threshold = std::min(o.outlier_min_score, UpperMedian(score));
    std::vector<bool> active(score.size());
    for (size_t i = 0; i < score.size(); ++i) active[i] = score[i] >= threshold;
    sim.SetActive(active);
    hp.points = sim.ActiveCount();
  }
  // Valid views (§3.3): views where the kept points correlate poorly at the
  // coarse maximum are probably occluded there and are left out.
  {
    std::vector<double> view_score;
    sim.Reduce(at_coarse_max, nullptr, &view_score);
    const double best = *std::max_element(view_score.begin(), view_score.end());
    std::vector<bool> valid(view_score.size());
    for (size_t i = 0; i < view_score.size(); ++i)
      valid[i] = view_score[i] >= o.valid_view_ratio * best;
    sim.SetActiveViews(valid);
    hp.views = sim.ActiveViewCount();
  }

  // Parabolic refinement, halving the bracket until it is below the
  // tolerance. A step clamped to the bracket lands where Sim was just
  // evaluated, so values are remembered by angle.
  std::map<double, double> known;
  auto eval = [&](double t) {
    t = std::clamp(t, t_min, t_max);
    const auto it = known.find(t);
    return it != known.end() ? it->second : known[t] = sim.Evaluate(t);
  };
  double h = step;
  double s0 = known[theta] = sim.Reduce(at_coarse_max);
  for (;;) {
    const double sm = eval(theta - h), sp = eval(theta + h);
    const double denom = sm - 2 * s0 + sp;
    double delta;
    if (denom < 0) {
      delta = std::clamp(0.5 * h * (sm - sp) / denom, -h, h);
    } else {
      delta = sp > sm ? h : (sm > sp ? -h : 0.0);
    }
    theta = std::clamp(theta + delta, t_min, t_max);
    if (h <= o.refine_tolerance_deg * kDeg) break;
    h *= 0.5;
    s0 = eval(theta);
  }
  // The face's extent needs each point's score at the maximum, which the
  // same evaluation gives.
  std::vector<double> score_at_max;
  hp.similarity = sim.Evaluate(theta, &score_at_max);
  const double hc = o.curvature_step_deg * kDeg;
  hp.curvature = (eval(theta - hc) - 2 * hp.similarity + eval(theta + hc)) / (hc * hc);
  hp.theta_deg = theta / kDeg;
  hp.plane = family->Plane(theta);
  hp.extent_m = FaceExtent(block.CameraOf(block.views[hp.reference_view]),
                           block.views[hp.reference_view].pose, *family, theta, score_at_max,
                           best_points, o, &hp.support);

  if (hp.views < o.min_views) {
    hp.reason = Format("too few views (%.0f < %.0f)", hp.views, o.min_views);
  } else if (k0 == 0 || k0 == samples - 1) {
    hp.reason = "maximum at the end of the angle range";
  } else if (hp.similarity < o.min_similarity) {
    hp.reason = Format("similarity %.3f < %.3f", hp.similarity, o.min_similarity);
  } else if (!(hp.curvature <= -o.min_curvature)) {
    hp.reason = Format("curvature %.2f above -%.2f per rad^2", hp.curvature, o.min_curvature);
  } else {
    hp.accepted = true;
  }
  hp.candidate_shape = hp.views >= o.min_views && k0 > 0 && k0 < samples - 1 &&
                       hp.curvature <= -o.candidate_min_curvature;
  hp.peak_ratio = hp.similarity / std::max(UpperMedian(hp.profile), 1e-3);
  // SweepHalfPlanes settles the candidates once the block's threshold is known.
  hp.candidate = hp.accepted;
  return hp;
}

}  // namespace

double CandidateThreshold(const std::vector<HalfPlane>& sides, const SweepOptions& o) {
  if (o.calibration_peak_ratio <= 0) return o.candidate_min_similarity;
  std::vector<double> clear;
  for (const HalfPlane& hp : sides)
    if (hp.candidate_shape && hp.peak_ratio >= o.calibration_peak_ratio)
      clear.push_back(hp.similarity);
  if (static_cast<int>(clear.size()) < std::max(1, o.calibration_min_sides))
    return o.candidate_min_similarity;
  const double scale = std::min(1.0, UpperMedian(clear) / o.calibration_reference_similarity);
  return std::max(o.candidate_floor_similarity, o.candidate_min_similarity * scale);
}

bool WantsWiderWindow(const std::vector<HalfPlane>& sides, const SweepOptions& o) {
  return o.wide_ncc_radius > o.ncc_radius &&
         CandidateThreshold(sides, o) < o.wide_window_below * o.candidate_min_similarity;
}

double ScoreThresholdAtImageQuality(double min_score, const std::vector<HalfPlane>& sides,
                                    const SweepOptions& o) {
  if (!(o.candidate_min_similarity > 0)) return min_score;
  const double scale = CandidateThreshold(sides, o) / o.candidate_min_similarity;
  return min_score * std::sqrt(std::clamp(scale, 0.0, 1.0));
}

std::vector<ViewTexture> PrepareViewTextures(const Block& block, const std::vector<cv::Mat>& images,
                                             const SweepOptions& options) {
  const int n_views = static_cast<int>(block.views.size());
  if (static_cast<int>(images.size()) != n_views)
    throw Error("sweep: " + std::to_string(images.size()) + " images for " +
                std::to_string(n_views) + " views of " + block.source);
  for (int v = 0; v < n_views; ++v) {
    const cv::Mat& im = images[v];
    const Camera& cam = block.CameraOf(block.views[v]);
    if (im.type() != CV_32FC3 && im.type() != CV_32FC1)
      throw Error("sweep: image of view '" + block.views[v].name + "' is not CV_32FC3 or CV_32FC1");
    if (im.cols != cam.width || im.rows != cam.height)
      throw Error("sweep: image of view '" + block.views[v].name + "' is " +
                  std::to_string(im.cols) + "x" + std::to_string(im.rows) + ", camera '" + cam.id +
                  "' is " + std::to_string(cam.width) + "x" + std::to_string(cam.height));
  }
  std::vector<ViewTexture> textures(n_views);
  tbb::parallel_for(0, n_views,
                    [&](int v) { textures[v] = PrepareViewTexture(images[v], options); });
  return textures;
}

std::vector<HalfPlane> SweepHalfPlanes(const Block& block, const std::vector<cv::Mat>& images,
                                       const std::vector<SweepLine>& lines,
                                       const SweepOptions& options, Progress& progress,
                                       const std::vector<HalfPlane>* previous) {
  ReportOrCancel(progress, 0.0, "sweep: preparing views");
  return SweepHalfPlanes(block, PrepareViewTextures(block, images, options), lines, options,
                         progress, previous);
}

std::vector<HalfPlane> SweepHalfPlanes(const Block& block, const std::vector<ViewTexture>& textures,
                                       const std::vector<SweepLine>& lines,
                                       const SweepOptions& options, Progress& progress,
                                       const std::vector<HalfPlane>* previous) {
  const int n_views = static_cast<int>(block.views.size());
  if (static_cast<int>(textures.size()) != n_views)
    throw Error("sweep: " + std::to_string(textures.size()) + " prepared views for " +
                std::to_string(n_views) + " views of " + block.source);
  // The band points are read from these rasters by pixel: views prepared
  // from other images would be read out of bounds.
  for (int v = 0; v < n_views; ++v) {
    const Camera& cam = block.CameraOf(block.views[v]);
    const ViewTexture& t = textures[v];
    if (t.grey.cols != cam.width || t.grey.rows != cam.height || t.poi.size() != t.grey.size())
      throw Error("sweep: prepared view '" + block.views[v].name + "' is " +
                  std::to_string(t.grey.cols) + "x" + std::to_string(t.grey.rows) + ", camera '" +
                  cam.id + "' is " + std::to_string(cam.width) + "x" + std::to_string(cam.height));
  }
  const int n_lines = static_cast<int>(lines.size());
  std::vector<std::vector<Projected>> projected(n_views, std::vector<Projected>(n_lines));
  tbb::parallel_for(0, n_views, [&](int v) {
    const Camera& cam = block.CameraOf(block.views[v]);
    const Pose& pose = block.views[v].pose;
    const double m = options.view_margin_px + options.ncc_radius;
    for (int i = 0; i < n_lines; ++i) {
      const auto a = Project(cam, pose, lines[i].segment.a);
      const auto b = Project(cam, pose, lines[i].segment.b);
      Projected& p = projected[v][i];
      if (!a || !b) continue;
      p.front = true;
      p.p0 = *a;
      p.p1 = *b;
      if (cam.Contains(*a, m) && cam.Contains(*b, m)) {
        p.v0 = *a;
        p.v1 = *b;
      } else {
        // The image is convex, so the inside part is one interval of the
        // line; found on a grid of 1/64 of the line (inner samples kept).
        constexpr int kSteps = 64;
        int first = -1, last = -1;
        for (int k = 0; k <= kSteps; ++k) {
          const auto q = Project(cam, pose, lines[i].segment.At(static_cast<double>(k) / kSteps));
          if (q && cam.Contains(*q, m)) {
            if (first < 0) first = k;
            last = k;
          }
        }
        if (first < 0 || last <= first) continue;
        p.v0 = *Project(cam, pose, lines[i].segment.At(static_cast<double>(first) / kSteps));
        p.v1 = *Project(cam, pose, lines[i].segment.At(static_cast<double>(last) / kSteps));
      }
      p.inside = (p.v1 - p.v0).norm() >= options.min_visible_px;
    }
  });

  std::vector<HalfPlane> out(2 * static_cast<size_t>(n_lines));
  // A line swept before keeps its sides unless an added line comes into its
  // band's reach in some view (the only way one line's sides depend on the
  // others: Blockers, with the same box test).
  std::vector<char> redo(n_lines, 1);
  const int n_before = previous ? std::min(n_lines, static_cast<int>(previous->size() / 2)) : 0;
  if (n_before > 0) {
    tbb::parallel_for(0, n_before, [&](int i) {
      bool reached = false;
      for (int v = 0; v < n_views && !reached; ++v)
        for (int j = n_before; j < n_lines && !reached; ++j)
          reached = NearBand(projected[v][i], projected[v][j], options.band_width_px);
      if (!reached) {
        redo[i] = 0;
        out[2 * static_cast<size_t>(i)] = (*previous)[2 * static_cast<size_t>(i)];
        out[2 * static_cast<size_t>(i) + 1] = (*previous)[2 * static_cast<size_t>(i) + 1];
      }
    });
  }
  constexpr int kChunk = 64;
  for (int begin = 0; begin < n_lines; begin += kChunk) {
    ReportOrCancel(progress, 0.05 + 0.95 * begin / std::max(1, n_lines), "sweep: half-planes");
    const int end = std::min(n_lines, begin + kChunk);
    tbb::parallel_for(0, 2 * (end - begin), [&](int k) {
      const int line = begin + k / 2;
      if (!redo[line]) return;
      const int side = k % 2 == 0 ? 1 : -1;
      out[2 * static_cast<size_t>(line) + k % 2] =
          SweepSide(block, textures, projected, lines, line, side, options);
    });
  }
  const double threshold = CandidateThreshold(out, options);
  for (HalfPlane& hp : out)
    hp.candidate = hp.accepted || (hp.candidate_shape && hp.similarity >= threshold);
  ReportOrCancel(progress, 1.0, "sweep: half-planes");
  return out;
}

}  // namespace roofsweep
