#pragma once

#include <string>

#include "algorithms/buildings/city_model.h"

namespace roofsweep::testing {

// Runs `xmllint --noout --nonet --schema CityGML-2.0-all.xsd path`. Returns
// -1 when xmllint or the schema is unavailable (callers skip, or fail under
// ROOFSWEEP_REQUIRE_SHARED=1), else its exit code; `log` gets its output.
int XmllintCityGml(const std::string& path, std::string* log);

// Validates a CityJSON document (or one CityJSONFeature with
// `feature`=true) against the shared CityJSON 2.0 schemas with valijson.
// Returns -1 when the schemas are missing, 0 valid, 1 invalid (`log` lists
// the errors).
int ValidateCityJson(const std::string& json_text, bool feature, std::string* log);

// Expects equal building count/order, ids, surface types and ids (when
// `surface_ids`), every vertex within `tol`, roof type, measured height and
// generic attributes (except roofsweep_validity).
void ExpectModelsNear(const CityModel& want, const CityModel& got, double tol,
                      bool surface_ids = true);

// Number of files in `dir` whose name contains ".tmp" (leftover temporaries).
int CountTempFiles(const std::string& dir);

std::string ReadText(const std::string& path);
void WriteText(const std::string& path, const std::string& text);

}  // namespace roofsweep::testing
