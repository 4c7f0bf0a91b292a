#pragma once

#include <limits>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/buildings/right_corners.h"
#include "algorithms/core/progress.h"
#include "algorithms/geometry/block.h"

namespace roofsweep {

// Options of the photometric verification of plane patches (Baillard &
// Zisserman 2000, §5: "patch verification over all views by correlation").
struct VerifyOptions {
  // Samples on a plan-view grid of this spacing (m) inside the patch; at
  // most max_samples textured ones, spread over the patch, are scored.
  double spacing_m = 0.25;
  int max_samples = 400;
  // Patches with fewer than 4 x min_samples grid points get a grid of half
  // the spacing, down to min_spacing_m. At 0.25 m a face needs 2 m² in plan
  // to reach min_samples at all; on `realistic` seed 1, 17 true faces
  // (dormers, hip ends) were rejected only for that, from true edges.
  double min_spacing_m = 0.125;
  // Also refine the grid, down to min_spacing_m, while fewer than
  // min_samples of its points are textured: a patch textured in part only
  // (a steep face in shade, a lit rim), whose grid points are many. Off by
  // default; `run` turns it on for the sweep's own planes, not for the
  // completions' proposals (strips along footprints, faces beyond ridges),
  // which then passed on thin texture and took a footprint's roof model's
  // place.
  bool refine_for_texture = false;
  // Correlation window (2 r + 1)^2 in the reference view, mapped pixel by
  // pixel through the plane into the other views (exact plane-induced
  // mapping, as in the sweep).
  int ncc_radius = 3;
  // Windows flatter than this grey standard deviation ([0, 1] scale) carry
  // no evidence and are skipped.
  double min_texture = 0.01;
  // A patch with fewer textured samples cannot be verified and is
  // rejected (its score is reported as NaN): the sweep's evidence lies
  // along the line, a roof face needs its own.
  int min_samples = 32;
  // Accept when the mean Cor+ over the samples reaches min_score and
  // exceeds by min_margin the score of the same plane moved up and down:
  // the images must clearly prefer this height. Rough surfaces (tree
  // crowns, hedges) correlate about equally well over a range of heights;
  // roofs do not. The same holds for the plane tilted about the patch
  // centre (about x and about y, both ways) so that the patch edge moves by
  // the offset: a wrong slope is caught too. The offset is the height change that moves the patch
  // centre by offset_parallax_px relative to the reference in the widest
  // baseline view (more than the window's half-width, so that the windows
  // decorrelate), bounded by [min_offset_m, max_offset_m]: about 0.8 m at
  // 5 cm GSD with base-to-height 0.3, more for small baselines.
  double min_score = 0.3;
  double offset_parallax_px = 5.0;
  double min_offset_m = 0.25;
  double max_offset_m = 5.0;
  double min_margin = 0.1;
  // Off for a plane whose height is known otherwise: a face mirrored about
  // a ridge shares the ridge with a face that passed the test
  // (MirrorCompletionOptions::height_from_ridge). It is then skipped; the
  // score, slope, off-line and ground tests still apply, and the plane
  // counts as height-confirmed.
  bool height_test = true;
  // The tilted alternatives agree with the plane near the patch centre, so
  // the plane need only not lose to them (a margin of 0.1 here rejected a
  // third of the true planes on `realistic`): it is refused when the best
  // tilted plane scores better on the same samples by more than
  // min_tilt_margin + tilt_z standard errors of the mean difference. With
  // tilt_z 1 instead of comparing the two means (over each plane's own
  // samples) plane quality rose on 14 of 24 eval cells (matched lines, with
  // footprints, true edges; `realistic` s1-s3, s7, s11, `easy`, `hard`,
  // Berlin) and fell on 4, by up to 2.4 points (s7 from true edges).
  double min_tilt_margin = 0.0;
  double tilt_z = 1.0;
  // Two more tilted alternatives for a plane hinged on one line (all its
  // lines' endpoints within hinge_max_offset_m of the longest one's line in
  // plan): the plane turned both ways about that line, so that the patch's
  // farthest point from it moves by the offset. The sweep chose such a
  // plane's slope about the line, and the textured samples along the line
  // confirm any slope about it; the alternatives turned about the patch
  // centre move the line off its edge and lose there, so a one-line plane
  // at a wrong slope (a neighbour's verge carrying a false face over a flat
  // roof, an eave carrying one over a lawn) passed them. On 30 paired runs
  // (`realistic` s1-s3, s7, s11, s13, s17, `easy`, `hard`, Berlin; matched
  // seeds 1-3) plane quality +0.42 +- 0.13 from matched lines (14 up, 0
  // down) and +0.50 +- 0.25 with footprints (8 / 4); correctness +0.72 and
  // +0.42. Turning every plane about its longest line instead, also where
  // other lines span the face: +0.10 +- 0.22 and +0.28 +- 0.32.
  bool hinge_tilt = true;
  double hinge_max_offset_m = 1.0;
  // Where the images cannot tell a plane's height, the height test refuses
  // true faces: when the offset moves the texture across itself by less
  // than the window's half-width (ncc_radius) in every view, e.g. tile
  // courses parallel to every baseline on a face at the block's edge seen
  // by one strip, the moved planes correlate as well as the true one (0.95
  // against 0.98 on such a face of `realistic` s1). There a plane that fails
  // only the height test is accepted on its lines when one of them, at least
  // crossing_line_min_length_m long, crosses the baseline of largest
  // parallax at crossing_line_min_angle_deg or more: matching measures the
  // height of such a line, not of lines along the baselines. It then yields
  // in conflicts to every plane whose height the images confirmed
  // (RoofPlaneHypothesis::height_from_lines), or its larger area would
  // carry a weakly supported plane over confirmed faces. On the 24 eval
  // cells plane quality rose on 14 and fell on 3 (by at most 1.2 points,
  // Berlin from matched lines); skipping the height test on low parallax
  // alone, without the crossing line and the yielding, fell on 7 (s2 from
  // matched lines 62.9 -> 54.5).
  bool height_from_crossing_lines = true;
  double crossing_line_min_length_m = 2.0;
  double crossing_line_min_angle_deg = 30.0;
  // A weakly textured face, a garden shed's flat roof of 2-3 m say, does
  // not score much better at its height than 0.75 m above or below (0.68
  // against 0.63 on one of `realistic` s1), whatever the parallax, and its
  // lines are too short for the assembly's 3 m. Its lines can still draw
  // it: such a plane that fails only the height test is accepted on its
  // lines too when at least outline_min_corners pairs of them meet at a
  // right angle and together they are at least outline_min_fraction of
  // the patch's perimeter long (three sides of its outline), one of them
  // crosses the baselines as above, and neither moved plane scores better
  // on the same samples. It yields in conflicts as one accepted on
  // crossing lines. Only for small buildings, sheds and garages, no line
  // longer than outline_max_line_m: a large face has texture enough to
  // tell its height, and where it does not, three lines with square
  // corners are no evidence. Three wall tops of 11-19 m around a Berlin
  // courtyard (71 % of its perimeter) carried a 217 m2 plane at 45 deg
  // across it (score 0.47, 0.43 moved up) on every matching seed.
  bool height_from_outline = true;
  int outline_min_corners = 2;
  double outline_min_fraction = 0.6;
  double outline_max_line_m = 8.0;
  RightCornerOptions outline_corners{1.0, 10.0, 0.5};
  // A flat plane (at most flat_max_slope_deg) of at least flat_from_lines
  // lines (0: off), one crossing the baselines, is accepted on its lines
  // when neither moved plane scores significantly better on the same
  // samples (by flat_tie_z standard errors): a flat roof's uniform cover
  // with its roof-top boxes scores alike at any height (0.73 against 0.75
  // 0.6 m higher for a 75 m2 roof of nine lines on `realistic` s2), and
  // level lines at one height on its sides fix it. It yields in conflicts
  // as one accepted on crossing lines. Over 30 paired runs plane quality
  // +0.08 +- 0.04 from matched lines and +0.10 +- 0.06 with footprints
  // (3 up, none down each; a flat roof of `realistic` s7 on every seed),
  // building quality +0.15 / +0.16 (sweep README, session 64).
  int flat_from_lines = 3;
  double flat_max_slope_deg = 3.0;
  double flat_tie_z = 2.0;
  // Delineation by the verification (§5): an accepted plane's patch is cut
  // back to where its samples do not refute it. A patch reaches past its
  // face where a stray point of the sweep's support or a line of a
  // neighbouring face widened its hull; there the plane runs through the
  // ground or another face and its samples do not correlate. A sample with
  // Cor+ below trim_max_score refutes the plane, one above supports it;
  // each sample keeps its cell when its neighbours within
  // trim_vote_radius_m (itself included; untextured ones abstain) do not
  // refute more than they support. The kept cells and the plane's lines
  // span the new patch, within the old one. From matched lines plane
  // quality rose on `realistic` s1 (63.6 -> 64.3), s7 (50.7 -> 52.1) and
  // Berlin (48.8 -> 50.0) and stayed on s2, s3, s11 and `easy`; the vertex
  // RMS fell on four of these seven and rose on three (`easy` 6.3 -> 7.4
  // GSD). A radius of 0.5 m left stray kept cells 2 m past an eave in the
  // unit test, whose hull kept the whole overshoot.
  bool trim_patch = true;
  double trim_max_score = 0.3;
  double trim_vote_radius_m = 0.75;
  // Only the kept cells connected (8-neighbours) to the cells nearest each
  // of the plane's lines span the trimmed patch: kept cells cut off from
  // the lines by refuted ones are texture that correlated by chance at the
  // wrong height, or a shed's roof on the face's extension past a lawn,
  // and one such island held the hull open over the whole overshoot. On 30
  // paired runs (`realistic` s1-s3, s7, s11, s13, s17, `easy`, `hard`,
  // Berlin; matched seeds 1-3) plane quality +0.13 +- 0.12 from matched
  // lines and +0.24 +- 0.11 with footprints, vertex RMS -0.13 +- 0.08 and
  // -0.42 +- 0.12 GSD.
  bool trim_connected = true;
  // Refusal on the samples away from the plane's own lines. A window that
  // straddles one of the plane's supporting lines correlates at the plane's
  // height whatever lies between the lines: two parallel lines at different
  // heights (a shed's eave and a house's eave across a shaded garden) span
  // a plane whose textured samples on the two lines carry its score and its
  // height test. When at least min_samples textured samples lie farther
  // than off_line_band_px (in the view nearest in plan: the window's
  // half-width and a pixel and a half) from every line, a plane that passed
  // is refused if they score below min_score and at least
  // off_line_min_drop below the plane's score over all its samples (its
  // lines carried it). Weakly textured true faces score low away from
  // their lines too, but not far below their score on them: without the
  // drop condition `hard` lost 4.5 points of plane quality on two of three
  // seeds. Planes accepted on their lines (height_from_crossing_lines) are
  // not tested.
  bool verify_off_lines = true;
  double off_line_band_px = 4.5;
  double off_line_min_drop = 0.15;
  // The ground as one more alternative height. A plane lying more than
  // ground_min_offsets offsets above the block's ground at its patch
  // centre is refused when the ground explains the same image evidence
  // better: the samples inside its trimmed patch,
  // carried along the reference view's rays down to the ground, score
  // there more than the plane's score on them minus ground_margin.
  // Ground texture with a period (mowing stripes, parking bays, dashed
  // markings) also correlates where the parallax shifts it by a whole
  // period; the plane moved up and down by the offset falls out of phase,
  // so the height test alone passes it. A roof's texture carried down to
  // the ground moves by the roof's parallax and decorrelates. On
  // `realistic` blocks at 10 cm GSD (2048 px, seeds 1-3) it removed 14-26
  // false faces away from every building, flat planes 5-35 m over lawns;
  // plane quality +4.2 to +6.7. A margin of 0.1, as the height test's,
  // also refused tile-course roofs whose courses the ground shift
  // realigned (0.76 against 0.66-0.69 on `easy`). Skipped without a known
  // ground.
  bool ground_alternative = true;
  double ground_margin = 0.0;
  // One offset down is the height test's own lower alternative; past it the
  // ground is a distinct one. Where parallax is small the offset is large:
  // lawns that only oblique views see have offsets of 1.7-2.5 m, and with
  // the ground tried only beyond two of them, 28 false flat faces over
  // mowing stripes piled up at 4.8-7.1 m on a `realistic -obliques` block.
  double ground_min_offsets = 1.0;
  // Planes accepted on their lines (height_from_crossing_lines,
  // height_from_outline, flat_from_lines) are tried too: the images could
  // not tell their height within one offset, but the ground lies further
  // down than that. Over those lawns they scored 0.31-0.37 against
  // 0.77-0.83 on the ground; true roofs so accepted scored 0.20-0.45 there,
  // below their own score.
  bool ground_on_lines = true;
  // BestModelHeights: a height counts only where at least this share of
  // the model's samples lies in two views or more, relative to the best
  // share over the window. High up, a footprint leaves all views but two
  // and mostly leaves those too; its score is then the agreement of two
  // views on the corner of it still inside them. On `hard` seed 1 a gabled
  // house 18.6 m high got a flat roof 56.8 m up (score 0.48 on 12 % of its
  // samples, against 0.2-0.25 around its true height seen whole).
  double model_min_seen_share = 0.5;
};

struct PlaneVerification {
  double score = 0;  // mean Cor+ at the plane; NaN when unverifiable
  double score_below = 0, score_above = 0;
  double score_tilted = 0;  // best of the four tilted alternatives
  double score_ground = std::numeric_limits<double>::quiet_NaN();  // NaN: not tested
  // Cor+ of the plane minus that of the best tilted one over the samples
  // both scored, and its standard error.
  double tilt_difference = 0, tilt_se = 0;
  // The same against the plane moved down and up by the offset.
  double below_difference = 0, below_se = 0, above_difference = 0, above_se = 0;
  double offset_m = 0;  // height offset of the alternatives (at the patch edge when tilted)
  int samples = 0;      // textured samples used
  bool accepted = false;
  // False when accepted on its lines where the images could not tell its
  // height (VerifyOptions::height_from_crossing_lines).
  bool height_confirmed = true;
  // The accepted patch cut back to where the images do not refute it
  // (VerifyOptions::trim_patch); empty when nothing was cut.
  std::vector<Eigen::Vector2d> patch;
  std::string reason;  // why not accepted
  // The test that refused it, for callers that weigh refusals differently
  // (JudgeModelsWhole): kNone when accepted.
  enum class Test { kNone, kPatch, kSamples, kScore, kHeight, kSlope, kOffLines, kGround };
  Test failed = Test::kNone;
};

// Scores every patch over all views that see it. `images` as SweepHalfPlanes
// takes them. Parallel over planes (TBB), deterministic. Cancels through
// `progress`.
std::vector<PlaneVerification> VerifyPlanes(const Block& block, const std::vector<cv::Mat>& images,
                                            const std::vector<RoofPlaneHypothesis>& planes,
                                            const VerifyOptions& options, Progress& progress);

// A search for the height of a roof model (RoofModelsOver): every face's
// plane moved up by the same h, between h_lo and h_hi.
struct ModelHeightSearch {
  std::vector<Ring2> patches;           // convex, counter-clockwise
  std::vector<Eigen::Vector4d> planes;  // at h = 0, one per patch
  double h_lo = 0, h_hi = 0;
};

struct ModelHeight {
  double h = std::numeric_limits<double>::quiet_NaN();      // NaN: none could be scored
  double score = std::numeric_limits<double>::quiet_NaN();  // mean Cor+ over all faces' samples
};

// Per search, the h at which the views agree best on the model: the mean
// Cor+ over the samples of all its faces (each on its own plane), tried in
// steps of about two pixels of parallax (at most max_steps of them), then
// refined to about half a pixel around the best; only heights at which the
// model is seen over most of it (VerifyOptions::model_min_seen_share) are
// candidates. A flat roof is one face on
// the plane z = 0. The result is a hypothesis only: VerifyPlanes decides on
// it. The scores of several models over
// one footprint compare: their samples lie on one plan grid. Parallel over
// the searches, deterministic.
std::vector<ModelHeight> BestModelHeights(const Block& block, const std::vector<cv::Mat>& images,
                                          const std::vector<ModelHeightSearch>& searches,
                                          const VerifyOptions& options, int max_steps = 400);

}  // namespace roofsweep
