#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "algorithms/core/error.h"
#include "io/citymodel/cityjson_reader.h"
#include "io/citymodel/citymodel_io.h"
#include "io/citymodel/procedural_buildings.h"
#include "io/citymodel/test_util.h"
#include "tests/support/shared_data.h"

namespace roofsweep {
namespace {

using testing::ReadText;
using testing::WriteText;

#define EXPECT_CITYJSON_VALID(text, feature)                               \
  do {                                                                     \
    std::string log_;                                                      \
    const int rc_ = testing::ValidateCityJson(text, feature, &log_);       \
    if (rc_ < 0) {                                                         \
      if (testing::SharedRequired()) FAIL() << "CityJSON schemas missing"; \
      GTEST_SKIP() << "shared CityJSON schemas missing -- skipping";       \
    }                                                                      \
    EXPECT_EQ(rc_, 0) << log_;                                             \
  } while (0)

TEST(CityJson, WrittenFileValidatesAgainstSchema) {
  const std::string path = testing::TempDir("cj") + "/city.city.json";
  WriteCityModel(testing::MakeCity(7), path);
  const std::string text = ReadText(path);
  const auto doc = nlohmann::json::parse(text);
  EXPECT_EQ(doc["version"], "2.0");
  EXPECT_EQ(doc["metadata"]["referenceSystem"], "https://www.opengis.net/def/crs/EPSG/0/25832");
  EXPECT_EQ(doc["transform"]["scale"][0], 0.001);
  const auto& g = doc["CityObjects"]["BLDG_000002"]["geometry"][0];
  EXPECT_EQ(g["type"], "Solid");
  EXPECT_EQ(g["lod"], "2");
  // Gable house: ground, 4 walls, 2 roofs; rings without the closing vertex.
  EXPECT_EQ(g["boundaries"][0].size(), 7u);
  EXPECT_EQ(g["boundaries"][0][0][0].size(), 4u);
  EXPECT_EQ(g["semantics"]["surfaces"][0]["type"], "GroundSurface");
  EXPECT_CITYJSON_VALID(text, false);
}

TEST(CityJson, BrokenDocumentFailsValidation) {
  const std::string path = testing::TempDir("cj") + "/city.city.json";
  WriteCityModel(testing::MakeCity(2), path);
  auto doc = nlohmann::json::parse(ReadText(path));
  doc["CityObjects"]["BLDG_000001"]["geometry"][0]["semantics"]["surfaces"][0]["type"] = "Cellar";
  std::string log;
  const int rc = testing::ValidateCityJson(doc.dump(), false, &log);
  if (rc < 0) GTEST_SKIP() << "shared CityJSON schemas missing";
  EXPECT_EQ(rc, 1);
  auto doc2 = nlohmann::json::parse(ReadText(path));
  doc2.erase("transform");  // mandatory in 2.0
  EXPECT_EQ(testing::ValidateCityJson(doc2.dump(), false, &log), 1);
}

TEST(CityJson, RoundTripWithinAMillimetre) {
  const std::string path = testing::TempDir("cj") + "/city.city.json";
  const CityModel m = testing::MakeCity(9);
  WriteCityModel(m, path);
  const CityModel r = ReadCityJson(path);
  EXPECT_EQ(r.crs, "EPSG:25832");
  testing::ExpectModelsNear(m, r, 1e-3);
  EXPECT_EQ(r.buildings[4].string_attributes.at("roofsweep_validity"), "valid");
}

TEST(CityJson, SeqStreamsFeaturesThatValidate) {
  const std::string path = testing::TempDir("cj") + "/city.city.jsonl";
  const CityModel m = testing::MakeCity(5);
  WriteCityModel(m, path);
  std::istringstream in(ReadText(path));
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    const auto doc = nlohmann::json::parse(line);
    if (n == 0) {
      EXPECT_EQ(doc["type"], "CityJSON");
      EXPECT_CITYJSON_VALID(line, false);
    } else {
      EXPECT_EQ(doc["type"], "CityJSONFeature");
      EXPECT_CITYJSON_VALID(line, true);
    }
    ++n;
  }
  EXPECT_EQ(n, 6);
  testing::ExpectModelsNear(m, ReadCityJsonSeq(path), 1e-3);
}

TEST(CityJson, BuildingPartsAreNestedAndMissingSemanticsUseNormals) {
  const std::string path = testing::TempDir("cj") + "/parts.city.json";
  // Two boxes' surfaces split between a Building and its BuildingPart; the
  // part has no semantics.
  const char* text = R"({"type":"CityJSON","version":"2.0",
    "transform":{"scale":[1,1,1],"translate":[0,0,0]},
    "CityObjects":{
      "P1":{"type":"BuildingPart","parents":["B1"],"geometry":[{"type":"MultiSurface","lod":"2",
            "boundaries":[[[0,1,2,3]],[[4,7,6,5]]]}]},
      "B1":{"type":"Building","children":["P1"],"attributes":{"measuredHeight":3.5,"roofType":1000},
            "geometry":[{"type":"MultiSurface","lod":"1","boundaries":[[[0,1,2]]]},
                        {"type":"Solid","lod":"2.2","boundaries":[[[[0,1,5,4]]]],
                         "semantics":{"surfaces":[{"type":"WallSurface","id":"w1"}],"values":[[0]]}}]}},
    "vertices":[[0,0,0],[0,1,0],[1,1,0],[1,0,0],[0,0,1],[0,1,1],[1,1,1],[1,0,1]]})";
  WriteText(path, text);
  const CityModel m = ReadCityJson(path);
  ASSERT_EQ(m.buildings.size(), 1u);
  const Building& b = m.buildings[0];
  EXPECT_EQ(b.id, "B1");
  EXPECT_EQ(b.roof_type, 1000);
  EXPECT_DOUBLE_EQ(b.measured_height, 3.5);
  ASSERT_EQ(b.surfaces.size(), 1u);
  EXPECT_EQ(b.surfaces[0].type, SurfaceType::kWall);
  EXPECT_EQ(b.surfaces[0].id, "w1");
  ASSERT_EQ(b.parts.size(), 1u);
  const Building& p = b.parts[0];
  EXPECT_EQ(p.id, "P1");
  ASSERT_EQ(p.surfaces.size(), 2u);
  EXPECT_EQ(p.surfaces[0].type, SurfaceType::kGround);  // 0,1,2,3 is clockwise from above
  EXPECT_EQ(p.surfaces[1].type, SurfaceType::kRoof);
  CityModel merged = m;
  MergeBuildingParts(&merged);
  ASSERT_EQ(merged.buildings[0].surfaces.size(), 3u);
  EXPECT_EQ(merged.buildings[0].surfaces[2].type, SurfaceType::kRoof);
}

TEST(CityJson, PartOfAMissingBuildingIsAnError) {
  const std::string path = testing::TempDir("cj") + "/orphan.city.json";
  WriteText(path, R"({"type":"CityJSON","version":"2.0",
    "transform":{"scale":[1,1,1],"translate":[0,0,0]},
    "CityObjects":{"P1":{"type":"BuildingPart","parents":["B9"]},
                   "P2":{"type":"BuildingPart","parents":["P3"]},
                   "P3":{"type":"BuildingPart","parents":["P2"]}},
    "vertices":[]})");
  try {
    ReadCityJson(path);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("BuildingPart without a parent Building"),
              std::string::npos)
        << e.what();
  }
}

void ExpectError(const std::string& path, const std::string& needle, bool seq = false) {
  try {
    seq ? ReadCityJsonSeq(path) : ReadCityJson(path);
    ADD_FAILURE() << "no error for " << path;
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(needle), std::string::npos) << msg;
  }
}

TEST(CityJson, BadInputNamesFileAndPointer) {
  const std::string dir = testing::TempDir("cj");
  WriteText(dir + "/trunc.json", R"({"type":"CityJSON","CityObjects":{)");
  ExpectError(dir + "/trunc.json", "JSON syntax error");
  WriteText(dir + "/other.json", R"({"type":"FeatureCollection","features":[]})");
  ExpectError(dir + "/other.json", "not CityJSON");
  WriteText(dir + "/idx.json", R"({"type":"CityJSON","version":"2.0",
    "transform":{"scale":[1,1,1],"translate":[0,0,0]},"vertices":[[0,0,0]],
    "CityObjects":{"B":{"type":"Building","geometry":[{"type":"MultiSurface","lod":"2","boundaries":[[[0,0,7]]]}]}}})");
  ExpectError(dir + "/idx.json",
              "/CityObjects/B/geometry/0/boundaries/0/0/2: vertex index 7 out of range");
  WriteText(dir + "/seq.jsonl",
            "{\"type\":\"CityJSON\",\"version\":\"2.0\",\"transform\":{\"scale\":"
            "[1,1,1],\"translate\":[0,0,0]},\"CityObjects\":{},\"vertices\":[]}\n"
            "{\"type\":\"CityJSONFeature\",\n");
  ExpectError(dir + "/seq.jsonl", "seq.jsonl:2: JSON syntax error", true);
  ExpectError(dir + "/none.json", "no such file");
}

}  // namespace
}  // namespace roofsweep
