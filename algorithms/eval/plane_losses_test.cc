#include "algorithms/eval/plane_losses.h"

#include <gtest/gtest.h>

#include "algorithms/eval/test_models.h"

namespace roofsweep {
namespace {

PlaneHypothesisRecord Flat(double x0, double y0, double x1, double y1, double z,
                           const std::string& status, const std::string& reason = "") {
  return {{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}, status, reason};
}

TEST(ClassifyMissedPlanes, EachMissedPlaneGetsTheFurthestStageOfAHypothesisForIt) {
  const CityModel truth = eval_test::ThreeHouses();
  CityModel result;
  result.crs = truth.crs;
  result.buildings = {truth.buildings[2]};  // only the hip house was built
  const EvalResult e = Evaluate(result, truth, EvalOptions());
  const std::vector<PlaneHypothesisRecord> hyps = {
      // The flat roof (z = 36) found and refused by the verification...
      Flat(1, 1, 9, 7, 36, "rejected",
           "height not confirmed: score 0.44, 0.7 m lower 0.40 (margin 0.10 needed)"),
      // ... a plane 4 m above it does not stand for it, though built...
      Flat(1, 1, 9, 7, 40, "built"),
      // ... nor does a flat plane over the gable's sloped faces.
      Flat(41, 1, 51, 7, 37.5, "built")};
  const PlaneLosses l = ClassifyMissedPlanes(truth, e, hyps);
  ASSERT_EQ(l.stage.size(), e.reference_planes.size());
  int missed = 0;
  for (size_t r = 0; r < l.stage.size(); ++r) {
    const PlaneRecord& p = e.reference_planes[r];
    EXPECT_EQ(l.stage[r].empty(), p.true_positive) << r;
    if (p.true_positive) continue;
    ++missed;
    if (p.building == 0)
      EXPECT_EQ(l.stage[r], "rejected: height not confirmed: score #, # m lower #");
    else
      EXPECT_EQ(l.stage[r], "no verified hypothesis") << r;
  }
  EXPECT_EQ(missed, 3);  // the box's roof and the gable's two faces
  EXPECT_EQ(l.count.at("no verified hypothesis"), 2);
  EXPECT_NEAR(l.area_m2.at("no verified hypothesis"), 12 * 8, 1e-6);
  EXPECT_NE(FormatPlaneLosses(l).find("(3)"), std::string::npos) << FormatPlaneLosses(l);
}

}  // namespace
}  // namespace roofsweep
