#pragma once

#include <optional>

#include "algorithms/buildings/city_model.h"
#include "algorithms/eval/evaluate.h"

namespace roofsweep {

// LoD1 blocks (Building::lod 1: a footprint extruded to one height, where
// the roof was not reconstructed) are not LoD2 models: a flat block over a
// gable would count as a wrong roof plane, and a building found only as a
// block is not found at LoD2. The evaluation therefore scores them apart.
struct Lod1Scores {
  int blocks = 0;          // LoD1 buildings in the result
  int over_reference = 0;  // of those, over a reference building (the building rule)
  int n_reference = 0;
  // Reference buildings that only an LoD1 block finds; found by an LoD2
  // building or a block.
  int found_by_block_only = 0, found = 0;
  std::optional<double> found_fraction;  // found / n_reference
  // Block tops against the reference roofs, over the grid cells both cover
  // (EvalOptions::rmsz_grid_m): RMS and mean of block - reference.
  long long cells = 0;
  std::optional<double> rmsz_m, dz_mean_m;
  // The same RMS for blocks whose tops lie at the mean height of the
  // reference roof under each: the least any flat block can reach, so
  // what rmsz_m exceeds it by is the error of the heights chosen.
  std::optional<double> rmsz_at_mean_m;
};

// Moves the LoD1 buildings out of `model` (parts merged first) and returns
// them as a model of their own, same CRS.
CityModel TakeLod1Buildings(CityModel* model);

// Scores `blocks` (LoD1 buildings) against `truth`; `lod2` is the
// evaluation of the rest of the result against the same truth, for the
// buildings it found. Throws roofsweep::Error as Evaluate does.
Lod1Scores EvaluateLod1(const CityModel& blocks, const CityModel& truth, const EvalResult& lod2,
                        const EvalOptions& options);

}  // namespace roofsweep
