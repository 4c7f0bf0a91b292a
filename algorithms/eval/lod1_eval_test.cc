#include "algorithms/eval/lod1_eval.h"

#include <gtest/gtest.h>

#include "algorithms/buildings/lod1_block.h"
#include "algorithms/eval/eval_report.h"
#include "algorithms/eval/test_models.h"

namespace roofsweep {
namespace {

Ring2 Rect(double x0, double y0, double l, double w) {
  return {{x0, y0}, {x0 + l, y0}, {x0 + l, y0 + w}, {x0, y0 + w}};
}

// The box found at LoD2; blocks over the box (1 m too high), over the
// gable (eaves 36, ridge 39: the block at 38) and over nothing.
TEST(Lod1Eval, BlocksAreScoredApartFromTheLod2Buildings) {
  const CityModel truth = eval_test::ThreeHouses();
  CityModel result;
  result.crs = truth.crs;
  result.buildings.push_back(truth.buildings[0]);
  result.buildings.push_back(Lod1Block(Rect(0, 0, 10, 8), 30, 37));
  result.buildings.push_back(Lod1Block(Rect(40, 0, 12, 8), 30, 38));
  result.buildings.push_back(Lod1Block(Rect(200, 0, 10, 10), 30, 35));

  const CityModel blocks = TakeLod1Buildings(&result);
  ASSERT_EQ(result.buildings.size(), 1u);
  ASSERT_EQ(blocks.buildings.size(), 3u);
  EXPECT_EQ(blocks.crs, truth.crs);

  EvalOptions o;
  const EvalResult lod2 = Evaluate(result, truth, o);
  EXPECT_EQ(lod2.buildings.tp_reference, 1);
  EXPECT_EQ(lod2.roof_planes.n_result, 1);  // the blocks' flat tops are not in it

  const Lod1Scores s = EvaluateLod1(blocks, truth, lod2, o);
  EXPECT_EQ(s.blocks, 3);
  EXPECT_EQ(s.over_reference, 2);
  EXPECT_EQ(s.n_reference, 3);
  EXPECT_EQ(s.found, 2);
  EXPECT_EQ(s.found_by_block_only, 1);
  EXPECT_NEAR(*s.found_fraction, 2.0 / 3.0, 1e-12);
  // Box: +1 m over 80 m2. Gable: 38 - (36 + 3 (1 - |y - 4| / 4)) over
  // 96 m2, mean +0.5 m and mean square 1 m2. Together RMS 1 m, mean
  // (80 + 48) / 176 m.
  ASSERT_TRUE(s.rmsz_m && s.dz_mean_m);
  EXPECT_NEAR(*s.rmsz_m, 1.0, 0.02);
  EXPECT_NEAR(*s.dz_mean_m, 128.0 / 176.0, 0.02);
  // At the mean heights: the box exact, the gable's roof spread about its
  // mean (37.5 m) by a standard deviation of 3 / sqrt(12) m over 96 of
  // 176 m2.
  ASSERT_TRUE(s.rmsz_at_mean_m);
  EXPECT_NEAR(*s.rmsz_at_mean_m, std::sqrt(96.0 / 176.0 * 9.0 / 12.0), 0.02);

  const std::string table = FormatLod1Table(s);
  EXPECT_NE(table.find("2 of 3 over a reference building"), std::string::npos) << table;
  EXPECT_EQ(Lod1ToJson(s)["found_by_block_only"], 1);
}

// Parts are merged first: a building of LoD1 parts is one block building.
TEST(Lod1Eval, ABuildingOfLod1PartsIsOneBlock) {
  CityModel m;
  Building whole;
  whole.lod = 1;
  whole.parts = {Lod1Block(Rect(0, 0, 5, 5), 0, 4), Lod1Block(Rect(5, 0, 5, 5), 0, 6)};
  m.buildings = {whole, eval_test::Box("B", 20, 0, 5, 5, 0, 3)};
  const CityModel blocks = TakeLod1Buildings(&m);
  ASSERT_EQ(blocks.buildings.size(), 1u);
  EXPECT_EQ(blocks.buildings[0].surfaces.size(), 12u);
  ASSERT_EQ(m.buildings.size(), 1u);
  EXPECT_EQ(m.buildings[0].lod, 2);
}

}  // namespace
}  // namespace roofsweep
