#include "algorithms/core/progress.h"

#include <gtest/gtest.h>

#include <vector>

namespace roofsweep {
namespace {

class Recorder : public Progress {
 public:
  bool Update(double f, const std::string&) override {
    seen.push_back(f);
    return f < cancel_at;
  }
  std::vector<double> seen;
  double cancel_at = 2.0;
};

TEST(SubProgress, MapsOntoParentRange) {
  Recorder parent;
  SubProgress sub(parent, 0.5, 0.75);
  sub.Update(0.0);
  sub.Update(0.5);
  sub.Update(2.0);  // clamped
  ASSERT_EQ(parent.seen.size(), 3u);
  EXPECT_DOUBLE_EQ(parent.seen[0], 0.5);
  EXPECT_DOUBLE_EQ(parent.seen[1], 0.625);
  EXPECT_DOUBLE_EQ(parent.seen[2], 0.75);
}

TEST(ReportOrCancel, ThrowsWhenCancelled) {
  Recorder p;
  p.cancel_at = 0.5;
  EXPECT_NO_THROW(ReportOrCancel(p, 0.25));
  EXPECT_THROW(ReportOrCancel(p, 0.75), Cancelled);
}

}  // namespace
}  // namespace roofsweep
