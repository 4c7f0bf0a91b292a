#pragma once

#include "algorithms/core/progress.h"

namespace roofsweep::cli {

// GDAL's "0...10...20...100 - done." on stdout, the way GDAL utilities
// report; the message of each update goes to CPLDebug (visible with --debug on).
class GdalTermProgress final : public Progress {
 public:
  bool Update(double fraction, const std::string& message) override;
};

// Makes SIGINT and SIGTERM a cancel request instead of an abrupt end: the
// next progress update returns false, the work unwinds, temporary outputs
// are removed and the program exits 2 ("interrupted"). The QGIS provider's
// Cancel sends SIGTERM.
void InstallInterruptHandler();
bool InterruptRequested();

// Wraps another progress (or none, with -q) and adds the interrupt check.
class InterruptibleProgress final : public Progress {
 public:
  explicit InterruptibleProgress(Progress* inner) : inner_(inner) {}
  bool Update(double fraction, const std::string& message) override {
    if (InterruptRequested()) return false;
    return inner_ ? inner_->Update(fraction, message) : true;
  }

 private:
  Progress* inner_;
};

}  // namespace roofsweep::cli
