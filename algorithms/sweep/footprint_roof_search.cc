#include "algorithms/sweep/footprint_roof_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/buildings/footprint_completion.h"
#include "algorithms/buildings/polygon2.h"
#include "algorithms/core/error.h"
#include "algorithms/geometry/slope.h"
#include "algorithms/sweep/plane_fit.h"

namespace roofsweep {
namespace {

ModelHeightSearch SearchOf(const RoofModel& m, double lo, double hi) {
  ModelHeightSearch h;
  for (const RoofModelFace& face : m.faces) {
    h.patches.push_back(face.patch);
    h.planes.push_back(face.plane);
  }
  h.h_lo = lo, h.h_hi = hi;
  return h;
}

// A shed at the slope of the one face found beyond whose ridge it lies
// (NaN: a bare footprint, none is).
bool IsAtFaceSlope(const RoofModel& m, double face_slope_deg) {
  return m.faces.size() == 1 &&
         std::abs(SlopeDeg(m.faces[0].plane.head<3>()) - face_slope_deg) < 0.5;
}

}  // namespace

std::pair<double, double> LineHeightSpan(const Ring2& outline, const std::vector<Segment3>& lines,
                                         double margin_m, double z_min) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::pair<double, double> span{nan, nan};
  if (outline.size() < 3) return span;
  auto over = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector2d q = x.head<2>();
    return InsideRing(outline, q) || DistanceToRing(outline, q) <= margin_m;
  };
  for (const Segment3& l : lines) {
    if (!(l.a.z() > z_min && l.b.z() > z_min) || !over(l.a) || !over(l.b)) continue;
    const double lo = std::min(l.a.z(), l.b.z()), hi = std::max(l.a.z(), l.b.z());
    if (!(span.first <= lo)) span.first = lo;
    if (!(span.second >= hi)) span.second = hi;
  }
  return span;
}

std::vector<std::pair<double, double>> SlopedModelWindows(double flat_h, double rise, double h_min,
                                                          double h_max,
                                                          std::pair<double, double> line_span) {
  std::vector<std::pair<double, double>> windows;
  const std::pair<double, double> below_flat{std::max(h_min, flat_h - rise - 1.0), flat_h + 0.5};
  if (below_flat.second > below_flat.first) windows.push_back(below_flat);
  const auto [lo, hi] = line_span;
  // Where the lines agree with the flat roof's height, more windows only
  // give the noise more chances to win.
  if (!std::isfinite(lo) || !(flat_h > hi + 1.0 || flat_h < lo - 1.0)) return windows;
  // The lines lie between the eaves and the top of the roof.
  const std::pair<double, double> by_lines{std::max(h_min, lo - rise - 0.5),
                                           std::min(h_max, hi + 0.5)};
  if (!(by_lines.second > by_lines.first)) return windows;
  if (!windows.empty() && by_lines.first <= windows[0].second &&
      windows[0].first <= by_lines.second)
    windows[0] = {std::min(windows[0].first, by_lines.first),
                  std::max(windows[0].second, by_lines.second)};
  else
    windows.push_back(by_lines);
  return windows;
}

int ChooseRoofModel(double flat_score, const std::vector<ScoredRoofModel>& sloped, double min_gain,
                    double prefer_face_slope) {
  int best = -1, mirror = -1;
  for (size_t j = 0; j < sloped.size(); ++j) {
    const double s = sloped[j].score;
    if (!std::isfinite(s) || !(s >= flat_score + min_gain)) continue;
    if (best < 0 || s > sloped[best].score) best = static_cast<int>(j);
    if (sloped[j].at_face_slope && (mirror < 0 || s > sloped[mirror].score))
      mirror = static_cast<int>(j);
  }
  if (mirror >= 0 && prefer_face_slope > 0 &&
      sloped[mirror].score >= sloped[best].score - prefer_face_slope)
    return mirror;
  return best;
}

std::vector<RoofPlaneHypothesis> RoofsOverBareFootprints(
    const Block& block, const std::vector<cv::Mat>& images,
    const std::vector<RoofPlaneHypothesis>& planes, const std::vector<Footprint>& footprints,
    const std::vector<Segment3>& lines, const BareFootprintRoofOptions& o,
    const VerifyOptions& verify, int* tried, int* beyond, std::vector<int>* model_of) {
  // The bare footprints, then the parts beyond a ridge, each with the models
  // to try there.
  std::vector<Footprint> outlines;
  std::vector<RoofModelOptions> model_options;
  // The slope of the one face found over a part beyond a ridge; NaN for a
  // bare footprint.
  std::vector<double> face_slope;
  std::vector<char> bare(footprints.size(), 0);
  for (int f : BareFootprints(planes, footprints)) {
    outlines.push_back(footprints[f]);
    model_options.push_back(o.model);
    face_slope.push_back(std::numeric_limits<double>::quiet_NaN());
    bare[f] = 1;
  }
  const size_t n_bare = outlines.size();
  if (o.models && o.beyond_ridges)
    for (FootprintBeyondRidge& r : FootprintsBeyondRidges(planes, footprints, o.beyond)) {
      if (bare[r.footprint]) continue;
      outlines.push_back(std::move(r.part));
      model_options.push_back(o.model);
      // The other face of a gable falls at the found face's slope; a hipped
      // roof over half a gable is no roof.
      model_options.back().shed_slopes_deg.push_back(r.face_slope_deg);
      model_options.back().hip_slopes_deg.clear();
      face_slope.push_back(r.face_slope_deg);
    }
  std::vector<ModelHeightSearch> searches;
  std::vector<std::pair<int, std::vector<RoofModel>>> which;
  std::vector<double> ground_z;
  int n_beyond = 0;
  for (size_t f = 0; f < outlines.size(); ++f) {
    std::vector<RoofModel> models = RoofModelsOver(outlines[f], model_options[f]);
    if (models.empty()) continue;
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (const auto& q : models[0].faces[0].patch) c += q;
    c /= static_cast<double>(models[0].faces[0].patch.size());
    const double g = block.ground.HeightAt(c.x(), c.y());
    if (!std::isfinite(g)) continue;
    if (!o.models) models.resize(1);
    searches.push_back(SearchOf(models[0], g + o.min_height_m, g + block.max_building_height));
    which.emplace_back(static_cast<int>(f), std::move(models));
    ground_z.push_back(g);
    n_beyond += f >= n_bare;
  }
  if (tried) *tried = static_cast<int>(which.size()) - n_beyond;
  if (beyond) *beyond = n_beyond;
  const std::vector<ModelHeight> z_flat = BestModelHeights(block, images, searches, verify);
  std::vector<ModelHeightSearch> sloped;
  std::vector<std::pair<size_t, size_t>> sloped_of;  // (footprint entry, model)
  for (size_t k = 0; k < which.size(); ++k) {
    if (!std::isfinite(z_flat[k].h)) continue;
    const double h_min = ground_z[k] + o.min_height_m;
    const double h_max = ground_z[k] + block.max_building_height;
    std::pair<double, double> span{std::numeric_limits<double>::quiet_NaN(), 0.0};
    if (o.line_heights)
      span = LineHeightSpan(outlines[which[k].first].outline, lines, o.line_margin_m, h_min);
    for (size_t m = 1; m < which[k].second.size(); ++m) {
      double rise = 0;
      for (const RoofModelFace& face : which[k].second[m].faces)
        for (const auto& q : face.patch) rise = std::max(rise, PlaneZ(face.plane, q.x(), q.y()));
      const std::vector<std::pair<double, double>> windows =
          SlopedModelWindows(z_flat[k].h, rise, h_min, h_max, span);
      for (const auto& w : windows) {
        sloped.push_back(SearchOf(which[k].second[m], w.first, w.second));
        sloped_of.emplace_back(k, m);
      }
    }
  }
  const std::vector<ModelHeight> z_sloped = BestModelHeights(block, images, sloped, verify);
  // Per footprint entry: the model chosen and its height.
  std::vector<std::vector<size_t>> searches_of(which.size());
  for (size_t j = 0; j < sloped.size(); ++j) searches_of[sloped_of[j].first].push_back(j);
  std::vector<std::pair<size_t, ModelHeight>> best(which.size(), {0, ModelHeight{}});
  for (size_t k = 0; k < which.size(); ++k) {
    best[k].second = z_flat[k];
    std::vector<ScoredRoofModel> scored;
    for (size_t j : searches_of[k])
      scored.push_back({z_sloped[j].score, IsAtFaceSlope(which[k].second[sloped_of[j].second],
                                                         face_slope[which[k].first])});
    const int c = ChooseRoofModel(z_flat[k].score, scored, o.min_gain, o.prefer_face_slope);
    if (c >= 0) {
      const size_t j = searches_of[k][c];
      best[k] = {sloped_of[j].second, z_sloped[j]};
    }
  }
  std::vector<RoofPlaneHypothesis> roofs;
  if (model_of) model_of->clear();
  for (size_t k = 0; k < which.size(); ++k) {
    if (!std::isfinite(best[k].second.h)) continue;
    const RoofModel& m = which[k].second[best[k].first];
    for (size_t face = 0; face < m.faces.size(); ++face) {
      roofs.push_back(RoofModelFaceAt(outlines[which[k].first], m, face, best[k].second.h));
      if (model_of) model_of->push_back(static_cast<int>(k));
    }
  }
  return roofs;
}

int JudgeModelsWhole(const std::vector<int>& model_of, const VerifyOptions& o,
                     std::vector<PlaneVerification>* checks, double min_z) {
  using Test = PlaneVerification::Test;
  std::vector<PlaneVerification>& v = *checks;
  if (model_of.size() != v.size())
    throw Error("JudgeModelsWhole: one model index per verification needed");
  std::map<int, std::vector<size_t>> faces;
  for (size_t i = 0; i < model_of.size(); ++i) faces[model_of[i]].push_back(i);
  int accepted = 0;
  for (const auto& [model, of] : faces) {
    bool any_accepted = false, all_judged = true;
    std::vector<size_t> refused;
    for (const size_t i : of) {
      if (v[i].accepted) {
        any_accepted = true;
        continue;
      }
      const bool weighable = v[i].failed == Test::kScore || v[i].failed == Test::kHeight ||
                             v[i].failed == Test::kSlope;
      // Not preferred at its height on its own samples, by a standard error
      // at least: a wrong model's face (a gable over a shed) then stands on
      // its sibling's evidence.
      if (!weighable || !std::isfinite(v[i].score) ||
          !(v[i].below_difference > min_z * v[i].below_se) ||
          !(v[i].above_difference > min_z * v[i].above_se))
        all_judged = false;
      refused.push_back(i);
    }
    if (!any_accepted || refused.empty() || !all_judged) continue;
    double n = 0, score = 0, below = 0, above = 0, tilt = 0, tilt_var = 0;
    for (const size_t i : of) {
      const double w = v[i].samples;
      n += w, score += w * v[i].score, below += w * v[i].score_below;
      above += w * v[i].score_above, tilt += w * v[i].tilt_difference;
      tilt_var += w * w * v[i].tilt_se * v[i].tilt_se;
    }
    if (!(n > 0)) continue;
    score /= n, below /= n, above /= n, tilt /= n;
    const double tilt_se = std::sqrt(tilt_var) / n;
    if (score < o.min_score || (o.height_test && score < std::max(below, above) + o.min_margin) ||
        tilt < o.min_tilt_margin - o.tilt_z * tilt_se)
      continue;
    for (const size_t i : refused) {
      v[i].accepted = true;
      v[i].height_confirmed = true;
      v[i].reason.clear();
      v[i].failed = Test::kNone;
      ++accepted;
    }
  }
  return accepted;
}

}  // namespace roofsweep
