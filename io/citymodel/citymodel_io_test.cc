#include "io/citymodel/citymodel_io.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "algorithms/buildings/lod1_block.h"
#include "algorithms/core/error.h"
#include "algorithms/core/progress.h"
#include "io/citymodel/procedural_buildings.h"
#include "io/citymodel/test_util.h"
#include "tests/support/shared_data.h"

namespace roofsweep {
namespace {

TEST(CityModelIo, FormatFromExtensionOrName) {
  EXPECT_EQ(ResolveCityModelFormat("a.gml"), "CityGML");
  EXPECT_EQ(ResolveCityModelFormat("a.XML"), "CityGML");
  EXPECT_EQ(ResolveCityModelFormat("a.city.json"), "CityJSON");
  EXPECT_EQ(ResolveCityModelFormat("a.json"), "CityJSON");
  EXPECT_EQ(ResolveCityModelFormat("a.city.jsonl"), "CityJSONSeq");
  EXPECT_EQ(ResolveCityModelFormat("a.gpkg"), "GPKG");
  EXPECT_EQ(ResolveCityModelFormat("a.fgb"), "FlatGeobuf");
  EXPECT_EQ(ResolveCityModelFormat("a.out", "cityjson"), "CityJSON");
  EXPECT_EQ(ResolveCityModelFormat("a.out", "GPKG"), "GPKG");
  EXPECT_THROW(ResolveCityModelFormat("a.out"), Error);
  EXPECT_THROW(ResolveCityModelFormat("a.gml", "NoSuchFormat"), Error);
}

// GML -> CityJSON -> GPKG -> GML keeps geometry (1 mm), semantics and
// attributes: the conversion chain `roofsweep convert` offers.
TEST(CityModelIo, RoundTripThroughAllFormats) {
  const std::string dir = testing::TempDir("io");
  const CityModel m = testing::MakeCity(10);
  WriteCityModel(m, dir + "/a.gml");
  const CityModel a = ReadCityModel(dir + "/a.gml");
  WriteCityModel(a, dir + "/b.city.json");
  const CityModel b = ReadCityModel(dir + "/b.city.json");
  WriteCityModel(b, dir + "/c.gpkg");
  const CityModel c = ReadCityModel(dir + "/c.gpkg");
  WriteCityModel(c, dir + "/d.gml");
  const CityModel d = ReadCityModel(dir + "/d.gml");
  EXPECT_EQ(d.crs, "EPSG:25832");
  testing::ExpectModelsNear(m, d, 1e-3);
  for (const auto& bl : d.buildings)
    EXPECT_EQ(bl.string_attributes.at("roofsweep_validity"), "valid");
  std::string log;
  if (testing::XmllintCityGml(dir + "/d.gml", &log) >= 0) {
    EXPECT_EQ(testing::XmllintCityGml(dir + "/d.gml", &log), 0) << log;
  }
}

// A building of two parts (the solids over one footprint) keeps its parts,
// their attributes and geometry in every format, and the files stay valid.
TEST(CityModelIo, BuildingPartsRoundTripThroughEveryFormat) {
  const std::string dir = testing::TempDir("io");
  CityModel m = testing::MakeCity(4);
  Building whole;
  whole.id = "house_1";
  whole.string_attributes["footprint_id"] = "DEBE123";
  whole.double_attributes["building_parts"] = 2;
  whole.roof_type = roof_type::kCombination;
  whole.parts = {m.buildings[0], m.buildings[1]};
  whole.parts[0].id = "house_1_p1";
  whole.parts[1].id = "house_1_p2";
  whole.measured_height = whole.RoofTopZ() - whole.GroundZ();
  m.buildings.erase(m.buildings.begin(), m.buildings.begin() + 2);
  m.buildings.insert(m.buildings.begin() + 1, whole);
  for (const char* out : {"p.gml", "p.city.json", "p.city.jsonl", "p.gpkg"}) {
    SCOPED_TRACE(out);
    WriteCityModel(m, dir + "/" + out);
    const CityModel r = ReadCityModel(dir + "/" + out);
    testing::ExpectModelsNear(m, r, 1e-3);
    ASSERT_EQ(r.buildings.size(), 3u);
    // The whole has no solid of its own to check; each part says it is valid.
    EXPECT_EQ(r.buildings[1].string_attributes.count("roofsweep_validity"), 0u);
    for (const Building& part : r.buildings[1].parts)
      EXPECT_EQ(part.string_attributes.at("roofsweep_validity"), "valid");
  }
  std::string log;
  const int rc = testing::XmllintCityGml(dir + "/p.gml", &log);
  if (rc >= 0) {
    EXPECT_EQ(rc, 0) << log;
  }
  const int cj = testing::ValidateCityJson(testing::ReadText(dir + "/p.city.json"), false, &log);
  if (cj >= 0) {
    EXPECT_EQ(cj, 0) << log;
  }
  // The flat layout keeps the parts and their attributes; the whole keeps its id.
  WriteCityModel(m, dir + "/p.fgb");
  CityModel flat = ReadCityModel(dir + "/p.fgb");
  CityModel want = m;
  want.buildings[1].string_attributes.clear();
  want.buildings[1].double_attributes.clear();
  want.buildings[1].roof_type = roof_type::kUnknown;
  want.buildings[1].measured_height = 0;
  testing::ExpectModelsNear(want, flat, 1e-3);
  // Merged, the parts' surfaces are the building's, in order.
  MergeBuildingParts(&flat);
  EXPECT_TRUE(flat.buildings[1].parts.empty());
  EXPECT_EQ(flat.buildings[1].surfaces.size(),
            m.buildings[1].parts[0].surfaces.size() + m.buildings[1].parts[1].surfaces.size());
}

// An LoD1 block beside LoD2 buildings stays LoD1 in every format: a
// lod1Solid of plain polygons in CityGML (LoD1 has no thematic surfaces),
// "lod": "1" in CityJSON, field lod in the OGR layers; the files stay valid.
TEST(CityModelIo, Lod1BlocksRoundTripThroughEveryFormat) {
  const std::string dir = testing::TempDir("io");
  CityModel m = testing::MakeCity(3);
  // Beside the others, at their coordinates' magnitude (MakeCity's origin).
  const Eigen::Vector3d at = m.buildings[0].surfaces[0].polygons[0].exterior[0];
  Ring2 l_shape = {{0, 0}, {12, 0}, {12, 5}, {5, 5}, {5, 10}, {0, 10}};
  for (auto& p : l_shape) p += at.head<2>() + Eigen::Vector2d(60.0037, 0.0041);
  Building block = Lod1Block(l_shape, at.z(), at.z() + 7.5);
  block.id = "rs_l0001";
  block.string_attributes["footprint_id"] = "DEBE9";
  block.string_attributes["lod1_reason"] = "no roof plane found over it";
  // A block's surfaces are not written as surfaces, so the ids they would
  // have had are free for a later building's.
  m.buildings[1].surfaces[0].id = "rs_l0001_surf_0";
  m.buildings.insert(m.buildings.begin() + 1, block);
  for (const char* out : {"l.gml", "l.city.json", "l.city.jsonl", "l.gpkg", "l.fgb"}) {
    SCOPED_TRACE(out);
    WriteCityModel(m, dir + "/" + out);
    const CityModel r = ReadCityModel(dir + "/" + out);
    testing::ExpectModelsNear(m, r, 1e-3);
    ASSERT_EQ(r.buildings.size(), 4u);
    EXPECT_EQ(r.buildings[1].lod, 1);
    EXPECT_EQ(r.buildings[2].lod, 2);
    EXPECT_EQ(r.buildings[1].string_attributes.at("roofsweep_validity"), "valid");
  }
  std::string log;
  const int rc = testing::XmllintCityGml(dir + "/l.gml", &log);
  if (rc >= 0) {
    EXPECT_EQ(rc, 0) << log;
  }
  const std::string gml = testing::ReadText(dir + "/l.gml");
  EXPECT_NE(gml.find("bldg:lod1Solid"), std::string::npos);
  const int cj = testing::ValidateCityJson(testing::ReadText(dir + "/l.city.json"), false, &log);
  if (cj >= 0) {
    EXPECT_EQ(cj, 0) << log;
  }
}

TEST(CityModelIo, RealBerlinTileConvertsToEveryFormat) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(path, "data/citygml/berlin-lod2/3910_5819.gml");
  const CityModel m = ReadCityModel(path);
  const std::string dir = testing::TempDir("io");
  for (const char* out : {"b.gml", "b.city.json", "b.city.jsonl", "b.gpkg"}) {
    SCOPED_TRACE(out);
    WriteCityModel(m, dir + "/" + out);
    const CityModel r = ReadCityModel(dir + "/" + out);
    EXPECT_EQ(r.crs, "EPSG:25833");
    testing::ExpectModelsNear(m, r, 1e-3, /*surface_ids=*/true);
  }
  std::string log;
  const int rc = testing::XmllintCityGml(dir + "/b.gml", &log);
  if (rc >= 0) {  // the source fails (no uom); ours must not
    EXPECT_EQ(rc, 0) << log;
  }
}

TEST(CityModelIo, ExistingOutputIsNeverReplacedSilently) {
  const std::string dir = testing::TempDir("io");
  for (const char* out : {"x.gml", "x.city.json", "x.city.jsonl", "x.gpkg"}) {
    SCOPED_TRACE(out);
    const std::string path = dir + "/" + out;
    testing::WriteText(path, "keep me");
    try {
      WriteCityModel(testing::MakeCity(2), path);
      ADD_FAILURE() << "replaced";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(path + ": output exists"), std::string::npos)
          << e.what();
    }
    EXPECT_EQ(testing::ReadText(path), "keep me");
    try {
      WriteCityModel(testing::MakeCity(2), dir + "/missing/" + out);
      ADD_FAILURE() << "wrote into a missing folder";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
    }
  }
  WriteOptions up;
  up.update = true;
  EXPECT_THROW(WriteCityModel(testing::MakeCity(1), dir + "/y.gml", up), Error);
  EXPECT_EQ(testing::CountTempFiles(dir), 0);
}

TEST(CityModelIo, CancelledWriteLeavesNothing) {
  struct CancelAtHalf : Progress {
    bool Update(double f, const std::string&) override { return f < 0.5; }
  } cancel;
  const std::string dir = testing::TempDir("io");
  for (const char* out : {"c.gml", "c.city.json", "c.city.jsonl", "c.gpkg", "c.fgb"}) {
    EXPECT_THROW(WriteCityModel(testing::MakeCity(200), dir + "/" + out, {}, &cancel), Cancelled);
    EXPECT_FALSE(std::filesystem::exists(dir + "/" + out)) << out;
  }
  EXPECT_EQ(testing::CountTempFiles(dir), 0);
}

TEST(CityModelIo, UnknownContentIsSniffed) {
  const std::string dir = testing::TempDir("io");
  WriteCityModel(testing::MakeCity(2), dir + "/m.gml");
  std::filesystem::copy_file(dir + "/m.gml", dir + "/m.data");
  EXPECT_EQ(ReadCityModel(dir + "/m.data").buildings.size(), 2u);
  EXPECT_THROW(ReadCityModel(dir + "/none.gml"), Error);
}

}  // namespace
}  // namespace roofsweep
