#pragma once

// Synthetic test images for the edge tests and benchmark (not part of the
// library).

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

namespace roofsweep::testing {

// Renders a CV_32FC3 (R, G, B) image in which the point (x, y) (corner
// convention) has colour colours[region(x, y)], anti-aliased by averaging
// `supersample` x `supersample` samples per pixel.
cv::Mat RenderRegions(cv::Size size, const std::function<int(double, double)>& region,
                      const std::vector<cv::Vec3f>& colours, int supersample = 16);

// Two colours either side of the line through `point` with direction
// angle `angle_deg` (x right, y down): `left` on the side of the normal
// (d.y, -d.x), as in Segment2D.
cv::Mat RenderHalfPlanes(cv::Size size, const Eigen::Vector2d& point, double angle_deg,
                         const cv::Vec3f& left, const cv::Vec3f& right, int supersample = 16);

// Adds Gaussian noise (standard deviation `sigma`) to every band, seeded.
void AddNoise(cv::Mat& image, double sigma, std::uint64_t seed);

// A roof-like aerial scene for the benchmark: a textured, noisy ground with
// many rotated rectangular buildings, each with a gable roof (two faces of
// one colour, differently shaded, with a ridge), a few flat roofs,
// roads and trees (blobs), quantised to 8 bits as a camera would give.
// CV_32FC3 in [0, 1], deterministic in `seed`.
cv::Mat RenderRoofScene(cv::Size size, std::uint64_t seed);

// Rec. 601 luma, as cv::cvtColor(RGB2GRAY).
inline float Luma(const cv::Vec3f& c) { return 0.299f * c[0] + 0.587f * c[1] + 0.114f * c[2]; }

}  // namespace roofsweep::testing
