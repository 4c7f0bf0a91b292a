#pragma once

#include <string>

#include "algorithms/buildings/city_model.h"
#include "io/citymodel/segments_json.h"

namespace roofsweep {

// Transforms every vertex of `model` from model.crs to `target_srs` through
// PROJ (io/core/crs_transform.h: the operation valid over the model's
// extent, 2D CRSs taken with ellipsoidal heights, ballpark steps refused)
// and sets model.crs = target_srs. Throws roofsweep::Error when the model
// has no CRS, either CRS is unknown, or a vertex cannot be transformed; the
// model is then unchanged. `-t_srs` of convert and run.
void ReprojectCityModel(CityModel& model, const std::string& target_srs);

// The same for 3D segments (`run -lines` given lines in another CRS than
// the block's): both ends of every segment, then set.crs = target_srs; the
// set is unchanged when it throws.
void ReprojectSegments(SegmentSet& set, const std::string& target_srs);

}  // namespace roofsweep
