#include "algorithms/core/progress.h"

#include <algorithm>

namespace roofsweep {

bool SubProgress::Update(double fraction, const std::string& message) {
  const double f = std::clamp(fraction, 0.0, 1.0);
  return parent_.Update(begin_ + f * (end_ - begin_), message);
}

void ReportOrCancel(Progress& progress, double fraction, const std::string& message) {
  if (!progress.Update(fraction, message)) throw Cancelled{};
}

}  // namespace roofsweep
