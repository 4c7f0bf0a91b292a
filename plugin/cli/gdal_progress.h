#pragma once

#include "algorithms/core/progress.h"

namespace roofsweep::cli {

// GDAL's "0...10...20...100 - done." on stdout, the way GDAL utilities
// report; the message of each update goes to CPLDebug (visible with --debug on).
class GdalTermProgress final : public Progress {
 public:
  bool Update(double fraction, const std::string& message) override;
};

}  // namespace roofsweep::cli
