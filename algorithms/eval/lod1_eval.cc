#include "algorithms/eval/lod1_eval.h"

#include <cmath>
#include <map>
#include <utility>

#include "algorithms/eval/roof_height_grid.h"

namespace roofsweep {

CityModel TakeLod1Buildings(CityModel* model) {
  MergeBuildingParts(model);
  CityModel blocks;
  blocks.crs = model->crs;
  std::vector<Building> kept;
  for (Building& b : model->buildings)
    (b.lod == 1 ? blocks.buildings : kept).push_back(std::move(b));
  model->buildings = std::move(kept);
  return blocks;
}

Lod1Scores EvaluateLod1(const CityModel& blocks, const CityModel& truth, const EvalResult& lod2,
                        const EvalOptions& options) {
  Lod1Scores s;
  s.blocks = static_cast<int>(blocks.buildings.size());
  s.n_reference = static_cast<int>(truth.buildings.size());
  // The blocks' roofs are one flat plane each, so the plane figures of this
  // evaluation mean nothing; its building matching and height grid are the
  // same rules as for LoD2.
  EvalOptions o = options;
  o.keep_vertices = false;
  const EvalResult r = blocks.buildings.empty() ? EvalResult{} : Evaluate(blocks, truth, o);
  s.over_reference = r.buildings.tp_result;
  for (int j = 0; j < s.n_reference; ++j) {
    const bool by_lod2 = j < static_cast<int>(lod2.reference_building_matched.size()) &&
                         lod2.reference_building_matched[j];
    const bool by_block = j < static_cast<int>(r.reference_building_matched.size()) &&
                          r.reference_building_matched[j];
    s.found += by_lod2 || by_block;
    s.found_by_block_only += by_block && !by_lod2;
  }
  if (s.n_reference > 0) s.found_fraction = static_cast<double>(s.found) / s.n_reference;
  s.cells = r.geometry.rmsz_cells;
  s.rmsz_m = r.geometry.rmsz_m;
  s.dz_mean_m = r.geometry.dz_mean_m;

  // Each block's top raised to its index: the grid then says which block
  // covers a cell (footprints do not overlap), and the reference heights
  // under each block give their spread about their mean.
  const std::optional<eval::GridSpan> span = eval::SpanGrid(blocks, truth, o.rmsz_grid_m);
  if (!span) return s;
  CityModel labels = blocks;
  for (size_t k = 0; k < labels.buildings.size(); ++k) {
    CityModel one;
    one.buildings.push_back(std::move(labels.buildings[k]));
    one.TransformVertices([&](const Eigen::Vector3d& v) -> Eigen::Vector3d {
      return {v.x(), v.y(), static_cast<double>(k)};
    });
    labels.buildings[k] = std::move(one.buildings[0]);
  }
  const auto gl = eval::RasteriseRoofs(labels, span->origin, o.rmsz_grid_m, span->cols, span->rows,
                                       o.planes.vertical_roof_deg);
  const auto gt = eval::RasteriseRoofs(truth, span->origin, o.rmsz_grid_m, span->cols, span->rows,
                                       o.planes.vertical_roof_deg);
  struct Sums {
    long long n = 0;
    double z = 0, z2 = 0;
  };
  std::map<long, Sums> per_block;
  for (size_t i = 0; i < gl.z.size(); ++i) {
    if (!std::isfinite(gl.z[i]) || !std::isfinite(gt.z[i])) continue;
    Sums& b = per_block[std::lround(gl.z[i])];
    ++b.n;
    b.z += gt.z[i];
    b.z2 += static_cast<double>(gt.z[i]) * gt.z[i];
  }
  long long n = 0;
  double ss = 0;
  for (const auto& [k, b] : per_block) {
    n += b.n;
    ss += std::max(0.0, b.z2 - b.z * b.z / static_cast<double>(b.n));
  }
  if (n > 0) s.rmsz_at_mean_m = std::sqrt(ss / static_cast<double>(n));
  return s;
}

}  // namespace roofsweep
