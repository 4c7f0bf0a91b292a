#pragma once

namespace roofsweep {

// Options of MatchLines (Scholze et al. 2000, §3). Lengths in pixels unless
// the name says metres, angles in degrees.
struct MatchOptions {
  // ---- geometric candidates (§3.1)
  // A candidate's direction may differ from the segment's by at most this
  // (undirected; corresponding edges in near-nadir aerial views turn little).
  double max_angle_deviation = 20.0;
  // Height range of the scene: ground (constant or DTM, else the lowest
  // camera minus 1000 m) minus this margin up to ground + max building height
  // + this margin; it limits the disparities along the epipolar strip.
  double height_margin_m = 3.0;
  // Segments shorter than this are not matched (the paper uses 15 px).
  double min_length = 15.0;
  // Segments marked as periodic texture (Segment2D::texture: tile courses,
  // brick rows) are matched too. Off: they are the rivals at the wrong
  // depth that the uniqueness step must settle, and the contours that stop
  // a flanking region one tile row away, so that its colours are those of
  // the row, not the face. Leaving them out, over ten blocks x three
  // seeds (matching README, "Texture segments"): 3D line precision +6.0
  // points, roof-edge completeness +1.2, plane quality +1.9 / +2.7 (SE
  // 0.8); Merton I match precision 82.4 -> 88.9 %.
  bool match_texture = false;
  // Where the segment meets the epipolar lines of the other view at less than
  // this angle, the pair is skipped and other views are used (§3.4). The
  // paper's 40 deg assumes another view always helps; in a two-strip block an
  // edge along the flight line near the block's edge is seen by one strip
  // only, whose pairs meet it at a few degrees, and hips at 20-40 deg lose
  // their in-strip pairs. 20 deg (depth error at most 1/sin 20 = 2.9 times
  // that of a perpendicular edge) measured on the matched lines, plane
  // quality without / with footprints: realistic s1 42.4 / 47.6 -> 47.6 /
  // 58.3 %, s2 35.2 / 51.4 -> 38.7 / 54.0 %, s3 31.9 / 44.4 -> 35.0 / 44.7 %,
  // Berlin 36.2 / 37.0 -> 38.0 / 37.8 %, easy 46.7 / 58.9 -> 46.2 / 58.4 %;
  // 30 deg was between; keeping 40 deg unless no view offers it was worse
  // (Berlin 29.4 / 23.4 %). `bench` run 13.3 -> 14.0 s.
  double min_epipolar_angle = 20.0;
  // Minimum length of the common part of both segments (px in the first view).
  double min_common_length = 10.0;

  // ---- chromatic attributes (§3.2)
  // Balance the colours of the views against each other before the L*a*b*
  // conversion (per-view gain and offset per channel from the overlaps, see
  // colour_balance.h): flight lines differ in colour calibration.
  bool colour_balance = true;
  double region_offset = 1.0;  // px between the segment and its flanking region
  double region_width = 10.0;  // px
  // L* outliers: farther than this many robust standard deviations from the
  // univariate MCD location.
  double l_outlier_sigmas = 2.5;
  int min_region_pixels = 20;  // fewer: the side has no attributes

  // ---- chromatic tests (§3.3)
  // Thresholds on t_mean (eq. 5) and t_cov (eq. 6): <= 0 means automatic,
  // threshold_factor times the median of the statistics of ~init_segments
  // random segments' geometric candidates, after dropping those rejected at
  // significance 0.001 (chi2 quantiles 13.82 for 2 dof, 16.27 for 3 dof).
  double mean_threshold = -1;
  double cov_threshold = -1;
  int init_segments = 60;
  // Initialisation pairs: per random segment the candidate side with the
  // highest a*b* correlation, when above this (see MatchLines).
  double init_min_correlation = 0.5;
  // true: per random segment the candidate side that correlates best in
  // a*b* (see MatchLines): thresholds that keep more of the true pairs
  // (92.5 % of the eligible ones on realistic s1, session 17), but twice
  // the candidates reach the correlation. false (default): the candidate
  // side with the smallest statistics, the minimum over all candidates:
  // lower thresholds (43 % kept on s1; see the matching README). Measured end
  // to end (`roofsweep run`, realistic seeds 1 and 2): false gives plane
  // quality 32.5 / 21.0 % against 27.1 / 18.2 % in 30 s against 55 s, so
  // it is the default.
  bool init_from_best_correlation = false;
  // The median alone would reject half of the correct pairs; the factor
  // turns it into a threshold (measured on the simulated blocks, see report).
  double threshold_factor = 8.0;
  // The statistics grow with the pixel count n; n is capped so that long
  // segments are not held to a stricter standard than short ones.
  int max_test_pixels = 200;

  // ---- correlation (§3.4)
  // Correlate L* too, h = 2/3 (ncc_a* + ncc_b* + ncc_L*), so h keeps its
  // range [-2, 2] — an addition to the paper, which correlates a* and b*
  // only so that the measure does not depend on illumination; NCC already
  // removes a gain and an offset per window. On roofs of one material a*
  // and b* hold little but noise, and where a roof is seen in two views
  // only, the correlation and the junction ends decide between rival
  // partners (README "True edges through the funnel"). 30 paired runs
  // (10 simulated blocks x 3 seeds): 3D line precision +1.14 +- 0.20 and
  // roof-edge completeness +0.60 +- 0.16; Merton I match precision 88.9 ->
  // 92.6 % at equal recall.
  bool correlate_lightness = true;
  double ncc_window = 7.0;   // px along the segment, window of pointwise NCC
  double sample_step = 1.0;  // px along the common part
  // The flanking area in the second view is scaled by s in [1/max, max]
  // across the segment (foreshortening), tried in scale_steps steps.
  double max_scale = 1.4;
  int scale_steps = 5;
  // A side correlates when its mean h (ncc_a + ncc_b, in [-2, 2]) exceeds
  // this (the paper: positive).
  double min_correlation = 0.0;

  // ---- multi-view verification
  // A detected segment supports a projected hypothesis when its endpoints
  // are within this distance of the projected line and directions agree
  // within verify_max_angle.
  double verify_distance = 2.0;
  double verify_max_angle = 5.0;
  // Where no segment was detected, mean gradient magnitude along the
  // projection (intensity/px, [0,1] images) above this also supports it.
  double verify_min_gradient = 0.03;
  // Fraction of the other views that see the hypothesis that must support it
  // (a detected segment counts 1, a gradient without a segment 0.5), and the
  // least number of other views with a supporting segment (when any sees it).
  double min_support_fraction = 0.5;
  int min_support_segments = 2;
  // Projections shorter than this in a view do not count as seeing it.
  double verify_min_length = 10.0;

  // ---- assignment
  // Drop a verified hypothesis when another one gives one of its segments a
  // different 3D line with at least its score (UnambiguousItems), before the
  // greedy one-to-one assignment.
  bool unique_matches = true;
  // Rank hypotheses of equal support by how many of their ends meet another
  // hypothesis in 3D (JunctionSupport) before the correlation: the score is
  // support + (junction ends + correlation) / 3 instead of support +
  // correlation. Support decides first, as before; of two rivals for a
  // segment with equal support the one that fits the lines around it wins.
  // On realistic s1, 25 % of the verified true hypotheses have both ends on
  // another line and 38 % neither, against 4 % and 74 % of the false ones.
  // Over ten simulated blocks and three seeds (30 paired runs): 3D line
  // precision +1.5 points (28 of 30 up), roof-edge completeness +0.6; plane
  // quality -0.5 +- 0.5 from matched lines, -0.6 +- 0.6 with footprints
  // (within the seeds' own spread). Merton I match precision 79.2 -> 82.4 %,
  // recall 26.7 -> 28.9 %; Model House 77.2 -> 76.8 %.
  bool junction_ranking = true;
  // An end meets a line within this distance (JunctionSupportOptions).
  double junction_rank_distance_m = 0.3;

  // ---- 3D estimation
  // Collinear 3D fragments are merged when their directions differ by less
  // than merge_angle and each endpoint lies within merge_distance_m of the
  // other line, with a gap at most merge_gap_m.
  double merge_angle = 2.0;
  double merge_distance_m = 0.1;
  double merge_gap_m = 0.5;
  // Lines with an RMS endpoint-to-line reprojection residual above this are dropped.
  double max_residual = 1.5;
  // Significance of the residual test of lines in three or more views
  // against the noise level estimated from the block's own lines
  // (residual_test.h); 0 switches the test off. 0.001: a correct line is
  // rejected once in a thousand.
  double residual_alpha = 0.001;
  // At least this many views must observe a final line.
  int min_views = 2;

  // Cut a line's ends that no stereo pair holds (one view alone, or views
  // along the line's epipolar lines) back to the part a pair holds, unless
  // the other views that see them confirm them at the line's depth
  // (CutUnconfirmedEnds).
  bool check_ends = true;

  // ---- junction completion (CompleteAtJunctions): segments no stereo pair
  // reached, reconstructed from the 3D lines their ends meet. The end must
  // come within junction_px of the anchor's piercing point, which must lie
  // within junction_gap_m of the anchor's end (edge detectors stop a few
  // pixels short of corners: 1 m is 20 px at 5 cm GSD) and pierce the
  // segment's interpretation plane at junction_min_angle or more.
  bool junction_completion = true;
  double junction_px = 6.0;
  double junction_gap_m = 1.0;
  double junction_min_angle = 15.0;
  double junction_min_length_m = 1.0;
  // A segment anchored at one end only becomes a horizontal line at the
  // anchor's height (eaves and ridges; see CompleteAtJunctions).
  bool junction_horizontal = true;

  // Seed of the random threshold initialisation.
  unsigned seed = 1;
};

}  // namespace roofsweep
