// Real-data check on the Oxford VGG "Merton College I" images, which come
// with hand-checked line segments (2D/00N.lines).

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "algorithms/edges/extract_segments.h"
#include "algorithms/edges/segment_geometry.h"
#include "tests/support/shared_data.h"

namespace roofsweep {
namespace {

// VGG files put the origin at the centre of the top-left pixel: +0.5 px.
Segments2D ReadVggLines(const std::string& path) {
  std::ifstream in(path);
  Segments2D out;
  double x0, y0, x1, y1;
  while (in >> x0 >> y0 >> x1 >> y1) {
    Segment2D s;
    s.p0 = {x0 + 0.5, y0 + 0.5};
    s.p1 = {x1 + 0.5, y1 + 0.5};
    out.push_back(s);
  }
  return out;
}

// Share of the reference lines that one found segment covers to >= 50 %
// of their length within 2 px and 5°.
double MatchedShare(const Segments2D& reference, const Segments2D& found) {
  int matched = 0;
  for (const auto& r : reference) {
    for (const auto& s : found) {
      if (CoveredFraction(r, s, 2.0, 5.0) >= 0.5) {
        ++matched;
        break;
      }
    }
  }
  return reference.empty() ? 0 : static_cast<double>(matched) / reference.size();
}

Segments2D Lsd(const cv::Mat& bgr8) {
  cv::Mat grey;
  cv::cvtColor(bgr8, grey, cv::COLOR_BGR2GRAY);
  std::vector<cv::Vec4f> lines;
  cv::createLineSegmentDetector()->detect(grey, lines);
  Segments2D out;
  for (const auto& l : lines) {
    Segment2D s;
    // LSD's coordinates are pixel-centre based as well.
    s.p0 = {l[0] + 0.5, l[1] + 0.5};
    s.p1 = {l[2] + 0.5, l[3] + 0.5};
    out.push_back(s);
  }
  return out;
}

TEST(MertonLines, MostAnnotatedLinesAreFound) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(root, "data/multiview/oxford-vgg/merton1");
  double sums[4] = {0, 0, 0, 0};
  size_t counts[4] = {0, 0, 0, 0};
  const char* names[4] = {"max", "dizenzo", "grey", "opencv-lsd"};
  for (const char* id : {"001", "002", "003"}) {
    const cv::Mat bgr8 = cv::imread(root + "/images/" + id + ".jpg", cv::IMREAD_COLOR);
    ASSERT_FALSE(bgr8.empty()) << id;
    cv::Mat rgb8, rgb;
    cv::cvtColor(bgr8, rgb8, cv::COLOR_BGR2RGB);
    rgb8.convertTo(rgb, CV_32FC3, 1.0 / 255.0);
    const Segments2D reference = ReadVggLines(root + "/2D/" + id + ".lines");
    ASSERT_GT(reference.size(), 500u);

    double share[4];
    const GradientMethod methods[3] = {GradientMethod::kMax, GradientMethod::kDiZenzo,
                                       GradientMethod::kGrey};
    for (int m = 0; m < 3; ++m) {
      EdgeOptions o;
      o.method = methods[m];
      const Segments2D found = ExtractSegments(rgb, o);
      share[m] = MatchedShare(reference, found);
      counts[m] += found.size();
    }
    const Segments2D lsd = Lsd(bgr8);
    share[3] = MatchedShare(reference, lsd);
    counts[3] += lsd.size();
    for (int m = 0; m < 4; ++m) {
      sums[m] += share[m];
      std::printf("merton1 %s %-10s %5.1f %% of %zu annotated lines matched\n", id, names[m],
                  100 * share[m], reference.size());
    }
    EXPECT_GE(share[0], 0.85) << "image " << id << ", default (max) method";
  }
  for (int m = 0; m < 4; ++m) {
    std::printf("merton1 mean  %-10s %5.1f %%  (%zu segments in 3 images)\n", names[m],
                100 * sums[m] / 3, counts[m]);
  }
}

}  // namespace
}  // namespace roofsweep
