#include "io/citymodel/ogr_citymodel.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <filesystem>
#include <memory>

#include "algorithms/core/error.h"
#include "io/citymodel/citymodel_io.h"
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

// The checks `ogrinfo -so` would show: layers, 3D MultiPolygon, CRS.
TEST(OgrCityModel, GpkgHasLayersGeometryTypeCrsAndSpatialIndex) {
  const std::string path = testing::TempDir("ogr") + "/city.gpkg";
  WriteCityModel(testing::MakeCity(6), path);
  auto ds = Open(path);
  ASSERT_TRUE(ds);
  EXPECT_STREQ(ds->GetDriver()->GetDescription(), "GPKG");
  for (const char* name : {"buildings", "roof_surfaces", "wall_surfaces", "ground_surfaces"}) {
    SCOPED_TRACE(name);
    OGRLayer* l = ds->GetLayerByName(name);
    ASSERT_NE(l, nullptr);
    EXPECT_EQ(l->GetGeomType(), wkbMultiPolygon25D);
    EXPECT_STREQ(OGRGeometryTypeToName(l->GetGeomType()), "3D Multi Polygon");
    const OGRSpatialReference* srs = l->GetSpatialRef();
    ASSERT_NE(srs, nullptr);
    EXPECT_EQ(srs->GetAxesCount(), 3);
    OGRSpatialReference want;
    want.importFromEPSG(25832);
    want.PromoteTo3D(nullptr);
    EXPECT_TRUE(srs->IsSame(&want));
    std::string sql = std::string("SELECT HasSpatialIndex('") + name + "', 'geom')";
    OGRLayer* r = ds->ExecuteSQL(sql.c_str(), nullptr, "SQLITE");
    ASSERT_NE(r, nullptr);
    std::unique_ptr<OGRFeature> f(r->GetNextFeature());
    EXPECT_EQ(f->GetFieldAsInteger(0), 1);
    ds->ReleaseResultSet(r);
  }
  OGRLayer* b = ds->GetLayerByName("buildings");
  EXPECT_EQ(b->GetFeatureCount(), 6);
  std::unique_ptr<OGRFeature> f(b->GetNextFeature());
  EXPECT_STREQ(f->GetFieldAsString("id"), "BLDG_000001");
  EXPECT_STREQ(f->GetFieldAsString("roof_type_name"), "flat");
  EXPECT_STREQ(f->GetFieldAsString("roofsweep_validity"), "valid");
  EXPECT_NEAR(f->GetFieldAsDouble("roofsweep_rmse"), 0.05, 1e-12);
  EXPECT_EQ(ds->GetLayerByName("roof_surfaces")->GetFeatureCount(), 2 * (1 + 2 + 4));
}

TEST(OgrCityModel, GpkgRoundTripIsExact) {
  const std::string path = testing::TempDir("ogr") + "/city.gpkg";
  const CityModel m = testing::MakeCity(8);
  WriteCityModel(m, path);
  const CityModel r = ReadOgrCityModel(path);
  EXPECT_EQ(r.crs, "EPSG:25832");
  testing::ExpectModelsNear(m, r, 1e-9);
}

TEST(OgrCityModel, SingleLayerFormatsRoundTrip) {
  const std::string dir = testing::TempDir("ogr");
  const CityModel m = testing::MakeCity(4);
  for (const char* name : {"city.fgb", "city.geojson"}) {
    SCOPED_TRACE(name);
    const std::string path = dir + "/" + name;
    WriteCityModel(m, path);
    auto ds = Open(path);
    ASSERT_TRUE(ds);
    ASSERT_EQ(ds->GetLayerCount(), 1);
    EXPECT_EQ(ds->GetLayer(0)->GetGeomType(), wkbMultiPolygon25D);
    ds.reset();
    const CityModel r = ReadCityModel(path);
    EXPECT_EQ(r.crs, "EPSG:25832");
    testing::ExpectModelsNear(m, r, 1e-6);
  }
  EXPECT_EQ(testing::CountTempFiles(dir), 0);
}

TEST(OgrCityModel, RefusesExistingOutputAndMissingFolder) {
  const std::string dir = testing::TempDir("ogr");
  const std::string path = dir + "/city.gpkg";
  WriteCityModel(testing::MakeCity(2), path);
  const auto size = fs::file_size(path);
  try {
    WriteCityModel(testing::MakeCity(5), path);
    ADD_FAILURE() << "existing output was replaced";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("output exists"), std::string::npos) << e.what();
  }
  EXPECT_EQ(fs::file_size(path), size);
  EXPECT_EQ(ReadOgrCityModel(path).buildings.size(), 2u);
  EXPECT_THROW(WriteCityModel(testing::MakeCity(1), dir + "/nope/city.gpkg"), Error);
  WriteOptions ow;
  ow.overwrite = true;
  WriteCityModel(testing::MakeCity(5), path, ow);
  EXPECT_EQ(ReadOgrCityModel(path).buildings.size(), 5u);
  EXPECT_EQ(testing::CountTempFiles(dir), 0);
}

TEST(OgrCityModel, UpdateKeepsOtherLayersAndExtraLayersCanBeAdded) {
  const std::string dir = testing::TempDir("ogr");
  const std::string path = dir + "/block.gpkg";
  WriteCityModel(testing::MakeCity(3), path);

  LayerFeature line;
  line.lines.push_back(
      {Eigen::Vector3d(500000, 5400000, 110), Eigen::Vector3d(500010, 5400002, 112)});
  line.integers["support"] = 5;
  line.reals["rmse"] = 0.25;
  line.strings["kind"] = "ridge";
  FeatureLayerOptions lo;
  lo.crs = "EPSG:25832";
  EXPECT_THROW(WriteFeatureLayer(path, "lines3d", LayerGeometry::kLineStringZ, {line}, lo), Error);
  lo.update = true;
  WriteFeatureLayer(path, "lines3d", LayerGeometry::kLineStringZ, {line, line}, lo);

  // Replace the city model layers, keep lines3d.
  WriteOptions up;
  up.update = true;
  WriteCityModel(testing::MakeCity(7), path, up);
  auto ds = Open(path);
  ASSERT_TRUE(ds);
  OGRLayer* l = ds->GetLayerByName("lines3d");
  ASSERT_NE(l, nullptr);
  EXPECT_EQ(l->GetGeomType(), wkbLineString25D);
  EXPECT_EQ(l->GetFeatureCount(), 2);
  std::unique_ptr<OGRFeature> f(l->GetNextFeature());
  EXPECT_STREQ(f->GetFieldAsString("kind"), "ridge");
  EXPECT_EQ(f->GetFieldAsInteger64("support"), 5);
  EXPECT_NEAR(f->GetGeometryRef()->toLineString()->getZ(1), 112, 1e-9);
  EXPECT_EQ(ds->GetLayerByName("buildings")->GetFeatureCount(), 7);
  ds.reset();
  EXPECT_EQ(ReadOgrCityModel(path).buildings.size(), 7u);
  EXPECT_EQ(testing::CountTempFiles(dir), 0);
}

TEST(OgrCityModel, SeveralTwoDimensionalLayersInOneWrite) {
  const std::string dir = testing::TempDir("ogr");
  const std::string path = dir + "/lines.gpkg";
  LayerFeature seg;
  seg.lines.push_back({Eigen::Vector3d(1.5, 2.5, 0), Eigen::Vector3d(40.25, 2.5, 0)});
  seg.reals["length_px"] = 38.75;
  std::vector<FeatureLayerData> layers(2);
  layers[0].name = "lines_001";
  layers[0].geometry = LayerGeometry::kLineString;
  layers[0].description = "image pixels";
  layers[0].features = {seg, seg, seg};
  layers[1].name = "lines_002";
  layers[1].geometry = LayerGeometry::kLineString;  // empty layer
  WriteFeatureLayers(path, layers, FeatureLayerOptions{});
  auto ds = Open(path);
  ASSERT_TRUE(ds);
  OGRLayer* l = ds->GetLayerByName("lines_001");
  ASSERT_NE(l, nullptr);
  EXPECT_EQ(l->GetGeomType(), wkbLineString);
  EXPECT_EQ(l->GetFeatureCount(), 3);
  // No CRS: GPKG's undefined Cartesian system (srs_id -1), not lat/lon.
  if (const OGRSpatialReference* srs = l->GetSpatialRef()) {
    EXPECT_FALSE(srs->IsGeographic());
    EXPECT_FALSE(srs->IsProjected());
  }
  ASSERT_NE(l->GetMetadataItem("DESCRIPTION"), nullptr);
  EXPECT_STREQ(l->GetMetadataItem("DESCRIPTION"), "image pixels");
  std::unique_ptr<OGRFeature> f(l->GetNextFeature());
  EXPECT_DOUBLE_EQ(f->GetGeometryRef()->toLineString()->getX(1), 40.25);
  ASSERT_NE(ds->GetLayerByName("lines_002"), nullptr);
  EXPECT_EQ(ds->GetLayerByName("lines_002")->GetFeatureCount(), 0);
  ds.reset();
  // Refused without overwrite; single-layer formats refuse several layers.
  EXPECT_THROW(WriteFeatureLayers(path, layers, FeatureLayerOptions{}), Error);
  EXPECT_THROW(WriteFeatureLayers(dir + "/lines.fgb", layers, FeatureLayerOptions{}), Error);
  EXPECT_EQ(testing::CountTempFiles(dir), 0);
}

TEST(OgrCityModel, NotACityModelDatasetIsAClearError) {
  const std::string dir = testing::TempDir("ogr");
  FeatureLayerOptions lo;
  WriteFeatureLayer(dir + "/other.gpkg", "half_planes", LayerGeometry::kMultiPolygonZ,
                    {LayerFeature{}}, lo);
  try {
    ReadOgrCityModel(dir + "/other.gpkg");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("found: half_planes"), std::string::npos) << e.what();
  }
  testing::WriteText(dir + "/junk.gpkg", "not a database");
  EXPECT_THROW(ReadOgrCityModel(dir + "/junk.gpkg"), Error);
}

}  // namespace
}  // namespace roofsweep
