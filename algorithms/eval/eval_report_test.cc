#include "algorithms/eval/eval_report.h"

#include <gtest/gtest.h>

#include "algorithms/eval/test_models.h"

namespace roofsweep {
namespace {

TEST(EvalReport, JsonHasTheAgreedKeysAndNullForUndefined) {
  const CityModel m = eval_test::ThreeHouses();
  const std::vector<Segment3> lines = eval_test::UniqueRoofEdges(m);
  const nlohmann::json j = ToJson(Evaluate(m, m, {}, &lines));
  for (const char* k :
       {"/roof_planes/completeness", "/roof_planes/correctness", "/roof_planes/quality",
        "/roof_planes/completeness_large", "/roof_planes/correctness_large",
        "/geometry/angle_median_deg", "/geometry/angle_rms_deg", "/geometry/vertex_rms_m",
        "/geometry/rmsz_m", "/buildings/completeness", "/buildings/correctness",
        "/lines3d/precision", "/lines3d/completeness", "/lines3d/roof_edge_completeness"}) {
    SCOPED_TRACE(k);
    ASSERT_TRUE(j.contains(nlohmann::json::json_pointer(k)));
    EXPECT_TRUE(j[nlohmann::json::json_pointer(k)].is_number());
  }
  EXPECT_EQ(j["roof_planes"]["n_reference"], 7);
  EXPECT_DOUBLE_EQ(j["roof_planes"]["quality"].get<double>(), 1.0);

  const nlohmann::json e = ToJson(Evaluate(CityModel{}, m, {}));
  EXPECT_DOUBLE_EQ(e["roof_planes"]["completeness"].get<double>(), 0.0);
  EXPECT_TRUE(e["roof_planes"]["correctness"].is_null());
  EXPECT_EQ(e["roof_planes"]["n_result"], 0);
  EXPECT_TRUE(e["geometry"]["rmsz_m"].is_null());
  EXPECT_FALSE(e["lines3d"]["evaluated"].get<bool>());
  EXPECT_TRUE(e["lines3d"]["precision"].is_null());
  const std::string text = e.dump();
  EXPECT_EQ(text.find("nan"), std::string::npos);
  EXPECT_EQ(text.find("inf"), std::string::npos);
  // Round trip through text: still valid JSON.
  EXPECT_FALSE(nlohmann::json::parse(text).is_discarded());
}

TEST(EvalReport, TableShowsFiguresAndNa) {
  const CityModel m = eval_test::ThreeHouses();
  const std::string t = FormatTable(Evaluate(CityModel{}, m, {}));
  EXPECT_NE(t.find("completeness"), std::string::npos);
  EXPECT_NE(t.find("0.0 %"), std::string::npos);
  EXPECT_NE(t.find("n/a"), std::string::npos);
  EXPECT_NE(t.find("0 of 7 reference"), std::string::npos);
  const std::string self = FormatTable(Evaluate(m, m, {}));
  EXPECT_NE(self.find("100.0 %"), std::string::npos);
  EXPECT_EQ(self.find("3D lines"), std::string::npos);  // none given
}

}  // namespace
}  // namespace roofsweep
