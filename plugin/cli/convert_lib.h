#pragma once

#include <string>

#include "algorithms/core/progress.h"
#include "io/citymodel/citymodel_io.h"

namespace roofsweep {

struct ConvertRequest {
  std::string input;
  std::string output;
  std::string input_format;  // empty: from the extension / content
  WriteOptions write;        // format (-of), overwrite, update
  std::string assign_crs;    // -a_srs: replaces the CRS the input declares
  std::string target_crs;    // -t_srs: reprojects from the input's CRS (excludes -a_srs)
  bool allow_empty = false;  // write a model with no buildings
  // Add the input's buildings to those of an existing output (read and
  // written back whole, atomically; a plain write when there is none): the
  // outputs of a tiled run gathered into one model. The two must share the
  // CRS, and no building id may be in both.
  bool append = false;
};

struct ConvertSummary {
  int buildings = 0;    // written (with -append: the input's and the output's)
  int appended_to = 0;  // -append: buildings the output held before
  int surfaces = 0;
  int invalid_buildings = 0;  // failing the solid checks (reported, still written)
  std::string format;
};

// `roofsweep convert`: reads a LoD2 model in any supported format and writes
// it in another. A model without buildings is refused unless allow_empty.
ConvertSummary RunConvert(const ConvertRequest& request, Progress& progress);

}  // namespace roofsweep
