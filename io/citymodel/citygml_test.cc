#include <gtest/gtest.h>

#include <filesystem>

#include "algorithms/core/error.h"
#include "io/citymodel/citygml_reader.h"
#include "io/citymodel/citygml_writer.h"
#include "io/citymodel/citymodel_io.h"
#include "io/citymodel/procedural_buildings.h"
#include "io/citymodel/test_util.h"
#include "tests/support/shared_data.h"

namespace roofsweep {
namespace {

using testing::ExpectModelsNear;
using testing::ReadText;
using testing::WriteText;

#define XMLLINT_OR_SKIP(path)                                                       \
  do {                                                                              \
    std::string log_;                                                               \
    const int rc_ = testing::XmllintCityGml(path, &log_);                           \
    if (rc_ < 0) {                                                                  \
      if (testing::SharedRequired()) FAIL() << "xmllint or CityGML schema missing"; \
      GTEST_SKIP() << "xmllint or shared CityGML schema missing -- skipping";       \
    }                                                                               \
    EXPECT_EQ(rc_, 0) << log_;                                                      \
  } while (0)

// A roof polygon with a hole (a light well) so interior rings are covered.
CityModel CityWithHole() {
  CityModel m = testing::MakeCity(6);
  Polygon3& roof = m.buildings[0].surfaces.back().polygons[0];  // box: flat roof
  const Eigen::Vector3d c = roof.exterior[0] + Eigen::Vector3d(4, 3, 0);
  roof.holes.push_back({c, c + Eigen::Vector3d(0, 1, 0), c + Eigen::Vector3d(1, 1, 0),
                        c + Eigen::Vector3d(1, 0, 0)});  // clockwise from above
  return m;
}

TEST(CityGml, WrittenFileValidatesAgainstXsd) {
  const std::string dir = testing::TempDir("gml");
  const std::string path = dir + "/city.gml";
  WriteCityModel(CityWithHole(), path);
  const std::string text = ReadText(path);
  EXPECT_NE(text.find("srsName=\"EPSG:25832\""), std::string::npos);
  EXPECT_LT(text.find("gen:doubleAttribute"), text.find("bldg:roofType"));
  EXPECT_LT(text.find("bldg:roofType"), text.find("bldg:measuredHeight"));
  EXPECT_NE(text.find("xlink:href=\"#BLDG_000001_poly_0\""), std::string::npos);
  XMLLINT_OR_SKIP(path);
}

TEST(CityGml, LibcitygmlReadsBackWithinAMillimetre) {
  const std::string dir = testing::TempDir("gml");
  const std::string path = dir + "/city.gml";
  const CityModel m = CityWithHole();
  WriteCityModel(m, path);
  const CityModel r = ReadCityGml(path);
  EXPECT_EQ(r.crs, "EPSG:25832");
  ExpectModelsNear(m, r, 1e-3);
  // The light well's edges belong to one polygon only: the solid is open,
  // and the writer says so.
  EXPECT_EQ(r.buildings[0].string_attributes.at("roofsweep_validity"), "302 SHELL_NOT_CLOSED");
  for (size_t i = 1; i < r.buildings.size(); ++i)
    EXPECT_EQ(r.buildings[i].string_attributes.at("roofsweep_validity"), "valid");
  EXPECT_EQ(r.buildings[0].surfaces.back().polygons[0].holes.size(), 1u);
}

TEST(CityGml, InvalidIdsAreMadeNcNamesAndStillValidate) {
  const std::string dir = testing::TempDir("gml");
  const std::string path = dir + "/ids.gml";
  CityModel m = testing::MakeCity(3);
  m.buildings[0].id = "123";
  m.buildings[1].id = "a b/c";
  m.buildings[2].id = "123";                         // duplicate after sanitising
  m.buildings[2].surfaces[0].id = "BLDG_000002_s0";  // clashes with building 1's surface
  WriteCityModel(m, path);
  const CityModel r = ReadCityGml(path);
  ASSERT_EQ(r.buildings.size(), 3u);
  EXPECT_EQ(r.buildings[0].id, "id_123");
  EXPECT_EQ(r.buildings[1].id, "a_b_c");
  EXPECT_NE(r.buildings[2].id, "id_123");
  XMLLINT_OR_SKIP(path);
}

TEST(CityGml, ValidityViolationsAreWrittenNotHidden) {
  const std::string dir = testing::TempDir("gml");
  const std::string path = dir + "/flip.gml";
  CityModel m = testing::MakeCity(2);
  auto& ring = m.buildings[1].surfaces[1].polygons[0].exterior;
  std::reverse(ring.begin(), ring.end());
  WriteCityModel(m, path);
  const CityModel r = ReadCityGml(path);
  EXPECT_EQ(r.buildings[0].string_attributes.at("roofsweep_validity"), "valid");
  EXPECT_EQ(r.buildings[1].string_attributes.at("roofsweep_validity"),
            "307 POLYGON_WRONG_ORIENTATION");
}

TEST(CityGml, StreamingWriterTakesBuildingsOneByOne) {
  const std::string dir = testing::TempDir("gml");
  const std::string path = dir + "/stream.gml";
  const CityModel m = testing::MakeCity(5);
  {
    CityGmlWriter w(path);
    w.Begin(m.crs, m.Bounds());
    for (const auto& b : m.buildings) w.Write(b);
    EXPECT_FALSE(std::filesystem::exists(path));  // only the temporary exists until End
    w.End();
  }
  ExpectModelsNear(m, ReadCityGml(path), 1e-3);
  EXPECT_EQ(testing::CountTempFiles(dir), 0);
}

TEST(CityGml, AbandonedWriterLeavesNothing) {
  const std::string dir = testing::TempDir("gml");
  {
    CityGmlWriter w(dir + "/x.gml");
    w.Begin("EPSG:25832", testing::MakeCity(1).Bounds());
    w.Write(testing::MakeCity(1).buildings[0]);
  }  // no End(): e.g. an exception in the caller
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.gml"));
  EXPECT_EQ(testing::CountTempFiles(dir), 0);
}

TEST(CityGml, ReadsKitEasyTestcase) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(
      path, "data/citygml/kit-fzk-easycitygml-testcase/LOD2_Buildings_v200.gml");
  const CityModel m = ReadCityGml(path);
  ASSERT_EQ(m.buildings.size(), 100u);
  for (const auto& b : m.buildings) {
    int roofs = 0, walls = 0, grounds = 0;
    for (const auto& s : b.surfaces) {
      roofs += s.type == SurfaceType::kRoof;
      walls += s.type == SurfaceType::kWall;
      grounds += s.type == SurfaceType::kGround;
    }
    EXPECT_EQ(roofs, 2) << b.id;
    EXPECT_EQ(walls, 4) << b.id;
    EXPECT_EQ(grounds, 1) << b.id;
    EXPECT_EQ(b.roof_type, roof_type::kGabled);
    EXPECT_GT(b.measured_height, 0);
  }
  EXPECT_EQ(m.crs, "");  // the test case has no srsName
}

TEST(CityGml, ReadsBerlinTileWithCrsFromUrn) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(path, "data/citygml/berlin-lod2/3910_5819.gml");
  const CityModel m = ReadCityGml(path);
  EXPECT_EQ(m.buildings.size(), 35u);
  int roofs = 0;
  for (const auto& b : m.buildings)
    for (const auto& s : b.surfaces) roofs += s.type == SurfaceType::kRoof;
  EXPECT_EQ(roofs, 59);
  EXPECT_EQ(m.crs, "EPSG:25833");
}

TEST(CityGml, BuildingPartsAreReadAsPartsAndMergeOnRequest) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(path, "data/citygml/berlin-lod2/3910_5817.gml");
  CityModel m = ReadCityGml(path);
  EXPECT_EQ(m.buildings.size(), 166u);
  int roofs = 0, own_roofs = 0, parts = 0;
  for (const auto& b : m.buildings) {
    parts += static_cast<int>(b.parts.size());
    for (const Building* solid : b.Solids())
      for (const auto& s : solid->surfaces) roofs += s.type == SurfaceType::kRoof;
    for (const auto& s : b.surfaces) own_roofs += s.type == SurfaceType::kRoof;
  }
  EXPECT_EQ(roofs, 387);  // PROVENANCE.md's count, which includes the parts' roofs
  EXPECT_LT(own_roofs, roofs);
  EXPECT_EQ(parts, 15);  // the file's bldg:BuildingPart elements
  MergeBuildingParts(&m);
  int merged = 0;
  for (const auto& b : m.buildings) {
    EXPECT_TRUE(b.parts.empty());
    for (const auto& s : b.surfaces) merged += s.type == SurfaceType::kRoof;
  }
  EXPECT_EQ(merged, 387);
}

TEST(CityGml, ReadsCityGml10) {
  const std::string dir = testing::TempDir("gml");
  WriteCityModel(testing::MakeCity(3), dir + "/v2.gml");
  std::string text = ReadText(dir + "/v2.gml");
  for (const char* mod : {"citygml/building/", "citygml/generics/", "citygml/"}) {
    const std::string from = std::string("http://www.opengis.net/") + mod + "2.0";
    const std::string to = std::string("http://www.opengis.net/") + mod + "1.0";
    for (size_t p; (p = text.find(from)) != std::string::npos;) text.replace(p, from.size(), to);
  }
  WriteText(dir + "/v1.gml", text);
  const CityModel m = ReadCityGml(dir + "/v1.gml");
  ExpectModelsNear(testing::MakeCity(3), m, 1e-3);
}

void ExpectErrorContaining(const std::string& path, const std::string& needle) {
  try {
    ReadCityGml(path);
    ADD_FAILURE() << "no error for " << path;
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(needle), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
}

TEST(CityGml, BadInputGivesOneLineErrors) {
  const std::string dir = testing::TempDir("gml");
  WriteCityModel(testing::MakeCity(3), dir + "/ok.gml");
  const std::string text = ReadText(dir + "/ok.gml");
  WriteText(dir + "/truncated.gml", text.substr(0, text.size() / 2));
  ExpectErrorContaining(dir + "/truncated.gml", "parse error");

  std::string wrong = text;
  const std::string core = "http://www.opengis.net/citygml/";
  for (size_t p; (p = wrong.find(core)) != std::string::npos;)
    wrong.replace(p, core.size(), "http://example.com/notcity/");
  WriteText(dir + "/wrongns.gml", wrong);
  ExpectErrorContaining(dir + "/wrongns.gml", "not CityGML");

  WriteText(dir + "/plain.xml", "<?xml version=\"1.0\"?><root><a/></root>\n");
  ExpectErrorContaining(dir + "/plain.xml", "not CityGML");
  ExpectErrorContaining(dir + "/missing.gml", "no such file");
}

TEST(CityGml, NoBuildingsGivesAnEmptyModel) {
  const std::string dir = testing::TempDir("gml");
  CityModel empty;
  empty.crs = "EPSG:25832";
  WriteCityModel(empty, dir + "/empty.gml");
  const CityModel m = ReadCityGml(dir + "/empty.gml");
  EXPECT_TRUE(m.buildings.empty());
  EXPECT_EQ(m.crs, "EPSG:25832");
}

}  // namespace
}  // namespace roofsweep
