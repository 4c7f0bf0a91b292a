// -co / -dsco / -lco: creation options reach the writers, and wrong ones
// are refused before anything is written.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <filesystem>
#include <memory>

#include "algorithms/core/error.h"
#include "io/citymodel/citymodel_io.h"
#include "io/citymodel/ogr_citymodel.h"
#include "io/citymodel/procedural_buildings.h"
#include "io/citymodel/test_util.h"
#include "tests/support/shared_data.h"

namespace roofsweep {
namespace {

namespace fs = std::filesystem;

std::unique_ptr<GDALDataset> Open(const std::string& path) {
  GDALAllRegister();
  return std::unique_ptr<GDALDataset>(GDALDataset::Open(
      path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
}

long long SqlCount(GDALDataset& ds, const std::string& sql) {
  OGRLayer* l = ds.ExecuteSQL(sql.c_str(), nullptr, nullptr);
  if (!l) return -1;
  OGRFeature* f = l->GetNextFeature();
  const long long n = f ? f->GetFieldAsInteger64(0) : -1;
  OGRFeature::DestroyFeature(f);
  ds.ReleaseResultSet(l);
  return n;
}

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::vector<LayerFeature> TwoLines() {
  std::vector<LayerFeature> out(2);
  out[0].lines = {{{500000, 5400000, 100}, {500010, 5400000, 101}}};
  out[1].lines = {{{500000, 5400005, 100}, {500000, 5400015, 102}}};
  out[1].reals["length_m"] = 10.2;
  return out;
}

TEST(CreationOptions, GpkgLayerAndDatasetOptionsReachGdal) {
  const std::string path = testing::TempDir("co") + "/lines.gpkg";
  FeatureLayerOptions o;
  o.crs = "EPSG:25832";
  o.layer_options = {"FID=myfid", "SPATIAL_INDEX=NO", "GEOMETRY_NAME=shape"};
  o.dataset_options = {"VERSION=1.2"};
  WriteFeatureLayer(path, "lines3d", LayerGeometry::kLineStringZ, TwoLines(), o);
  auto ds = Open(path);
  ASSERT_TRUE(ds);
  OGRLayer* l = ds->GetLayerByName("lines3d");
  ASSERT_TRUE(l);
  EXPECT_STREQ(l->GetFIDColumn(), "myfid");
  EXPECT_STREQ(l->GetGeometryColumn(), "shape");
  EXPECT_EQ(l->GetFeatureCount(), 2);
  EXPECT_EQ(SqlCount(*ds, "SELECT COUNT(*) FROM sqlite_master WHERE name LIKE 'rtree_%'"), 0);
  // GeoPackage 1.2 writes user_version 10200 (1.3 would be 10300).
  EXPECT_EQ(SqlCount(*ds, "PRAGMA user_version"), 10200);

  // Without options: roofsweep's defaults (spatial index, geom, fid).
  const std::string plain = testing::TempDir("co") + "/plain.gpkg";
  FeatureLayerOptions d;
  d.crs = "EPSG:25832";
  WriteFeatureLayer(plain, "lines3d", LayerGeometry::kLineStringZ, TwoLines(), d);
  auto pds = Open(plain);
  ASSERT_TRUE(pds);
  EXPECT_STREQ(pds->GetLayerByName("lines3d")->GetGeometryColumn(), "geom");
  EXPECT_GT(SqlCount(*pds, "SELECT COUNT(*) FROM sqlite_master WHERE name LIKE 'rtree_%'"), 0);
}

TEST(CreationOptions, WrongOptionsAreRefusedBeforeWriting) {
  const std::string dir = testing::TempDir("co");
  const std::string path = dir + "/bad.gpkg";
  auto write = [&](std::vector<std::string> lco, std::vector<std::string> dsco) {
    FeatureLayerOptions o;
    o.layer_options = std::move(lco);
    o.dataset_options = std::move(dsco);
    WriteFeatureLayer(path, "lines3d", LayerGeometry::kLineStringZ, TwoLines(), o);
  };
  std::string msg = ErrorOf([&] { write({"NO_SUCH_THING=1"}, {}); });
  EXPECT_NE(msg.find("layer creation option 'NO_SUCH_THING'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("SPATIAL_INDEX"), std::string::npos) << msg;  // lists the known ones
  EXPECT_NE(msg.find("bad.gpkg"), std::string::npos) << msg;
  msg = ErrorOf([&] { write({"SPATIAL_INDEX=MAYBE"}, {}); });
  EXPECT_NE(msg.find("SPATIAL_INDEX expects YES or NO, got 'MAYBE'"), std::string::npos) << msg;
  msg = ErrorOf([&] { write({}, {"VERSION=9.9"}); });
  EXPECT_NE(msg.find("dataset creation option VERSION expects one of"), std::string::npos) << msg;
  msg = ErrorOf([&] { write({"novalue"}, {}); });
  EXPECT_NE(msg.find("not NAME=VALUE"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(testing::CountTempFiles(dir), 0);
}

TEST(CreationOptions, CityModelWritersTakeTheirOwn) {
  const std::string dir = testing::TempDir("co");
  CityModel m = testing::MakeCity(3, 500000, 5400000, 100, "EPSG:25832");
  WriteOptions gpkg;
  gpkg.layer_options = {"GEOMETRY_NAME=shape", "FID=fid"};
  WriteCityModel(m, dir + "/city.gpkg", gpkg);
  auto ds = Open(dir + "/city.gpkg");
  ASSERT_TRUE(ds);
  EXPECT_STREQ(ds->GetLayerByName("roof_surfaces")->GetGeometryColumn(), "shape");
  testing::ExpectModelsNear(m, ReadCityModel(dir + "/city.gpkg"), 1e-6);

  // MakeCity puts vertices at x = ...0.1237: one decimal must cut it.
  const CityModel& shifted = m;
  WriteOptions gml;
  gml.creation_options = {"DECIMALS=1"};
  WriteCityModel(shifted, dir + "/city.gml", gml);
  testing::ExpectModelsNear(shifted, ReadCityModel(dir + "/city.gml"), 0.05 + 1e-9);
  const std::string text = testing::ReadText(dir + "/city.gml");
  EXPECT_EQ(text.find("500000.12"), std::string::npos);  // one decimal
  EXPECT_NE(text.find("500000.1 "), std::string::npos);
  WriteCityModel(shifted, dir + "/default.gml", {});
  EXPECT_NE(testing::ReadText(dir + "/default.gml").find("500000.1237 "), std::string::npos);

  std::string msg = ErrorOf([&] { WriteCityModel(m, dir + "/x.city.json", gml); });
  EXPECT_NE(msg.find("CityJSON has no creation option 'DECIMALS'"), std::string::npos) << msg;
  msg = ErrorOf([&] { WriteCityModel(m, dir + "/x.gml", gpkg); });
  EXPECT_NE(msg.find("-dsco/-lco"), std::string::npos) << msg;
  WriteOptions co_on_gpkg;
  co_on_gpkg.creation_options = {"DECIMALS=1"};
  msg = ErrorOf([&] { WriteCityModel(m, dir + "/x.gpkg", co_on_gpkg); });
  EXPECT_NE(msg.find("-co"), std::string::npos) << msg;
  WriteOptions bad;
  bad.creation_options = {"DECIMALS=many"};
  msg = ErrorOf([&] { WriteCityModel(m, dir + "/x.gml", bad); });
  EXPECT_NE(msg.find("DECIMALS expects 0 to 17"), std::string::npos) << msg;
  for (const char* f : {"x.city.json", "x.gml", "x.gpkg"}) EXPECT_FALSE(fs::exists(dir + "/" + f));
}

}  // namespace
}  // namespace roofsweep
