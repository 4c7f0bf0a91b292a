#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "algorithms/buildings/city_model.h"
#include "algorithms/eval/evaluate.h"

namespace roofsweep {

// A roof plane hypothesis as `roofsweep run -planes` writes it: its patch
// on its plane (in the models' coordinates) and what became of it.
struct PlaneHypothesisRecord {
  std::vector<Eigen::Vector3d> patch;
  std::string status;  // "built", "rejected" or "not built"
  std::string reason;  // for the last two
};

// When a hypothesis stands for a reference roof plane.
struct PlaneLossOptions {
  // Normals within this angle...
  double max_angle_deg = 10.0;
  // ... the reference plane's vertices within this height of the
  // hypothesis's plane (median)...
  double max_height_m = 0.5;
  // ... and the patch covers this share of the reference plane's plan
  // area, or this share of its own (a patch is often a part of the face:
  // the support of the lines that found it).
  double min_reference_overlap = 0.3;
  double min_own_overlap = 0.5;
};

struct PlaneLosses {
  // Per reference plane, in EvalResult::reference_planes order: empty for
  // a true positive, else the stage where it was lost:
  //   "built, but not matched"   a hypothesis for it roofs a building, whose
  //                              face was cut or merged beyond the match;
  //   "not built: <reason kind>" its building hypothesis failed as a whole;
  //   "rejected: <reason kind>"  verification, conflicts or assembly;
  //   "no verified hypothesis"   lines, sweep or grouping never proposed it.
  // Of several hypotheses, the one that went furthest (built, not built,
  // rejected), then the one covering most of the reference plane.
  std::vector<std::string> stage;
  std::map<std::string, int> count;       // missed reference planes per stage
  std::map<std::string, double> area_m2;  // their plan area per stage
};

// Where the reference planes that `eval` did not match were lost, from the
// hypotheses of the run (coordinates as the models given to Evaluate).
PlaneLosses ClassifyMissedPlanes(const CityModel& truth, const EvalResult& eval,
                                 const std::vector<PlaneHypothesisRecord>& hypotheses,
                                 const PlaneLossOptions& options = {});

// A few lines for the eval table, most frequent stage first.
std::string FormatPlaneLosses(const PlaneLosses& losses);

}  // namespace roofsweep
