#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace roofsweep {

// How the colour bands were fused into one gradient (Scholze et al. 2000, §2).
enum class GradientMethod : std::uint8_t {
  kMax,      // maximum of the per-band gradient norms (§2.1, the default)
  kDiZenzo,  // spatial gradient: sqrt of the largest eigenvalue of JᵀJ (§2.2)
  kGrey,     // gradient of the grey level 0.299 R + 0.587 G + 0.114 B (the usual baseline)
};

// Which band carried a segment's gradient.
enum class EdgeBand : std::uint8_t { kRed, kGreen, kBlue, kFused, kGrey };

// A straight image edge segment. Pixel convention as everywhere in
// roofsweep: x right, y down, origin at the top-left CORNER of the image.
//
// Orientation: walking from p0 to p1 the brighter side (the side the
// carrying gradient points to) is on the LEFT, i.e. along LeftNormal() =
// (d.y, -d.x) for the unit direction d. With y down, "left" is what a
// viewer of the image sees as left of the walking direction.
struct Segment2D {
  Eigen::Vector2d p0 = Eigen::Vector2d::Zero();  // sub-pixel endpoints
  Eigen::Vector2d p1 = Eigen::Vector2d::Zero();
  float contrast = 0;      // mean fused gradient magnitude along it (intensity / px)
  float rms_residual = 0;  // RMS orthogonal distance of the edge points to the line, px
  int support = 0;         // number of edge points the line was fitted to
  EdgeBand band = EdgeBand::kFused;
  GradientMethod method = GradientMethod::kMax;  // detector that found it
  // Mean colour (R, G, B in [0, 1]; grey images repeat the grey value)
  // along a line on each side, a few pixels (EdgeOptions::side_distance)
  // from the segment.
  Eigen::Vector3f colour_left = Eigen::Vector3f::Zero();
  Eigen::Vector3f colour_right = Eigen::Vector3f::Zero();
  // Inside a periodic pattern of parallel edges (tile courses, brick rows;
  // EdgeOptions::mark_texture): a real image edge, but no edge of the
  // scene's geometry, and ambiguous to match.
  bool texture = false;
  // Image scale the segment was found at: 1 at full resolution, 2 from the
  // coarse pass over the half-resolution image (EdgeOptions::coarse_fusion).
  std::uint8_t scale = 1;

  double Length() const { return (p1 - p0).norm(); }
  Eigen::Vector2d Direction() const { return (p1 - p0).normalized(); }
  Eigen::Vector2d LeftNormal() const {
    const Eigen::Vector2d d = Direction();
    return {d.y(), -d.x()};
  }
  Eigen::Vector2d Midpoint() const { return 0.5 * (p0 + p1); }
};

using Segments2D = std::vector<Segment2D>;

}  // namespace roofsweep
