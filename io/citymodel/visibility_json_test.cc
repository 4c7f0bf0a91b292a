// The roof visibility file of `simulate`, read back by `eval`.
#include "io/citymodel/visibility_json.h"

#include <gtest/gtest.h>

#include "algorithms/core/error.h"
#include "io/citymodel/test_util.h"
#include "tests/support/shared_data.h"

namespace roofsweep {
namespace {

RoofVisibilityFile TwoPolygons() {
  RoofVisibilityFile f;
  f.crs = "EPSG:25832";
  f.views = {"s01_i001", "s01_i002"};
  f.polygons.push_back({"BLDG_0001", {691000.5, 5335000.25, 528.3}, {1.0f, 0.25f}});
  f.polygons.push_back({"BLDG_0002", {691010.0, 5335020.0, 525.0}, {0.0f, 0.6666f}});
  return f;
}

TEST(RoofVisibilityJson, WhatIsWrittenComesBackWithTheSharesRounded) {
  const std::string path = testing::TempDir("visibility") + "/groundtruth_visibility.json";
  WriteRoofVisibilityJson(TwoPolygons(), path, false);
  const RoofVisibilityFile got = ReadRoofVisibilityJson(path);
  EXPECT_EQ(got.crs, "EPSG:25832");
  EXPECT_EQ(got.views, TwoPolygons().views);
  ASSERT_EQ(got.polygons.size(), 2u);
  EXPECT_EQ(got.polygons[0].building, "BLDG_0001");
  EXPECT_EQ(got.polygons[0].centroid, Eigen::Vector3d(691000.5, 5335000.25, 528.3));
  EXPECT_EQ(got.polygons[0].seen, (std::vector<float>{1.0f, 0.25f}));
  EXPECT_EQ(got.polygons[1].seen, (std::vector<float>{0.0f, 0.667f}));
  // An existing file is kept unless asked.
  EXPECT_THROW(WriteRoofVisibilityJson(TwoPolygons(), path, false), Error);
  EXPECT_EQ(testing::CountTempFiles(testing::TempDir("visibility")), 0);
}

TEST(RoofVisibilityJson, ADamagedPolygonIsNamedWithItsIndex) {
  const std::string dir = testing::TempDir("visibility_bad");
  testing::WriteText(dir + "/v.json",
                     R"({"roof_polygons": [{"centroid": [1, 2, 3], "seen": [1]},
                                           {"centroid": [1, 2], "seen": [1]}]})");
  try {
    ReadRoofVisibilityJson(dir + "/v.json");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(dir + "/v.json: roof polygon 1 "), std::string::npos)
        << e.what();
  }
  testing::WriteText(dir + "/w.json", "[1, 2]");
  EXPECT_THROW(ReadRoofVisibilityJson(dir + "/w.json"), Error);
  EXPECT_THROW(ReadRoofVisibilityJson(dir + "/missing.json"), Error);
}

}  // namespace
}  // namespace roofsweep
