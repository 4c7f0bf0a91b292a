#include "algorithms/edges/segment_index.h"

#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/core/error.h"
#include "algorithms/edges/extract_segments.h"
#include "algorithms/edges/segment_fusion.h"
#include "algorithms/edges/segment_geometry.h"
#include "algorithms/edges/synthetic_images.h"

namespace roofsweep {
namespace {

Segment2D Seg(double x0, double y0, double x1, double y1) {
  Segment2D s;
  s.p0 = {x0, y0};
  s.p1 = {x1, y1};
  return s;
}

Segments2D RandomSegments(int count, std::uint64_t seed) {
  cv::RNG rng(seed);
  Segments2D out;
  for (int i = 0; i < count; ++i) {
    const double x = rng.uniform(0.0, 500.0), y = rng.uniform(0.0, 400.0);
    const double a = rng.uniform(0.0, 2 * M_PI), l = rng.uniform(15.0, 80.0);
    out.push_back(Seg(x, y, x + l * std::cos(a), y + l * std::sin(a)));
  }
  return out;
}

TEST(SegmentGeometry, Distances) {
  const Segment2D a = Seg(0, 0, 10, 0);
  EXPECT_DOUBLE_EQ(PointSegmentDistance({5, 3}, a), 3);
  EXPECT_DOUBLE_EQ(PointSegmentDistance({13, 4}, a), 5);
  EXPECT_DOUBLE_EQ(SegmentDistance(a, Seg(5, -1, 5, 1)), 0);  // crossing
  EXPECT_DOUBLE_EQ(SegmentDistance(a, Seg(12, 0, 20, 0)), 2);
  EXPECT_DOUBLE_EQ(SegmentDistance(a, Seg(3, 2, 7, 2)), 2);
  EXPECT_NEAR(LineAngleDeg(a, Seg(0, 0, -10, 0)), 0, 1e-12);
  EXPECT_NEAR(LineAngleDeg(a, Seg(0, 0, 1, 1)), 45, 1e-12);
}

TEST(SegmentGeometry, CoveredFraction) {
  const Segment2D t = Seg(0, 0, 100, 0);
  EXPECT_NEAR(CoveredFraction(t, Seg(20, 1, 80, 1), 2, 5), 0.6, 1e-12);
  EXPECT_NEAR(CoveredFraction(t, Seg(80, 1, 20, 1), 2, 5), 0.6, 1e-12);  // orientation ignored
  EXPECT_NEAR(CoveredFraction(t, Seg(-50, 0, 150, 0), 2, 5), 1.0, 1e-12);
  EXPECT_EQ(CoveredFraction(t, Seg(20, 3, 80, 3), 2, 5), 0);    // too far
  EXPECT_EQ(CoveredFraction(t, Seg(20, 0, 80, 10), 2, 5), 0);   // angle 9.5°
  EXPECT_EQ(CoveredFraction(t, Seg(120, 0, 180, 0), 2, 5), 0);  // beside
  // Crossing at a small angle: only the part within 2 px counts... both
  // clipped ends must be close, so a tilted segment reaching 3 px fails.
  EXPECT_EQ(CoveredFraction(t, Seg(0, -1, 100, 3), 2, 5), 0);
  EXPECT_NEAR(CoveredFraction(t, Seg(0, -1, 100, 1.5), 2, 5), 1.0, 1e-12);
}

// (g) The R-tree returns exactly the neighbours a brute-force scan finds.
TEST(SegmentIndex, NeighbourQueriesMatchBruteForce) {
  const Segments2D segments = RandomSegments(600, 5);
  const SegmentIndex index(segments);
  EXPECT_EQ(index.size(), 600);
  cv::RNG rng(6);
  int total = 0;
  for (int q = 0; q < 200; ++q) {
    const int id = rng.uniform(0, 600);
    const double radius = rng.uniform(0.0, 30.0);
    std::vector<int> expected;
    for (int j = 0; j < 600; ++j) {
      if (j != id && SegmentDistance(segments[id], segments[j]) <= radius) expected.push_back(j);
    }
    EXPECT_EQ(index.Neighbours(id, radius), expected);
    total += static_cast<int>(expected.size());

    const Eigen::Vector2d p(rng.uniform(0.0, 500.0), rng.uniform(0.0, 400.0));
    std::vector<int> near_point;
    for (int j = 0; j < 600; ++j) {
      if (PointSegmentDistance(p, segments[j]) <= radius) near_point.push_back(j);
    }
    EXPECT_EQ(index.NearPoint(p, radius), near_point);
  }
  EXPECT_GT(total, 200);  // the queries did find neighbours
  const std::vector<int> in_box = index.InBox({100, 100}, {200, 150});
  for (int j = 0; j < 600; ++j) {
    const auto& s = segments[j];
    const bool meets = std::max(s.p0.x(), s.p1.x()) >= 100 && std::min(s.p0.x(), s.p1.x()) <= 200 &&
                       std::max(s.p0.y(), s.p1.y()) >= 100 && std::min(s.p0.y(), s.p1.y()) <= 150;
    EXPECT_EQ(std::binary_search(in_box.begin(), in_box.end(), j), meets) << j;
  }
  EXPECT_THROW(index.Neighbours(600, 1), Error);
}

TEST(SegmentIndex, EmptyAndNonFinite) {
  const SegmentIndex empty(Segments2D{});
  EXPECT_TRUE(empty.Near(Seg(0, 0, 1, 1), 10).empty());
  EXPECT_THROW(SegmentIndex(Segments2D{Seg(0, 0, NAN, 1)}), Error);
}

// (h) The label map agrees with the segments.
TEST(RasterizeSegments, LabelMapAgreesWithSegments) {
  const cv::Size size(320, 240);
  const cv::Mat image = testing::RenderRoofScene(size, 17);
  const Segments2D segments = ExtractSegments(image, EdgeOptions{});
  ASSERT_GT(segments.size(), 30u);
  const cv::Mat labels = RasterizeSegments(segments, size);
  ASSERT_EQ(labels.type(), CV_32S);
  ASSERT_EQ(labels.size(), size);
  std::vector<int> pixels(segments.size(), 0);
  int labelled = 0;
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      const int id = labels.at<int>(y, x);
      ASSERT_GE(id, -1);
      ASSERT_LT(id, static_cast<int>(segments.size()));
      if (id < 0) continue;
      ++labelled;
      ++pixels[id];
      // The segment passes through this pixel: within half a diagonal of its centre.
      EXPECT_LE(PointSegmentDistance({x + 0.5, y + 0.5}, segments[id]), std::sqrt(0.5) + 1e-9);
    }
  }
  EXPECT_GT(labelled, 0);
  // Every segment owns most of its pixels (crossings are lost to the longer one).
  for (size_t i = 0; i < segments.size(); ++i) {
    const double l = segments[i].Length();
    EXPECT_GE(pixels[i], 0.8 * l) << i;
    EXPECT_LE(pixels[i], 2.0 * l + 2) << i;
  }
  // The longer segment wins a shared pixel.
  const Segments2D crossing = {Seg(0, 5.5, 20, 5.5), Seg(5.5, 0, 5.5, 30)};
  const cv::Mat l2 = RasterizeSegments(crossing, cv::Size(40, 40));
  EXPECT_EQ(l2.at<int>(5, 5), 1);
  EXPECT_EQ(l2.at<int>(5, 10), 0);
  EXPECT_EQ(l2.at<int>(20, 5), 1);
  EXPECT_EQ(l2.at<int>(30, 30), -1);
}

TEST(AddMissingSegments, AddsOnlyWhatIsNotPresent) {
  Segments2D base = {Seg(0, 0, 100, 0), Seg(0, 50, 0, 100)};
  const Segments2D extra = {Seg(10, 1, 90, 1),     // present (covered by base[0])
                            Seg(0, 60, 0.5, 120),  // half covered (40/60 > 50 %)
                            Seg(50, 50, 90, 90),   // new
                            Seg(52, 51, 88, 87)};  // covered by the one just added
  EXPECT_EQ(AddMissingSegments(base, extra, 2, 5, 0.5), 1);
  ASSERT_EQ(base.size(), 3u);
  EXPECT_EQ(base[2].p0, Eigen::Vector2d(50, 50));
}

}  // namespace
}  // namespace roofsweep
