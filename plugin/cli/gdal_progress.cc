#include "plugin/cli/gdal_progress.h"

#include <cpl_error.h>
#include <cpl_progress.h>

namespace roofsweep::cli {

bool GdalTermProgress::Update(double fraction, const std::string& message) {
  if (!message.empty()) CPLDebug("ROOFSWEEP", "%.0f%% %s", 100 * fraction, message.c_str());
  return GDALTermProgress(fraction, nullptr, nullptr) != FALSE;
}

}  // namespace roofsweep::cli
