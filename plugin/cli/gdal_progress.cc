#include "plugin/cli/gdal_progress.h"

#include <cpl_error.h>
#include <cpl_progress.h>

#include <atomic>
#include <csignal>

namespace roofsweep::cli {

bool GdalTermProgress::Update(double fraction, const std::string& message) {
  if (!message.empty()) CPLDebug("ROOFSWEEP", "%.0f%% %s", 100 * fraction, message.c_str());
  return GDALTermProgress(fraction, nullptr, nullptr) != FALSE;
}

namespace {
std::atomic<bool> g_interrupted{false};
extern "C" void OnInterrupt(int) { g_interrupted.store(true); }
}  // namespace

void InstallInterruptHandler() {
  std::signal(SIGINT, OnInterrupt);
  std::signal(SIGTERM, OnInterrupt);
}

bool InterruptRequested() { return g_interrupted.load(); }

}  // namespace roofsweep::cli
