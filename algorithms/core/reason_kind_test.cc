#include "algorithms/core/reason_kind.h"

#include <gtest/gtest.h>

namespace roofsweep {
namespace {

TEST(ReasonKind, NumbersSubjectAndTailGo) {
  EXPECT_EQ(ReasonKind("plane 7 (line 3): slope 71.4 deg > 70.0 deg (a wall?)"),
            "slope # deg > # deg");
  EXPECT_EQ(ReasonKind("building hypothesis 19: footprint 2.5 m2 < 5.0 m2"),
            "footprint # m# < # m#");
  // A reason without a subject keeps its own colon.
  EXPECT_EQ(
      ReasonKind("height not confirmed: score 0.44, 0.7 m lower 0.40 (margin 0.10 needed)", false),
      "height not confirmed: score #, # m lower #");
  EXPECT_EQ(ReasonKind("no colon here 12"), "no colon here #");
}

}  // namespace
}  // namespace roofsweep
