#include "io/citymodel/reproject.h"

#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/core/error.h"
#include "io/citymodel/procedural_buildings.h"

namespace roofsweep {
namespace {

// cs2cs -d 9 EPSG:25833 EPSG:25832 <<< "391800 5819000 50"
//   -> 798922.616786730 5826932.150407154 50.000000000
TEST(ReprojectCityModel, MovesEveryVertexAndTheCrs) {
  CityModel m;
  m.crs = "EPSG:25833";
  m.buildings.push_back(testing::MakeGable("b1", 391800.0, 5819000.0, 50.0, 12, 8, 4, 7));
  const size_t n = m.buildings[0].surfaces.size();
  ReprojectCityModel(m, "EPSG:25832");
  EXPECT_EQ(m.crs, "EPSG:25832");
  ASSERT_EQ(m.buildings[0].surfaces.size(), n);
  bool found_corner = false;
  for (const Surface& s : m.buildings[0].surfaces)
    for (const Polygon3& p : s.polygons)
      for (const Eigen::Vector3d& v : p.exterior) {
        // UTM 33 -> 32 moves points ~400 km east; heights are untouched.
        EXPECT_GT(v.x(), 798000.0);
        if ((v - Eigen::Vector3d(798922.616786730, 5826932.150407154, 50.0)).norm() < 1e-6)
          found_corner = true;
      }
  EXPECT_TRUE(found_corner)
      << "the footprint corner (391800, 5819000, 50) is not where cs2cs puts it";
}

TEST(ReprojectSegments, MovesBothEndsAndTheCrs) {
  SegmentSet set;
  set.crs = "EPSG:25833";
  LabelledSegment l;
  l.segment = {{391800.0, 5819000.0, 50.0}, {391810.0, 5819000.0, 52.0}};
  l.rms_px = 0.2;
  set.segments.push_back(l);
  ReprojectSegments(set, "EPSG:25832");
  EXPECT_EQ(set.crs, "EPSG:25832");
  ASSERT_EQ(set.segments.size(), 1u);
  // The same cs2cs point as above.
  EXPECT_LT((set.segments[0].segment.a - Eigen::Vector3d(798922.616786730, 5826932.150407154, 50.0))
                .norm(),
            1e-6);
  EXPECT_NEAR((set.segments[0].segment.b - set.segments[0].segment.a).norm(), std::hypot(10.0, 2.0),
              0.01);
  EXPECT_DOUBLE_EQ(set.segments[0].rms_px, 0.2);
  SegmentSet none;
  none.segments = set.segments;
  EXPECT_THROW(ReprojectSegments(none, "EPSG:25832"), Error);
}

TEST(ReprojectCityModel, UrnSpellingIsAccepted) {
  CityModel m;
  m.crs = "urn:ogc:def:crs:EPSG::25833";
  m.buildings.push_back(testing::MakeBox("b1", 391800.0, 5819000.0, 50.0, 10, 10, 6));
  ReprojectCityModel(m, "EPSG:4979");
  const Eigen::Vector3d& v = m.buildings[0].surfaces[0].polygons[0].exterior[0];
  EXPECT_NEAR(v.x(), 13.4, 0.01);
  EXPECT_NEAR(v.y(), 52.5, 0.02);
}

TEST(ReprojectCityModel, FailureLeavesTheModelUnchanged) {
  CityModel m;
  m.crs = "EPSG:25833";
  m.buildings.push_back(testing::MakeBox("b1", 391800.0, 5819000.0, 50.0, 10, 10, 6));
  const CityModel before = m;
  EXPECT_THROW(ReprojectCityModel(m, "EPSG:25833+7837"), Error);  // ballpark heights
  EXPECT_THROW(ReprojectCityModel(m, "EPSG:999999"), Error);
  EXPECT_EQ(m.crs, before.crs);
  EXPECT_EQ(m.buildings[0].surfaces[0].polygons[0].exterior,
            before.buildings[0].surfaces[0].polygons[0].exterior);
  CityModel local;
  local.buildings = m.buildings;
  try {
    ReprojectCityModel(local, "EPSG:25832");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no CRS"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace roofsweep
