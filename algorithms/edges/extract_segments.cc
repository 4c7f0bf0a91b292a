#include "algorithms/edges/extract_segments.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "algorithms/core/error.h"
#include "algorithms/edges/edge_linking.h"
#include "algorithms/edges/edge_points.h"
#include "algorithms/edges/gradient.h"
#include "algorithms/edges/line_pieces.h"
#include "algorithms/edges/segment_attributes.h"
#include "algorithms/edges/segment_fusion.h"
#include "algorithms/edges/texture_filter.h"
#include "algorithms/edges/thresholds.h"

namespace roofsweep {
namespace {

void Require(bool ok, const std::string& what) {
  if (!ok) throw Error("EdgeOptions: " + what);
}

void ValidateOptions(const EdgeOptions& o) {
  auto finite = [](double v) { return std::isfinite(v); };
  Require(finite(o.sigma) && o.sigma >= 0 && o.sigma <= 50, "sigma must be in [0, 50]");
  Require(finite(o.high_threshold) && finite(o.low_threshold),
          "thresholds must be finite (negative = automatic)");
  Require(finite(o.auto_high_factor) && o.auto_high_factor > 0, "auto_high_factor must be > 0");
  Require(finite(o.auto_low_ratio) && o.auto_low_ratio > 0 && o.auto_low_ratio <= 1,
          "auto_low_ratio must be in (0, 1]");
  Require(finite(o.auto_min_high) && o.auto_min_high >= 0, "auto_min_high must be >= 0");
  Require(finite(o.link_max_angle) && o.link_max_angle > 0 && o.link_max_angle <= 90,
          "link_max_angle must be in (0, 90]");
  Require(finite(o.split_tangent_angle) && o.split_tangent_angle > 0,
          "split_tangent_angle must be > 0");
  Require(o.tangent_window >= 1, "tangent_window must be >= 1");
  Require(finite(o.fit_max_deviation) && o.fit_max_deviation > 0, "fit_max_deviation must be > 0");
  Require(finite(o.fit_max_sagitta) && o.fit_max_sagitta > 0, "fit_max_sagitta must be > 0");
  Require(finite(o.fit_curve_min_explained) && o.fit_curve_min_explained >= 0 &&
              o.fit_curve_min_explained <= 1,
          "fit_curve_min_explained must be in [0, 1]");
  Require(o.min_support >= 2, "min_support must be >= 2");
  Require(o.end_trim_points >= 0 && finite(o.end_trim_distance) && o.end_trim_distance > 0,
          "end_trim_points must be >= 0 and end_trim_distance > 0");
  Require(finite(o.merge_max_gap) && o.merge_max_gap >= 0, "merge_max_gap must be >= 0");
  Require(finite(o.merge_max_angle) && o.merge_max_angle >= 0, "merge_max_angle must be >= 0");
  Require(finite(o.merge_max_offset) && o.merge_max_offset >= 0, "merge_max_offset must be >= 0");
  Require(finite(o.min_length) && o.min_length >= 0, "min_length must be >= 0");
  Require(finite(o.coarse_min_length) && o.coarse_min_length >= 0,
          "coarse_min_length must be >= 0");
  Require(finite(o.side_distance) && o.side_distance >= 0, "side_distance must be >= 0");
  Require(finite(o.fuse_max_distance) && finite(o.fuse_max_angle) && finite(o.fuse_min_overlap) &&
              o.fuse_min_overlap >= 0 && o.fuse_min_overlap <= 1,
          "fuse_* must be finite, fuse_min_overlap in [0, 1]");
  Require(finite(o.texture_max_angle) && o.texture_max_angle >= 0 && o.texture_max_angle < 90 &&
              finite(o.texture_min_offset) && o.texture_min_offset >= 0 &&
              finite(o.texture_max_offset) && o.texture_max_offset >= o.texture_min_offset &&
              finite(o.texture_spacing_ratio) && o.texture_spacing_ratio >= 1 &&
              finite(o.texture_min_overlap) && o.texture_min_overlap >= 0 &&
              o.texture_min_overlap <= 1 && finite(o.texture_dominance) && o.texture_dominance > 0,
          "texture_* must be finite: max_angle in [0, 90), 0 <= min_offset <= max_offset, "
          "spacing_ratio >= 1, min_overlap in [0, 1], dominance > 0");
}

void ValidateImage(const cv::Mat& image) {
  if (image.empty()) throw Error("ExtractSegments: empty image");
  if (image.type() != CV_32FC3 && image.type() != CV_32FC1) {
    throw Error("ExtractSegments: expected a CV_32FC3 (R, G, B) or CV_32FC1 image in [0, 1], got " +
                cv::typeToString(image.type()));
  }
  if (image.dims != 2) throw Error("ExtractSegments: expected a 2-D image");
  // cv::checkRange is a scalar loop (7 % of the extraction on a 2048²
  // colour image); a sum is vectorised and any NaN or infinity makes it
  // non-finite (pixels are floats, so the double sum cannot overflow).
  // checkRange then only finds the pixel to name.
  const cv::Scalar sum = cv::sum(image);
  bool finite = true;
  for (int c = 0; c < image.channels(); ++c) finite = finite && std::isfinite(sum[c]);
  cv::Point bad;
  if (!finite && !cv::checkRange(image, true, &bad)) {
    throw Error("ExtractSegments: NaN or infinite pixel at x=" + std::to_string(bad.x) +
                ", y=" + std::to_string(bad.y) + "; fill or mask it first");
  }
}

bool LongerFirst(const Segment2D& a, const Segment2D& b) {
  const double la = a.Length(), lb = b.Length();
  if (la != lb) return la > lb;
  if (a.p0.x() != b.p0.x()) return a.p0.x() < b.p0.x();
  if (a.p0.y() != b.p0.y()) return a.p0.y() < b.p0.y();
  if (a.p1.x() != b.p1.x()) return a.p1.x() < b.p1.x();
  return a.p1.y() < b.p1.y();
}

// `side_colours`: false leaves them to the caller (the coarse pass measures
// them on the full-resolution image).
Segments2D ExtractWithMethod(const cv::Mat& image, GradientMethod method, const EdgeOptions& o,
                             EdgeStats* stats, bool side_colours = true) {
  if (image.channels() == 1) method = GradientMethod::kGrey;
  const GradientField gradient = ComputeGradient(GradientPlanes(image, method), method, o.sigma);
  const HysteresisThresholds t = ChooseThresholds(gradient.magnitude, o);
  const EdgeMap map = DetectEdgePoints(gradient, t.low, t.high);
  const auto chains = LinkEdgePoints(map, o.link_max_angle, o.min_support);
  std::vector<LinePiece> pieces = ChainsToPieces(chains, map, o);
  const int raw_pieces = static_cast<int>(pieces.size());
  if (o.merge) pieces = MergeCollinearPieces(std::move(pieces), map, o);

  Segments2D out;
  for (const LinePiece& piece : pieces) {
    if (piece.fit.Length() + 1.0 < o.min_length) continue;  // see PieceToSegment
    Segment2D s = PieceToSegment(piece, map, gradient);
    if (side_colours) MeasureSideColours(s, image, o.side_distance);
    out.push_back(s);
  }
  if (stats) {
    stats->noise = t.noise;
    stats->low = t.low;
    stats->high = t.high;
    stats->edge_points = static_cast<int>(map.points.size());
    stats->chains = static_cast<int>(chains.size());
    stats->pieces = raw_pieces;
  }
  return out;
}

// ExtractWithMethod on the image averaged down 2 x 2, the segments given
// back in full-resolution pixels (EdgeOptions::coarse_fusion).
Segments2D ExtractCoarse(const cv::Mat& image, const EdgeOptions& o) {
  const int w = image.cols / 2, h = image.rows / 2;
  if (w < 3 || h < 3) return {};
  cv::Mat half;
  cv::resize(image, half, cv::Size(w, h), 0, 0, cv::INTER_AREA);
  // INTER_AREA maps the image corners onto each other, so corner-convention
  // coordinates scale by the size ratio (2, or a little more for odd sizes).
  const double sx = static_cast<double>(image.cols) / w, sy = static_cast<double>(image.rows) / h;
  EdgeOptions co = o;
  co.min_length = o.coarse_min_length / sx;
  Segments2D out = ExtractWithMethod(half, o.method, co, nullptr, false);
  for (Segment2D& s : out) {
    s.p0 = Eigen::Vector2d(s.p0.x() * sx, s.p0.y() * sy);
    s.p1 = Eigen::Vector2d(s.p1.x() * sx, s.p1.y() * sy);
    // Gradient and residual per full-resolution pixel.
    s.contrast = static_cast<float>(s.contrast / sx);
    s.rms_residual = static_cast<float>(s.rms_residual * sx);
    s.scale = 2;
    MeasureSideColours(s, image, o.side_distance * sx);
  }
  return out;
}

}  // namespace

Segments2D ExtractSegments(const cv::Mat& image, const EdgeOptions& options, EdgeStats* stats) {
  ValidateOptions(options);
  ValidateImage(image);
  if (stats) *stats = EdgeStats{};
  if (image.cols < 3 || image.rows < 3) return {};
  // Contiguous input keeps the row loops simple; ReadImage's images are.
  const cv::Mat input = image.isContinuous() ? image : image.clone();

  Segments2D segments = ExtractWithMethod(input, options.method, options, stats);
  for (GradientMethod extra : options.fuse_methods) {
    if (input.channels() == 1 || extra == options.method) continue;
    AddMissingSegments(segments, ExtractWithMethod(input, extra, options, nullptr),
                       options.fuse_max_distance, options.fuse_max_angle, options.fuse_min_overlap);
  }
  if (options.coarse_fusion) {
    AddUncoveredParts(segments, ExtractCoarse(input, options), options.fuse_max_distance,
                      options.fuse_max_angle, options.min_length);
  }
  if (options.mark_texture) {
    const std::vector<bool> texture = MarkRepetitiveTexture(segments, options);
    for (size_t i = 0; i < segments.size(); ++i) segments[i].texture = texture[i];
  }
  std::sort(segments.begin(), segments.end(), LongerFirst);
  return segments;
}

}  // namespace roofsweep
