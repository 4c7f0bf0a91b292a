#include "algorithms/sweep/footprint_roof_search.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "algorithms/buildings/footprint_completion.h"
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

}  // namespace

std::vector<RoofPlaneHypothesis> RoofsOverBareFootprints(
    const Block& block, const std::vector<cv::Mat>& images,
    const std::vector<RoofPlaneHypothesis>& planes, const std::vector<Footprint>& footprints,
    const BareFootprintRoofOptions& o, const VerifyOptions& verify, int* tried, int* beyond) {
  // The bare footprints, then the parts beyond a ridge, each with the models
  // to try there.
  std::vector<Footprint> outlines;
  std::vector<RoofModelOptions> model_options;
  std::vector<char> bare(footprints.size(), 0);
  for (int f : BareFootprints(planes, footprints)) {
    outlines.push_back(footprints[f]);
    model_options.push_back(o.model);
    bare[f] = 1;
  }
  const size_t n_bare = outlines.size();
  if (o.models && o.beyond_ridges)
    for (FootprintBeyondRidge& r : FootprintsBeyondRidges(planes, footprints, o.beyond)) {
      if (bare[r.footprint]) continue;
      outlines.push_back(std::move(r.part));
      model_options.push_back(o.model);
      // The other face of a gable falls at the found face's slope.
      model_options.back().shed_slopes_deg.push_back(r.face_slope_deg);
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
    for (size_t m = 1; m < which[k].second.size(); ++m) {
      double rise = 0;
      for (const RoofModelFace& face : which[k].second[m].faces)
        for (const auto& q : face.patch) rise = std::max(rise, PlaneZ(face.plane, q.x(), q.y()));
      const double lo = std::max(ground_z[k] + o.min_height_m, z_flat[k].h - rise - 1.0);
      if (!(z_flat[k].h + 0.5 > lo)) continue;
      sloped.push_back(SearchOf(which[k].second[m], lo, z_flat[k].h + 0.5));
      sloped_of.emplace_back(k, m);
    }
  }
  const std::vector<ModelHeight> z_sloped = BestModelHeights(block, images, sloped, verify);
  // Per footprint entry: the model chosen and its height.
  std::vector<std::pair<size_t, ModelHeight>> best(which.size(), {0, ModelHeight{}});
  for (size_t k = 0; k < which.size(); ++k) best[k].second = z_flat[k];
  for (size_t j = 0; j < sloped.size(); ++j) {
    const size_t k = sloped_of[j].first;
    auto& [model, height] = best[k];
    if (std::isfinite(z_sloped[j].score) && z_sloped[j].score >= z_flat[k].score + o.min_gain &&
        !(z_sloped[j].score <= height.score))
      model = sloped_of[j].second, height = z_sloped[j];
  }
  std::vector<RoofPlaneHypothesis> roofs;
  for (size_t k = 0; k < which.size(); ++k) {
    if (!std::isfinite(best[k].second.h)) continue;
    const RoofModel& m = which[k].second[best[k].first];
    for (size_t face = 0; face < m.faces.size(); ++face)
      roofs.push_back(RoofModelFaceAt(outlines[which[k].first], m, face, best[k].second.h));
  }
  return roofs;
}

}  // namespace roofsweep
