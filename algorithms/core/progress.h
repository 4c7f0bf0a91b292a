#pragma once

#include <string>

namespace roofsweep {

// Long work reports a fraction in [0, 1] and may be cancelled. The command
// line backs this with GDAL's term progress, the QGIS provider with its
// feedback object, so algorithms stay free of GDAL.
class Progress {
 public:
  virtual ~Progress() = default;
  // Returns false when the user asked to cancel; the caller should stop soon
  // and throw roofsweep::Cancelled.
  virtual bool Update(double fraction, const std::string& message = {}) = 0;
};

// Progress that shows nothing (-q, tests).
class NullProgress final : public Progress {
 public:
  bool Update(double, const std::string&) override { return true; }
};

// Maps [0, 1] of a sub-task onto [begin, end] of its parent, so stages can be
// chained without knowing their place in the pipeline.
class SubProgress final : public Progress {
 public:
  SubProgress(Progress& parent, double begin, double end)
      : parent_(parent), begin_(begin), end_(end) {}
  bool Update(double fraction, const std::string& message = {}) override;

 private:
  Progress& parent_;
  double begin_;
  double end_;
};

// Thrown when Progress::Update returned false.
struct Cancelled {};

// Calls progress.Update and throws Cancelled if the user cancelled.
void ReportOrCancel(Progress& progress, double fraction, const std::string& message = {});

}  // namespace roofsweep
