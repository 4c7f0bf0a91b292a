#pragma once

#include <vector>

#include "algorithms/edges/segment2d.h"

namespace roofsweep {

// Options of ExtractSegments. Lengths in pixels, angles in degrees,
// gradient magnitudes in intensity units ([0, 1] images) per pixel.
struct EdgeOptions {
  // Gradient fusion of the colour bands; grey images always use kGrey.
  GradientMethod method = GradientMethod::kMax;

  // Standard deviation of the Gaussian applied to each band before the
  // central-difference gradient.
  double sigma = 1.0;

  // Hysteresis thresholds on the fused gradient magnitude. Negative means
  // automatic (the default), from the gradient statistics:
  //   noise  = median(|grad|) / sqrt(2 ln 2)   (the median of a Rayleigh
  //            variable is sigma sqrt(2 ln 2); edges and texture only push
  //            the median up, so the estimate errs on the safe side)
  //   high   = max(auto_high_factor * noise, auto_min_high)
  //   low    = auto_low_ratio * high
  // (On the merton1 test images low ratios from 0.4 to 0.6 find the same
  // share of the reference lines; 0.6 keeps fewer texture points, which
  // saves a fifth of the time.)
  // The median is taken over every second pixel in each direction.
  double high_threshold = -1;
  double low_threshold = -1;
  double auto_high_factor = 2.0;
  double auto_low_ratio = 0.6;
  // Floor for the automatic high threshold, for images whose median
  // gradient is ~0 (noise-free synthetic ones, large saturated areas):
  // 0.003 is the peak of a 2/255 step blurred with sigma 1, so 8-bit
  // quantisation contours stay out, while a step of 0.01 (a 16 % edge in
  // 12-bit data stored as 16 bits, values up to 0.0625) peaks at 0.004.
  double auto_min_high = 0.003;

  // Edge linking: neighbouring edge points link when their gradient
  // directions differ by less than this (mod 180°).
  double link_max_angle = 40.0;
  // Chains are split where the tangent turns by more than this between the
  // `tangent_window` points before and after a point.
  double split_tangent_angle = 30.0;
  int tangent_window = 6;

  // Line fitting (orthogonal regression, recursive split): no edge point
  // farther than this from the fitted line...
  double fit_max_deviation = 1.0;
  // ...and no systematic curvature: a segment whose residuals follow a
  // parabola with sagitta above this, significant at 3 standard errors and
  // explaining at least fit_curve_min_explained of the residual sum of
  // squares, is split, so arcs are not approximated piecewise (an arc of
  // radius R then gives pieces of at most sqrt(8 R fit_max_sagitta) px,
  // shorter than min_length up to R ~ 90 px).
  double fit_max_sagitta = 0.3;
  double fit_curve_min_explained = 0.9;
  // Up to this many points at either end of a piece are dropped while they
  // lie farther than end_trim_distance from the line through the rest
  // (corners and junctions, rounded by the smoothing, bend the last points).
  int end_trim_points = 4;
  double end_trim_distance = 0.8;
  // Pieces with fewer edge points are dropped before merging.
  int min_support = 6;

  // Merging of collinear segments across small gaps.
  double merge_max_gap = 5.0;     // endpoint to endpoint along the line
  double merge_max_angle = 2.0;   // between the two directions
  double merge_max_offset = 1.0;  // endpoint distance to the other line
  bool merge = true;

  // Segments shorter than this are dropped (Scholze et al. use 15 px).
  double min_length = 15.0;

  // Side colours are averaged along the lines parallel to the segment at
  // this distance on either side: beyond the blur of the edge itself (the
  // smoothing plus a pixel), close enough to stay on the face it bounds.
  double side_distance = 2.5;

  // Texture: tile courses, brick rows and paving give rows of parallel
  // edges of one polarity a few pixels apart. Their segments are not scene
  // edges, and in matching they are the rivals at the wrong depth and the
  // contours that stop the flanking regions a row away
  // (MatchOptions::match_texture). A segment is marked
  // (Segment2D::texture) when a parallel segment of the same polarity lies on each side
  // at offsets in [texture_min_offset, texture_max_offset] px that differ
  // by at most texture_spacing_ratio (a period), each overlapping it along
  // texture_min_overlap of the shorter one, and it is not
  // texture_dominance times as strong as one of them. Same polarity keeps
  // both edges of a painted stripe and an eave beside its cast shadow.
  bool mark_texture = true;
  double texture_max_angle = 5.0;
  double texture_min_offset = 2.0;
  double texture_max_offset = 16.0;  // a period of 0.8 m at 5 cm GSD
  double texture_spacing_ratio = 2.0;
  double texture_min_overlap = 0.5;
  double texture_dominance = 1.5;

  // Optional fusion (§2.3): segments from these methods that are not
  // already present in the result of `method` are added. Empty: off.
  std::vector<GradientMethod> fuse_methods;
  // A segment counts as present when a kept one lies within this distance
  // and angle and covers at least this fraction of its length.
  double fuse_max_distance = 2.0;
  double fuse_max_angle = 5.0;
  double fuse_min_overlap = 0.5;

  // Coarse-scale fusion — an addition to the paper. Where tile courses or
  // other fine texture cross an edge (the hips and valleys of tiled roofs,
  // the courses of both faces meeting there at an angle), non-maximum
  // suppression follows the courses, so the edge's points link into the
  // courses' chains and the edge itself breaks into pieces shorter than
  // min_length. The same extraction on the image averaged down 2 x 2 (the
  // courses, a few pixels apart, average out there; the edge between two
  // faces of different shading stays) finds those edges. The parts of its
  // segments, at least coarse_min_length (full-resolution pixels) long,
  // that no full-resolution segment covers (within fuse_max_distance and
  // fuse_max_angle) are added when at least min_length long.
  // Off by default: on 30 simulated runs it raised roof-edge completeness of
  // the 3D lines by 1.7 points at 0.9 points of precision, but not the roof
  // planes (algorithms/edges/README.md).
  bool coarse_fusion = false;
  double coarse_min_length = 50.0;
};

}  // namespace roofsweep
