#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "algorithms/eval/evaluate.h"

namespace roofsweep {

struct EvalRequest {
  std::string result;  // LoD2 model (CityGML, CityJSON, GPKG)
  // Ground truth: a LoD2 model, or a folder written by `roofsweep simulate`
  // (groundtruth.gml, groundtruth_edges.json and the GSD from simulation.json).
  std::string truth;
  std::string lines;  // optional 3D lines: GPKG/OGR line layer or segments JSON
  std::string png;    // optional plan-view overlay to write
  // Optional point layer `vertices` (GPKG or any OGR format) in the models'
  // CRS: every vertex of the matched result planes with its distance to the
  // reference outline and its place (VertexPlace), for a GIS to show where
  // a model's outlines go wrong.
  std::string vertices;
  // Optional roof plane hypotheses of the run (`run -planes`): the missed
  // reference planes are told by where they were lost.
  std::string planes;
  bool overwrite = false;
  EvalOptions options;  // gsd_m = 0: from the simulation folder when there is one
};

struct EvalReport {
  EvalResult result;
  std::string table;
  nlohmann::json json;
};

// `roofsweep eval`: scores a reconstruction against ground truth in the
// manner of the ISPRS benchmark (see algorithms/eval/evaluate.h for the rules).
EvalReport RunEval(const EvalRequest& request);

}  // namespace roofsweep
