#pragma once

#include <limits>
#include <opencv2/core.hpp>
#include <utility>
#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/buildings/footprint.h"
#include "algorithms/buildings/footprint_completion.h"
#include "algorithms/buildings/footprint_roofs.h"
#include "algorithms/geometry/block.h"
#include "algorithms/geometry/segment3.h"
#include "algorithms/sweep/verify_planes.h"

namespace roofsweep {

// Options of RoofsOverBareFootprints.
struct BareFootprintRoofOptions {
  // false: the flat roof only (the behaviour before the roof models).
  bool models = true;
  RoofModelOptions model;
  // A sloped model replaces the flat roof only where it fits the images
  // better by this (mean Cor+): a model with more parameters fits noise
  // better.
  double min_gain = 0.05;
  // The eaves lie this high above the ground at least (m).
  double min_height_m = 1.5;
  // Also the part of a footprint beyond the top of the one sloped face
  // found over it (FootprintsBeyondRidges: the other side of a gable whose
  // one face was found), with the models above and a shed falling away from
  // the ridge at the face's own slope; only with `models`. With footprints a
  // gable came out as a shed roof 46 times over the 30 eval runs
  // (`realistic`, `easy`, `hard` and Berlin blocks, matching seeds 1-3); with
  // these, over those 30 paired runs, building quality rose by 1.72 +- 0.35
  // (17 runs up, 0 down), plane completeness by 0.63 +- 0.15 (13 / 0), plane
  // quality by 0.38 +- 0.14 (10 / 3), correctness -0.21 +- 0.14.
  bool beyond_ridges = true;
  BeyondRidgeOptions beyond;
  // Beyond a ridge, a shed at the found face's slope (its mirror image: most
  // pitched roofs are symmetric) is taken over a better scoring sloped model
  // unless that one scores more than this higher (mean Cor+; 0: the best
  // scoring one). Where tile courses run along the baselines the images tell
  // slopes apart poorly: on `easy-1` a 30° shed beat the mirror of a gable's
  // 40.3° face by a hair on every matching seed.
  double prefer_face_slope = 0.05;
  // The sloped models are also searched at the heights of the 3D lines over
  // the footprint (LineHeightSpan) where those contradict the flat roof's
  // best height (SlopedModelWindows): over a steep roof no flat plane fits,
  // and its best height can lie tens of metres off.
  bool line_heights = true;
  // A line counts for a footprint when both its ends lie inside it or within
  // this of its outline (m): eaves lie on the outline.
  double line_margin_m = 0.5;
};

// The lowest and highest z of the 3D lines over `outline` (both ends inside
// it or within `margin_m` of it) whose ends both lie above `z_min`; NaN, NaN
// when none.
std::pair<double, double> LineHeightSpan(const Ring2& outline, const std::vector<Segment3>& lines,
                                         double margin_m, double z_min);

// The height windows [lo, hi] in which a sloped model's eaves are searched,
// for a model rising `rise` m to its top, between h_min and h_max. Below the
// flat roof's best height `flat_h` (down by the rise and 1 m, up 0.5 m);
// and where the lines' span of heights (LineHeightSpan; NaN: none) lies more
// than 1 m above or below flat_h, also where the lines lie between the
// eaves and the top (padded by 0.5 m), merged with the first where the two
// overlap.
std::vector<std::pair<double, double>> SlopedModelWindows(double flat_h, double rise, double h_min,
                                                          double h_max,
                                                          std::pair<double, double> line_span);

// One sloped roof model over a footprint as the height search scored it.
struct ScoredRoofModel {
  double score = std::numeric_limits<double>::quiet_NaN();  // mean Cor+; NaN: none
  // A shed at the slope of the one face found, over the part of a
  // footprint beyond that face's ridge.
  bool at_face_slope = false;
};

// The model taken over one footprint: the index of the sloped model that
// scores best, among those that beat the flat roof's score by min_gain, or
// -1 for the flat roof. Beyond a ridge the best one at the face's slope
// instead, when it scores within prefer_face_slope of that (0: never).
int ChooseRoofModel(double flat_score, const std::vector<ScoredRoofModel>& sloped, double min_gain,
                    double prefer_face_slope);

// Roof hypotheses over the footprints that no plane covers
// (BareFootprints), and over the parts of footprints beyond the one face
// found over them (beyond_ridges): every roof model over each (RoofModelsOver) at the
// height the views agree on best (BestModelHeights). The flat roof's height
// is searched from min_height_m to the block's maximum building height; a
// sloped model's eaves lie below it by at most the model's rise, which
// bounds their search (a tenth of the cost); with line_heights, also at
// the heights of the 3D lines over the footprint (`lines`, local frame)
// where those contradict it (SlopedModelWindows). The best model per
// footprint gives its faces, derived, for the caller to verify each like any plane. `tried`: how
// many bare footprints had a ground height; `beyond`: how many parts beyond a ridge; `model_of`:
// per face, the index of its model (faces of one model share it; JudgeModelsWhole). Deterministic.
std::vector<RoofPlaneHypothesis> RoofsOverBareFootprints(
    const Block& block, const std::vector<cv::Mat>& images,
    const std::vector<RoofPlaneHypothesis>& planes, const std::vector<Footprint>& footprints,
    const std::vector<Segment3>& lines, const BareFootprintRoofOptions& options,
    const VerifyOptions& verify, int* tried, int* beyond = nullptr,
    std::vector<int>* model_of = nullptr);

// A roof model stands or falls as a whole: its slope and height were chosen
// over all its faces together (BestModelHeights), and one face kept without
// the other makes a gable a shed over half its footprint. Over the 30 eval
// runs with footprints 49 reference gables came out so, the other face
// refused by the per-face tests on thin evidence (score 0.29 < 0.30; 0.36
// against 0.32 when 0.7 m higher on tile courses). Where some face of a
// model (`model_of`, as RoofsOverBareFootprints gives it) was accepted and
// the others were refused only by the score, height or slope test, those
// are accepted too when the model's faces pooled (means weighted by their
// samples) pass the same three tests of `verify`, and each of them scores
// better at its height than moved up and down on its own samples, by min_z
// standard errors of the paired difference. Without that a gable model over
// a shed of `realistic-19` stood whole, its second face 0.02 (0.6 standard
// errors) better than moved down; the readmitted faces of true gables on
// `hard-1` s1 lay 1.5-10 standard errors clear. Returns how many faces were
// so accepted; `checks` are updated in place.
int JudgeModelsWhole(const std::vector<int>& model_of, const VerifyOptions& verify,
                     std::vector<PlaneVerification>* checks, double min_z = 1.0);

}  // namespace roofsweep
