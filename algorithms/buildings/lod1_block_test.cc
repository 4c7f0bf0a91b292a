#include "algorithms/buildings/lod1_block.h"

#include <gtest/gtest.h>

#include "algorithms/buildings/solid_check.h"

namespace roofsweep {
namespace {

// A gable house 10 m x 8 m on the ground at z 100: eaves at 105 along x,
// ridge at 108 over y = 4, four verges.
std::vector<Segment3> GableLines() {
  return {{{0, 0, 105}, {10, 0, 105}}, {{0, 8, 105}, {10, 8, 105}}, {{0, 4, 108}, {10, 4, 108}},
          {{0, 0, 105}, {0, 4, 108}},  {{0, 8, 105}, {0, 4, 108}},  {{10, 0, 105}, {10, 4, 108}},
          {{10, 8, 105}, {10, 4, 108}}};
}

const Ring2 kRect = {{0, 0}, {10, 0}, {10, 8}, {0, 8}};

TEST(Lod1Block, HeightIsTheLengthWeightedQuantileOfTheRoofLines) {
  std::vector<Segment3> lines = GableLines();
  // None of these may count: a line on the ground, a wall's corner, a
  // line beyond the footprint and one above the block's highest building.
  lines.push_back({{1, 1, 100.2}, {9, 1, 100.2}});
  lines.push_back({{10, 0, 102.5}, {10, 0, 105}});
  lines.push_back({{12, 0, 120}, {20, 0, 120}});
  lines.push_back({{2, 2, 200}, {8, 2, 200}});
  const Lod1Height h = Lod1HeightFromLines(kRect, 100, 60, lines);
  EXPECT_EQ(h.lines, 7);
  EXPECT_NEAR(h.length_m, 50, 1e-9);
  // 20 m of eaves at 105, 20 m of verges spread evenly over 105-108, 10 m
  // of ridge at 108: 70 % of the 50 m lies below 105 + 3 * 15 / 20.
  EXPECT_NEAR(h.z, 107.25, 0.1);
  Lod1Options median;
  median.quantile = 0.5;
  EXPECT_NEAR(Lod1HeightFromLines(kRect, 100, 60, lines, median).z, 105 + 3 * 5 / 20.0, 0.1);
}

// An eave and a ridge running on along a terrace count for this house by
// their stretch over its footprint (with the 0.5 m margin).
TEST(Lod1Block, LinesCountByTheirStretchOverTheFootprint) {
  const std::vector<Segment3> terrace = {{{-10, 0, 105}, {20, 0, 105}},
                                         {{-10, 4, 108}, {20, 4, 108}}};
  const Lod1Height h = Lod1HeightFromLines(kRect, 100, 60, terrace);
  EXPECT_EQ(h.lines, 2);
  EXPECT_NEAR(h.length_m, 22, 0.3);
  EXPECT_NEAR(h.z, 108, 1e-9);
  // A line that only grazes the footprint (its last 0.3 m) does not count.
  const std::vector<Segment3> grazing = {terrace[0], {{10.2, 3, 106}, {30, 3, 106}}};
  EXPECT_EQ(Lod1HeightFromLines(kRect, 100, 60, grazing).lines, 1);
}

// Short lines matched 30 m too high are left out, however the quantile
// falls; without them what is left may be too little.
TEST(Lod1Block, LinesFarFromTheMedianHeightAreLeftOut) {
  std::vector<Segment3> lines = GableLines();
  lines.push_back({{2, 2, 138}, {2, 6, 138}});
  lines.push_back({{8, 2, 138}, {8, 6, 138}});
  const Lod1Height h = Lod1HeightFromLines(kRect, 100, 60, lines);
  EXPECT_EQ(h.lines, 7);
  EXPECT_NEAR(h.z, 107.25, 0.1);
  // Three short lines, one far above the two others: none to trust.
  const std::vector<Segment3> sparse = {
      {{1, 1, 107}, {1, 3.1, 107}}, {{3, 1, 111}, {3, 2.3, 111}}, {{5, 1, 141.7}, {5, 2.6, 141.7}}};
  const Lod1Height s = Lod1HeightFromLines(kRect, 100, 60, sparse);
  EXPECT_EQ(s.lines, 2);
  EXPECT_TRUE(std::isnan(s.z));
}

TEST(Lod1Block, TooLittleEvidenceGivesNoHeight) {
  const std::vector<Segment3> one = {GableLines()[2]};
  const Lod1Height h = Lod1HeightFromLines(kRect, 100, 60, one);
  EXPECT_EQ(h.lines, 1);
  EXPECT_TRUE(std::isnan(h.z));
  const std::vector<Segment3> short_ones = {{{1, 1, 105}, {2, 1, 105}}, {{1, 2, 105}, {2, 2, 105}}};
  EXPECT_TRUE(std::isnan(Lod1HeightFromLines(kRect, 100, 60, short_ones).z));
  EXPECT_TRUE(std::isnan(Lod1HeightFromLines(kRect, NAN, 60, GableLines()).z));
  EXPECT_TRUE(std::isnan(Lod1HeightFromLines({}, 100, 60, GableLines()).z));
}

TEST(Lod1Block, BlockOverANonConvexFootprintIsAValidSolid) {
  const Ring2 l_shape = {{0, 0}, {12, 0}, {12, 5}, {5, 5}, {5, 10}, {0, 10}};
  const Building b = Lod1Block(l_shape, 50, 56.5);
  EXPECT_EQ(b.lod, 1);
  EXPECT_EQ(b.roof_type, roof_type::kUnknown);
  EXPECT_DOUBLE_EQ(b.measured_height, 6.5);
  ASSERT_EQ(b.surfaces.size(), 2 + l_shape.size());
  EXPECT_EQ(b.surfaces[0].type, SurfaceType::kGround);
  EXPECT_EQ(b.surfaces[1].type, SurfaceType::kRoof);
  EXPECT_GT(b.surfaces[1].polygons[0].Normal().z(), 0.99);
  EXPECT_NEAR(b.surfaces[1].polygons[0].Area(), 12 * 5 + 5 * 5, 1e-9);
  const SolidCheckResult check = CheckBuildingSolid(b);
  EXPECT_TRUE(check.Valid()) << check.Summary();
}

// A footprint that got a building is left alone; one with lines over it
// gets a block and its reason marked; one without lines keeps its reason;
// the two pieces of a multipolygon footprint become the parts of one.
TEST(Lod1Block, FootprintsWithoutABuildingGetABlockWhereTheLinesAllow) {
  auto shifted = [](const Ring2& r, double dx) {
    Ring2 out = r;
    for (auto& p : out) p.x() += dx;
    return out;
  };
  auto lines_over = [](double dx) {
    std::vector<Segment3> out = GableLines();
    for (auto& l : out) l.a.x() += dx, l.b.x() += dx;
    return out;
  };
  const std::vector<Footprint> footprints = {{"A", kRect, 0},
                                             {"B", shifted(kRect, 20), 0},
                                             {"C", shifted(kRect, 40), 0},
                                             {"D", shifted(kRect, 60), 1},
                                             {"D", shifted(kRect, 80), 0}};
  std::vector<Segment3> lines;
  for (double dx : {0.0, 20.0, 60.0, 80.0})
    for (const Segment3& l : lines_over(dx)) lines.push_back(l);
  AssemblyResult assembled;
  CityModel& model = assembled.model;
  model.buildings.push_back(Lod1Block(kRect, 100, 108));
  model.buildings.back().lod = 2;
  model.buildings.back().string_attributes["footprint_id"] = "A";
  // The reasons are the footprint_rejection entries, not the text: D's
  // line names a building, and DE's subject starts with D's.
  std::vector<std::string>& rejected = assembled.rejected;
  rejected = {"footprint B: no roof plane found over it", "plane 3: too small",
              "footprint C: no roof plane found over it",
              "footprint D (building rs_b0007): edges not seen",
              "footprint DE: no roof plane found over it"};
  assembled.footprint_rejection = {{"B", {"no roof plane found over it", 0}},
                                   {"C", {"no roof plane found over it", 2}},
                                   {"D", {"edges not seen", 3}},
                                   {"DE", {"no roof plane found over it", 4}}};
  GroundModel ground;
  ground.height = 100;
  const Lod1Counts counts = AddLod1Blocks(footprints, ground, 60, lines, {}, &assembled);
  EXPECT_EQ(counts.footprints_without, 3);
  EXPECT_EQ(counts.blocks, 2);
  ASSERT_EQ(model.buildings.size(), 3u);
  const Building& b = model.buildings[1];
  EXPECT_EQ(b.id, "rs_l0001");
  EXPECT_EQ(b.lod, 1);
  EXPECT_EQ(b.string_attributes.at("footprint_id"), "B");
  EXPECT_EQ(b.string_attributes.at("lod1_reason"), "no roof plane found over it");
  EXPECT_DOUBLE_EQ(b.double_attributes.at("supporting_lines"), 7);
  EXPECT_NEAR(b.RoofTopZ(), 107.25, 0.1);
  EXPECT_EQ(rejected[0], "footprint B: no roof plane found over it; a flat block instead (LoD1)");
  EXPECT_EQ(rejected[2], "footprint C: no roof plane found over it");
  const Building& d = model.buildings[2];
  EXPECT_EQ(d.string_attributes.at("footprint_id"), "D");
  EXPECT_EQ(d.string_attributes.at("lod1_reason"), "edges not seen");
  EXPECT_EQ(rejected[3],
            "footprint D (building rs_b0007): edges not seen; a flat block instead (LoD1)");
  EXPECT_EQ(rejected[4], "footprint DE: no roof plane found over it");
  EXPECT_EQ(d.string_attributes.at("outline"), "footprint (1 courtyards not modelled)");
  EXPECT_EQ(d.lod, 1);
  EXPECT_TRUE(d.surfaces.empty());
  ASSERT_EQ(d.parts.size(), 2u);
  for (const Building& part : d.parts) {
    EXPECT_EQ(part.lod, 1);
    EXPECT_TRUE(CheckBuildingSolid(part).Valid());
  }
  EXPECT_NEAR(d.double_attributes.at("footprint_m2"), 160, 1e-9);
}

}  // namespace
}  // namespace roofsweep
