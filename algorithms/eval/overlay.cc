#include "algorithms/eval/overlay.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "algorithms/core/error.h"
#include "algorithms/eval/plan_view.h"

namespace roofsweep {
namespace {

const cv::Scalar kWhite(255, 255, 255);
const cv::Scalar kBlack(0, 0, 0);
const cv::Scalar kRefMatchedFill(190, 235, 190);
const cv::Scalar kRefMissedFill(190, 190, 255);
const cv::Scalar kRefOutline(200, 110, 0);
const cv::Scalar kResCorrect(0, 120, 0);
const cv::Scalar kResFalse(200, 0, 200);
const cv::Scalar kLod1Block(0, 140, 255);
constexpr int kShift = 4;  // sub-pixel bits for OpenCV drawing

struct Frame {
  double x0, y1, mpp;  // left x, top y, metres per pixel
  cv::Point P(const Eigen::Vector2d& v) const {
    const double s = 1 << kShift;
    return {static_cast<int>(std::lround((v.x() - x0) / mpp * s)),
            static_cast<int>(std::lround((y1 - v.y()) / mpp * s))};
  }
};

std::vector<std::vector<cv::Point>> Rings(const eval::MultiPolygon2& m, const Frame& f) {
  std::vector<std::vector<cv::Point>> out;
  for (const auto& p : m) {
    auto add = [&](const eval::Ring2& r) {
      std::vector<cv::Point> pts;
      for (const auto& v : r) pts.push_back(f.P(v));
      if (pts.size() >= 2) out.push_back(std::move(pts));
    };
    add(p.outer);
    for (const auto& h : p.holes) add(h);
  }
  return out;
}

void Text(cv::Mat& img, const std::string& s, cv::Point at, const cv::Scalar& colour = kBlack) {
  cv::putText(img, s, at, cv::FONT_HERSHEY_SIMPLEX, 0.45, colour, 1, cv::LINE_AA);
}

std::string Percent(const std::optional<double>& v) {
  if (!v) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f%%", *v * 100);
  return buf;
}

constexpr int kLegendLine = 18;
constexpr int kLegendWidth = 300;
int LegendHeight(bool blocks) { return (blocks ? 9 : 8) * kLegendLine + 16; }

// Drawn in a band below the map, so it never hides a roof.
void Legend(cv::Mat& img, int top, const EvalResult& e, const Frame& f, int blocks) {
  const int line = kLegendLine;
  cv::Rect box(8, top + 8, kLegendWidth, LegendHeight(blocks > 0));
  cv::rectangle(img, box, kBlack, 1);
  int y = box.y + line;
  const int x = box.x + 8;
  auto swatch_fill = [&](const cv::Scalar& fill, const std::string& label) {
    cv::rectangle(img, cv::Rect(x, y - 11, 28, 12), fill, cv::FILLED);
    cv::rectangle(img, cv::Rect(x, y - 11, 28, 12), kRefOutline, 1);
    Text(img, label, {x + 36, y});
    y += line;
  };
  auto swatch_line = [&](const cv::Scalar& colour, int thickness, const std::string& label) {
    cv::line(img, {x, y - 5}, {x + 28, y - 5}, colour, thickness, cv::LINE_AA);
    Text(img, label, {x + 36, y});
    y += line;
  };
  swatch_fill(kRefMatchedFill, "reference plane, matched");
  swatch_fill(kRefMissedFill, "reference plane, missed");
  swatch_line(kRefOutline, 1, "reference outline");
  swatch_line(kResCorrect, 2, "result plane, correct");
  swatch_line(kResFalse, 2, "result plane, false");
  if (blocks > 0)
    swatch_line(kLod1Block, 2,
                "LoD1 block" + std::string(blocks > 1 ? "s" : "") + " (" + std::to_string(blocks) +
                    ", scored apart)");
  const auto& p = e.roof_planes;
  Text(img, "planes: compl " + Percent(p.completeness) + "  corr " + Percent(p.correctness),
       {x, y});
  y += line;
  Text(img,
       "quality " + Percent(p.quality) + "  (" + std::to_string(p.n_reference) + " ref, " +
           std::to_string(p.n_result) + " result)",
       {x, y});
  y += line;
  // Scale bar of a round length near 1/4 of the legend width.
  const double target = 120 * f.mpp;
  double len = std::pow(10.0, std::floor(std::log10(target)));
  if (len * 5 <= target)
    len *= 5;
  else if (len * 2 <= target)
    len *= 2;
  const int px = static_cast<int>(std::lround(len / f.mpp));
  cv::line(img, {x, y - 4}, {x + px, y - 4}, kBlack, 2);
  cv::line(img, {x, y - 8}, {x, y}, kBlack, 1);
  cv::line(img, {x + px, y - 8}, {x + px, y}, kBlack, 1);
  char buf[32];
  std::snprintf(buf, sizeof buf, len >= 1 ? "%.0f m" : "%.2f m", len);
  Text(img, buf, {x + px + 8, y});
}

}  // namespace

cv::Mat RenderOverlay(const CityModel& result, const CityModel& truth, const EvalResult& eval,
                      const OverlayOptions& options, const CityModel* blocks) {
  if (!(options.metres_per_pixel > 0) || options.max_side_px < 64)
    throw Error("overlay: metres_per_pixel must be positive and max_side_px at least 64");
  const auto res = eval::ExtractRoofPlanes(result, eval.options.planes);
  const auto ref = eval::ExtractRoofPlanes(truth, eval.options.planes);
  if (res.planes.size() != eval.result_planes.size() ||
      ref.planes.size() != eval.reference_planes.size())
    throw Error("overlay: the evaluation does not belong to these two models");

  const int n_blocks = blocks ? static_cast<int>(blocks->buildings.size()) : 0;
  const auto a = result.Bounds(), b = truth.Bounds();
  double x0 = std::min(a(0), b(0)), y0 = std::min(a(1), b(1));
  double x1 = std::max(a(3), b(3)), y1 = std::max(a(4), b(4));
  if (n_blocks > 0) {
    const auto c = blocks->Bounds();
    x0 = std::min(x0, c(0)), y0 = std::min(y0, c(1));
    x1 = std::max(x1, c(3)), y1 = std::max(y1, c(4));
  }
  if (!std::isfinite(x0) || !std::isfinite(x1)) x0 = y0 = 0, x1 = y1 = 1;
  x0 -= options.margin_m, y0 -= options.margin_m, x1 += options.margin_m, y1 += options.margin_m;
  double mpp = options.metres_per_pixel;
  mpp = std::max(mpp, std::max(x1 - x0, y1 - y0) / options.max_side_px);
  const int cols = std::max(kLegendWidth + 16, static_cast<int>(std::ceil((x1 - x0) / mpp)));
  const int map_rows = static_cast<int>(std::ceil((y1 - y0) / mpp));
  const Frame f{x0, y0 + map_rows * mpp, mpp};
  cv::Mat img(map_rows + LegendHeight(n_blocks > 0) + 16, cols, CV_8UC3, kWhite);

  for (size_t i = 0; i < ref.planes.size(); ++i) {
    const auto rings = Rings(ref.planes[i].outline, f);
    cv::fillPoly(img, rings,
                 eval.reference_planes[i].true_positive ? kRefMatchedFill : kRefMissedFill,
                 cv::LINE_AA, kShift);
  }
  for (const auto& p : ref.planes)
    cv::polylines(img, Rings(p.outline, f), true, kRefOutline, 1, cv::LINE_AA, kShift);
  for (size_t i = 0; i < res.planes.size(); ++i)
    cv::polylines(img, Rings(res.planes[i].outline, f), true,
                  eval.result_planes[i].true_positive ? kResCorrect : kResFalse, 2, cv::LINE_AA,
                  kShift);
  for (int i = 0; i < n_blocks; ++i)
    cv::polylines(img, Rings(eval::BuildingFootprint(blocks->buildings[i], eval.options.planes), f),
                  true, kLod1Block, 2, cv::LINE_AA, kShift);
  cv::line(img, {0, map_rows}, {cols - 1, map_rows}, cv::Scalar(160, 160, 160), 1);
  Legend(img, map_rows, eval, f, n_blocks);
  return img;
}

}  // namespace roofsweep
