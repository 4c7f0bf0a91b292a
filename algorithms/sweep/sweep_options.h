#pragma once

namespace roofsweep {

// Options of the half-plane sweep (Baillard & Zisserman 2000, §3). Defaults
// are the paper's where it gives them, otherwise chosen on simulated blocks
// at 5 cm GSD.
struct SweepOptions {
  // Swept angle range and coarse step (degrees; paper: [-75, 75]). Sim's
  // peaks are 10-30 deg wide, so 4 deg loses nothing before the parabolic
  // refinement: on `realistic` seeds 1/2 (rs_sweep_sim_eval) acceptance
  // 30.2/31.1 % -> 30.0/32.4 %, median error 0.11/0.08 -> 0.10/0.07 deg,
  // sweep 7.4/5.8 -> 5.3/4.7 s against a 2 deg step.
  double theta_min_deg = -75.0;
  double theta_max_deg = 75.0;
  double coarse_step_deg = 4.0;
  // Parabolic refinement stops when the bracket half-width falls below this
  // (paper: "uncertainty less than 1 degree").
  double refine_tolerance_deg = 0.5;
  // The coarse sweep uses at most this many of a side's points (an even
  // subset; 0: all); outlier removal, refinement and the acceptance use all.
  int coarse_max_points = 80;

  // Acceptance (paper, figure 5): Sim(theta*) >= min_similarity and
  // |Sim''(theta*)| >= min_curvature, with Sim'' per radian squared (the
  // paper's figure 5 plots Sim against the angle; a peak of height ~0.3
  // above its base with a half-width of ~15 deg has |Sim''| ~ 4 per rad^2,
  // while 4 per deg^2 would need the score to drop by 2 within one degree,
  // impossible for Sim in [0, 1]). The second derivative is the central
  // difference over +-curvature_step_deg around theta*.
  double min_similarity = 0.4;
  double min_curvature = 4.0;
  double curvature_step_deg = 2.0;
  // Candidates: half-planes whose interior maximum reaches these looser
  // values propose planes too; roofsweep's grouping uses them and leaves
  // the decision to the verification of the whole plane patch over all
  // views (§5), which separates true planes far more sharply than Sim''
  // does at the small base-to-height ratios of nadir blocks (on the
  // `realistic` block's true edges: plane completeness 33 -> 42 %, with
  // correctness 95 -> 100 %). Set them to min_similarity / min_curvature
  // for the paper's behaviour.
  double candidate_min_similarity = 0.2;
  double candidate_min_curvature = 1.0;
  // Sim's height falls with image noise, haze and low contrast; its shape
  // does not. From true edges (rs_sweep_sim_eval, seed 1) the median Sim of
  // true faces is 0.40 on `realistic` and 0.13 on `hard`, yet their peaks
  // stand a median 4.8 times above the median of their coarse profile on
  // both (sides without a face: 3.0-3.4 times). So the block calibrates the
  // candidate threshold on its own clear peaks: the sides whose maximum
  // stands calibration_peak_ratio times above their profile (at least
  // calibration_min_sides of them). Their median Sim over
  // calibration_reference_similarity (that median on `realistic`) scales
  // candidate_min_similarity down, never up, and not below
  // candidate_floor_similarity. calibration_peak_ratio 0 turns it off.
  double calibration_peak_ratio = 5.0;
  int calibration_min_sides = 30;
  double calibration_reference_similarity = 0.32;
  double candidate_floor_similarity = 0.05;
  // A side needs at least this many points of interest and this many views
  // besides the reference. One other view suffices: near the block's edges
  // a roof is seen by two images of one strip only (half the `realistic`
  // block), and the verification of the whole patch over all views follows.
  // With 2, 118 of the 450 true roof sides of `realistic` seed 1 were
  // rejected for it; with 1 the acceptance on roof sides is 39.1 % instead
  // of 30.0 % (median angle error 0.12 deg instead of 0.10; sides without a
  // roof face accepted 6.5 % instead of 5.0 %).
  int min_points = 20;
  int min_views = 1;

  // Neighbourhood of the projected line in the reference view (a simple
  // stand-in for the paper's constrained Delaunay triangulation): a band of
  // this width (px) on the side, shortened by end_margin_px at both ends,
  // and clipped where another projected 3D line lies between a point and
  // the line. Points are kept min_distance_px + ncc_radius off the line so
  // that no correlation window reaches within min_distance_px of it: pixels
  // on the line map to themselves for every theta, and a window straddling
  // the line correlates the other side's texture.
  // 100 px = 5 m at 5 cm GSD: with the small base-to-height ratios of
  // nadir blocks (0.04..0.08 on `realistic`) points near the line hardly
  // move with theta; on the realistic block 100 px instead of 40 px raised
  // the acceptance on textured faces from 7 % to 35 % (median angle error of
  // all swept sides 0.78 deg instead of 1.43 deg).
  double band_width_px = 100.0;
  double min_distance_px = 2.0;
  double end_margin_px = 3.0;
  bool clip_at_other_lines = true;

  // Points of interest: Canny edges of the grey image (0..255 scale, after a
  // Gaussian blur of poi_blur_sigma px) with a very low threshold, as the
  // paper asks, at most max_points per side (evenly thinned).
  double poi_blur_sigma = 1.0;
  double poi_canny_low = 4.0;
  double poi_canny_high = 8.0;
  int max_points = 300;

  // Correlation: NCC on the grey image over a (2 r + 1)^2 window mapped
  // point by point through the homography (7 x 7 by default).
  int ncc_radius = 3;
  // ... and wide_ncc_radius on noisy imagery: where the block's clear peaks
  // correlate at less than wide_window_below of a clean block's (the
  // candidate threshold scaled below wide_window_below x
  // candidate_min_similarity), run sweeps again with the wider window,
  // which averages the noise over 2.5 times the pixels. From true edges on
  // `hard` s1 (rs_sweep_sim_eval), 11 x 11 brought the swept sides within 2
  // deg of their face from 58.9 to 69.4 %; on `realistic` s1 it doubled
  // the sides accepted without a face (6.5 -> 13.4 %), and plane quality
  // from matched lines fell from 86.4 to 79.5 %: clean imagery keeps 7 x 7.
  // The scale is 1 on `realistic`, `easy` and Berlin, 0.45 on `hard`.
  // wide_ncc_radius <= ncc_radius turns it off.
  int wide_ncc_radius = 5;
  double wide_window_below = 0.6;
  // Outlier removal after the coarse sweep: points whose mean squared
  // correlation over the views at the coarse maximum is below this are
  // dropped, keeping at least the better half of the points.
  double outlier_min_score = 0.1;
  // Valid views (paper §3.3: "a sufficient number of high correlation
  // scores"): after outlier removal, a view whose weighted mean squared
  // correlation at the coarse maximum is below this fraction of the best
  // view's is dropped from Sim (occlusion, strong perspective change).
  double valid_view_ratio = 0.5;

  // Face extent (HalfPlane::extent_m): the extent_quantile of the distances
  // from the line of the points whose mean Cor+^2 at theta* is at least
  // extent_min_score.
  double extent_min_score = 0.25;
  double extent_quantile = 0.9;
  // Lines steeper than this (deg from horizontal) have no horizontal side.
  double max_line_slope_deg = 80.0;
  // A view sees the line when both end points are in front and a part of
  // at least min_visible_px of its projection is view_margin_px (plus the
  // NCC radius) inside the image; in the reference view the band follows
  // that part only.
  double view_margin_px = 4.0;
  double min_visible_px = 20.0;
};

}  // namespace roofsweep
