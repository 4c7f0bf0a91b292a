#include "io/citymodel/footprint_reader.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>

#include "algorithms/core/error.h"
#include "io/citymodel/ogr_citymodel.h"
#include "io/citymodel/test_util.h"
#include "io/core/crs_transform.h"
#include "io/core/gdal_util.h"
#include "tests/support/shared_data.h"

namespace roofsweep {
namespace {

namespace fs = std::filesystem;

struct TestFeature {
  TestFeature(std::string w, std::map<std::string, std::string> f)
      : wkt(std::move(w)), fields(std::move(f)) {}
  explicit TestFeature(std::shared_ptr<OGRGeometry> g) : geometry(std::move(g)) {}
  std::string wkt;  // or `geometry`
  std::map<std::string, std::string> fields;
  std::shared_ptr<OGRGeometry> geometry;
};

// Adds layer `name` to the GeoPackage at `path` (created when missing):
// string fields `fields`, CRS `crs` (empty: none).
void AddGpkgLayer(const std::string& path, const std::string& name, const std::string& crs,
                  OGRwkbGeometryType type, const std::vector<std::string>& fields,
                  const std::vector<TestFeature>& features) {
  GDALAllRegister();
  GDALDataset* ds = nullptr;
  if (fs::exists(path)) {
    ds =
        GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE, nullptr, nullptr, nullptr);
  } else {
    GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GPKG");
    ASSERT_NE(drv, nullptr);
    ds = drv->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
  }
  ASSERT_NE(ds, nullptr) << path;
  std::unique_ptr<OGRSpatialReference> srs;
  if (!crs.empty()) {
    srs = std::make_unique<OGRSpatialReference>();
    ASSERT_EQ(srs->SetFromUserInput(crs.c_str()), OGRERR_NONE);
    srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  }
  OGRLayer* layer = ds->CreateLayer(name.c_str(), srs.get(), type, nullptr);
  ASSERT_NE(layer, nullptr);
  for (const std::string& f : fields) {
    OGRFieldDefn defn(f.c_str(), OFTString);
    ASSERT_EQ(layer->CreateField(&defn), OGRERR_NONE);
  }
  for (const TestFeature& tf : features) {
    OGRFeature f(layer->GetLayerDefn());
    for (const auto& [k, v] : tf.fields) f.SetField(k.c_str(), v.c_str());
    if (tf.geometry) {
      f.SetGeometry(tf.geometry.get());
    } else if (!tf.wkt.empty()) {
      OGRGeometry* g = nullptr;
      ASSERT_EQ(OGRGeometryFactory::createFromWkt(tf.wkt.c_str(), nullptr, &g), OGRERR_NONE)
          << tf.wkt;
      f.SetGeometryDirectly(g);
    }
    ASSERT_EQ(layer->CreateFeature(&f), OGRERR_NONE);
  }
  GDALClose(ds);
}

const LocalFrame& NoCrs() {
  static const LocalFrame frame("", Eigen::Vector3d::Zero());
  return frame;
}

std::vector<Footprint> Read(const std::string& path, const FootprintReadOptions& o = {},
                            std::vector<std::string>* messages = nullptr,
                            const LocalFrame& frame = NoCrs()) {
  std::vector<std::string> ignored;
  return ReadFootprints(path, frame, o, messages ? messages : &ignored);
}

// what() of the Error ReadFootprints throws, or "" when it does not.
std::string ErrorOf(const std::string& path, const FootprintReadOptions& o = {}) {
  try {
    Read(path, o);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

bool AnyContains(const std::vector<std::string>& messages, const std::string& text) {
  for (const std::string& m : messages)
    if (m.find(text) != std::string::npos) return true;
  return false;
}

TEST(FootprintReader, ClockwiseRingBecomesCounterClockwiseWithoutClosingVertex) {
  const std::string path = testing::TempDir("fp") + "/fp.gpkg";
  // Clockwise, with a repeated vertex.
  AddGpkgLayer(path, "footprints", "", wkbPolygon, {"id"},
               {{"POLYGON ((0 0,0 10,0 10,10 10,10 0,0 0))", {{"id", "a"}}}});
  std::vector<std::string> messages;
  const auto fps = Read(path, {}, &messages);
  ASSERT_EQ(fps.size(), 1u);
  EXPECT_EQ(fps[0].id, "a");
  EXPECT_EQ(fps[0].holes, 0);
  const Ring2& r = fps[0].outline;
  ASSERT_EQ(r.size(), 4u);
  EXPECT_NEAR(SignedArea(r), 100.0, 1e-9);
  // The first vertex stays first.
  const Ring2 want = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  for (size_t i = 0; i < 4; ++i) EXPECT_TRUE(r[i].isApprox(want[i], 1e-12)) << i;
  // No block CRS: nothing assumed, nothing said.
  EXPECT_TRUE(messages.empty()) << messages.front();
}

TEST(FootprintReader, MultiPolygonPartsShareTheId) {
  const std::string path = testing::TempDir("fp") + "/fp.gpkg";
  AddGpkgLayer(path, "footprints", "", wkbMultiPolygon, {"id"},
               {{"MULTIPOLYGON (((0 0,10 0,10 10,0 10,0 0)),((20 0,30 0,30 5,20 5,20 0)))",
                 {{"id", "house"}}},
                {"MULTIPOLYGON (((40 0,50 0,50 10,40 10,40 0)))", {{"id", "shed"}}}});
  const auto fps = Read(path);
  ASSERT_EQ(fps.size(), 3u);
  EXPECT_EQ(fps[0].id, "house");
  EXPECT_EQ(fps[1].id, "house");
  EXPECT_EQ(fps[2].id, "shed");
  EXPECT_NEAR(SignedArea(fps[0].outline), 100.0, 1e-9);
  EXPECT_NEAR(SignedArea(fps[1].outline), 50.0, 1e-9);
}

TEST(FootprintReader, IdFieldIsExplicitElseAKnownNameElseTheFid) {
  const std::string dir = testing::TempDir("fp");
  const std::string named = dir + "/named.gpkg";
  AddGpkgLayer(named, "l", "", wkbPolygon, {"name", "ID", "gml_id"},
               {{"POLYGON ((0 0,1 0,1 1,0 1,0 0))",
                 {{"name", "Rathaus"}, {"ID", "B-17"}, {"gml_id", "g1"}}}});
  {
    const auto fps = Read(named);  // "id" comes first, matched case-insensitively
    ASSERT_EQ(fps.size(), 1u);
    EXPECT_EQ(fps[0].id, "B-17");
  }
  {
    FootprintReadOptions o;
    o.id_field = "name";
    const auto fps = Read(named, o);
    ASSERT_EQ(fps.size(), 1u);
    EXPECT_EQ(fps[0].id, "Rathaus");
  }
  {
    FootprintReadOptions o;
    o.id_field = "fid";  // the GPKG's FID column, not a field
    const auto fps = Read(named, o);
    ASSERT_EQ(fps.size(), 1u);
    EXPECT_EQ(fps[0].id, "1");
  }
  const std::string gml_id = dir + "/gml_id.gpkg";
  AddGpkgLayer(gml_id, "l", "", wkbPolygon, {"name", "gml_id"},
               {{"POLYGON ((0 0,1 0,1 1,0 1,0 0))", {{"name", "x"}, {"gml_id", "DEBY_1"}}}});
  ASSERT_EQ(Read(gml_id).size(), 1u);
  EXPECT_EQ(Read(gml_id)[0].id, "DEBY_1");

  const std::string anonymous = dir + "/anonymous.gpkg";
  AddGpkgLayer(anonymous, "l", "", wkbPolygon, {"name"},
               {{"POLYGON ((0 0,1 0,1 1,0 1,0 0))", {{"name", "a"}}},
                {"POLYGON ((2 0,3 0,3 1,2 1,2 0))", {{"name", "b"}}}});
  const auto fps = Read(anonymous);
  ASSERT_EQ(fps.size(), 2u);
  EXPECT_EQ(fps[0].id, "1");
  EXPECT_EQ(fps[1].id, "2");

  FootprintReadOptions o;
  o.id_field = "objectid";
  const std::string e = ErrorOf(anonymous, o);
  EXPECT_NE(e.find(anonymous), std::string::npos) << e;
  EXPECT_NE(e.find("no field 'objectid' (fields: name)"), std::string::npos) << e;
}

TEST(FootprintReader, LayerInAnotherCrsIsTransformedIntoTheLocalFrame) {
  const std::string dir = testing::TempDir("fp");
  const std::string path = dir + "/wgs84.gpkg";
  const CrsTransform to_utm("EPSG:4326", "EPSG:25833");
  const double h = 40.0;
  const Eigen::Vector3d origin = to_utm.Forward({13.40, 52.52, h});
  const LocalFrame frame("EPSG:25833", origin);
  // ~70 m x 70 m north-east of the origin, counter-clockwise in lon/lat.
  const std::vector<Eigen::Vector2d> lonlat = {
      {13.4001, 52.5201}, {13.4011, 52.5201}, {13.4011, 52.5207}, {13.4001, 52.5207}};
  std::string wkt = "POLYGON ((";
  for (size_t i = 0; i <= lonlat.size(); ++i) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%.10f %.10f", i ? "," : "", lonlat[i % 4].x(),
                  lonlat[i % 4].y());
    wkt += buf;
  }
  wkt += "))";
  AddGpkgLayer(path, "buildings", "EPSG:4326", wkbPolygon, {"id"}, {{wkt, {{"id", "b1"}}}});

  FootprintReadOptions o;
  o.block_crs = "EPSG:25833";
  std::vector<std::string> messages;
  const auto fps = Read(path, o, &messages, frame);
  EXPECT_TRUE(messages.empty()) << messages.front();
  ASSERT_EQ(fps.size(), 1u);
  ASSERT_EQ(fps[0].outline.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    const Eigen::Vector3d utm = to_utm.Forward({lonlat[i].x(), lonlat[i].y(), h});
    const Eigen::Vector2d want = frame.ToLocal({utm.x(), utm.y(), h}).head<2>();
    EXPECT_LT((fps[0].outline[i] - want).norm(), 0.01) << i;
  }
  EXPECT_GT(fps[0].outline[0].x(), 0.0);
  EXPECT_GT(fps[0].outline[0].y(), 0.0);
  EXPECT_NEAR(SignedArea(fps[0].outline), 68 * 67, 200);  // about 4500 m²

  // The same footprint in the block CRS itself: no transformation.
  const std::string utm_path = dir + "/utm.gpkg";
  std::string utm_wkt = "POLYGON ((";
  for (size_t i = 0; i <= 4; ++i) {
    const Eigen::Vector3d u = to_utm.Forward({lonlat[i % 4].x(), lonlat[i % 4].y(), h});
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s%.6f %.6f", i ? "," : "", u.x(), u.y());
    utm_wkt += buf;
  }
  utm_wkt += "))";
  AddGpkgLayer(utm_path, "buildings", "EPSG:25833", wkbPolygon, {"id"},
               {{utm_wkt, {{"id", "b1"}}}});
  const auto same = Read(utm_path, o, &messages, frame);
  ASSERT_EQ(same.size(), 1u);
  for (size_t i = 0; i < 4; ++i)
    EXPECT_LT((same[0].outline[i] - fps[0].outline[i]).norm(), 0.01) << i;
}

// GML 3 with an EPSG:4326 URN stores latitude first. GDAL's GML driver
// swaps to longitude first by default; told not to, it says so in the
// layer's data axis mapping instead. Either way the footprint is the same.
TEST(FootprintReader, LatitudeFirstGmlIsReadEastFirst) {
  const std::string dir = testing::TempDir("fp");
  const std::string gml = dir + "/latlon.gml";
  testing::WriteText(gml, R"(<?xml version="1.0" encoding="utf-8" ?>
<ogr:FeatureCollection xmlns:ogr="http://ogr.maptools.org/" xmlns:gml="http://www.opengis.net/gml">
  <ogr:featureMember>
    <ogr:a gml:id="a.0">
      <ogr:geometryProperty><gml:Polygon srsName="urn:ogc:def:crs:EPSG::4326"><gml:exterior>
        <gml:LinearRing><gml:posList>52.5201 13.4001 52.5201 13.4011 52.5207 13.4011 52.5207
          13.4001 52.5201 13.4001</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon>
      </ogr:geometryProperty>
      <ogr:id>b1</ogr:id>
    </ogr:a>
  </ogr:featureMember>
</ogr:FeatureCollection>
)");
  const CrsTransform to_utm("EPSG:4326", "EPSG:25833");
  const Eigen::Vector3d origin = to_utm.Forward({13.40, 52.52, 40});
  const LocalFrame frame("EPSG:25833", origin);
  FootprintReadOptions o;
  o.block_crs = "EPSG:25833";
  const Eigen::Vector3d first = to_utm.Forward({13.4001, 52.5201, 40});
  const Eigen::Vector2d want = frame.ToLocal({first.x(), first.y(), 40}).head<2>();
  for (const char* invert : {"YES", "NO"}) {
    SCOPED_TRACE(invert);
    gdal::ScopedThreadConfig config("GML_INVERT_AXIS_ORDER_IF_LAT_LONG", invert);
    fs::remove(dir + "/latlon.gfs");
    const auto fps = Read(gml, o, nullptr, frame);
    ASSERT_EQ(fps.size(), 1u);
    EXPECT_EQ(fps[0].id, "b1");
    EXPECT_LT((fps[0].outline[0] - want).norm(), 0.01);
    EXPECT_NEAR(SignedArea(fps[0].outline), 67.9 * 66.8, 20);
  }
}

// What `roofsweep simulate` writes: ground surfaces (clockwise seen from
// above, outward normal down) as MultiPolygonZ in the block CRS promoted to
// 3D. The 3D CRS is the block CRS: nothing to transform, nothing to say.
TEST(FootprintReader, ReadsGroundSurfacesWrittenByWriteFeatureLayer) {
  const std::string path = testing::TempDir("fp") + "/footprints.gpkg";
  const Eigen::Vector3d origin(691000, 5335000, 520);
  const Ring2 ccw = {{690990, 5334990}, {691010, 5334990}, {691010, 5335005}, {690990, 5335005}};
  LayerFeature f;
  f.strings["id"] = "BLDG_000001";
  Polygon3 ground;
  for (auto it = ccw.rbegin(); it != ccw.rend(); ++it)
    ground.exterior.emplace_back(it->x(), it->y(), 521.5);
  f.polygons.push_back(ground);
  FeatureLayerOptions fo;
  fo.crs = "EPSG:25832";
  WriteFeatureLayer(path, "footprints", LayerGeometry::kMultiPolygonZ, {f}, fo);

  const LocalFrame frame("EPSG:25832", origin);
  FootprintReadOptions o;
  o.block_crs = "EPSG:25832";
  std::vector<std::string> messages;
  const auto fps = Read(path, o, &messages, frame);
  EXPECT_TRUE(messages.empty()) << messages.front();
  ASSERT_EQ(fps.size(), 1u);
  EXPECT_EQ(fps[0].id, "BLDG_000001");
  ASSERT_EQ(fps[0].outline.size(), 4u);
  EXPECT_NEAR(SignedArea(fps[0].outline), 20 * 15, 0.1);  // grid scale 1.00005
  // The first vertex written (the last of `ccw`) stays first.
  const Eigen::Vector2d want = frame.ToLocal({690990, 5335005, origin.z()}).head<2>();
  EXPECT_LT((fps[0].outline[0] - want).norm(), 1e-6);
}

TEST(FootprintReader, LayerWithoutCrsIsReadAsBlockCoordinatesAndSaysSo) {
  const std::string path = testing::TempDir("fp") + "/nocrs.gpkg";
  const Eigen::Vector3d origin(391800, 5819000, 40);
  AddGpkgLayer(path, "footprints", "", wkbPolygon, {},
               {{"POLYGON ((391810 5819010,391820 5819010,391820 5819020,391810 5819020,"
                 "391810 5819010))",
                 {}}});
  const LocalFrame frame("EPSG:25833", origin);
  FootprintReadOptions o;
  o.block_crs = "EPSG:25833";
  std::vector<std::string> messages;
  const auto fps = Read(path, o, &messages, frame);
  ASSERT_EQ(fps.size(), 1u);
  const Eigen::Vector2d want = frame.ToLocal({391810, 5819010, 40}).head<2>();
  EXPECT_LT((fps[0].outline[0] - want).norm(), 1e-6);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0], path + ": layer 'footprints' has no CRS; read as block coordinates");
}

TEST(FootprintReader, ErrorsNameTheFile) {
  const std::string dir = testing::TempDir("fp");
  const std::string missing = dir + "/missing.gpkg";
  EXPECT_EQ(ErrorOf(missing), missing + ": no such file");

  const std::string text = dir + "/text.gpkg";
  testing::WriteText(text, "not a geopackage\n");
  std::string e = ErrorOf(text);
  EXPECT_EQ(e.rfind(text + ": cannot open as a vector dataset", 0), 0u) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;

  const std::string path = dir + "/two.gpkg";
  AddGpkgLayer(path, "points", "", wkbPoint, {}, {{"POINT (1 2)", {}}});
  AddGpkgLayer(path, "houses", "", wkbPolygon, {}, {{"POLYGON ((0 0,1 0,1 1,0 0))", {}}});
  FootprintReadOptions o;
  o.layer = "foo";
  EXPECT_EQ(ErrorOf(path, o), path + ": no layer 'foo' (layers: points, houses)");
  o.layer = "points";
  EXPECT_EQ(ErrorOf(path, o), path + ": layer 'points' holds Point geometries, not polygons");
  // Without a layer name, the first polygon layer is taken.
  EXPECT_EQ(Read(path).size(), 1u);

  const std::string only_points = dir + "/points.gpkg";
  AddGpkgLayer(only_points, "points", "", wkbPoint, {}, {{"POINT (1 2)", {}}});
  EXPECT_EQ(ErrorOf(only_points),
            only_points + ": no layer with polygon geometries (layers: points)");
}

TEST(FootprintReader, NanCoordinateIsAnError) {
  const std::string path = testing::TempDir("fp") + "/nan.gpkg";
  auto ring = std::make_unique<OGRLinearRing>();
  ring->addPoint(0, 0);
  ring->addPoint(10, 0);
  ring->addPoint(std::numeric_limits<double>::quiet_NaN(), 10);
  ring->addPoint(0, 10);
  ring->addPoint(0, 0);
  auto poly = std::make_shared<OGRPolygon>();
  poly->addRingDirectly(ring.release());
  const TestFeature good("POLYGON ((20 0,30 0,30 10,20 0))", {});
  const TestFeature bad(poly);
  AddGpkgLayer(path, "footprints", "", wkbPolygon, {}, {good, bad});
  EXPECT_EQ(ErrorOf(path), path + ": feature 2: coordinate is not finite");
}

TEST(FootprintReader, DegenerateAndSelfCrossingPolygonsAreSkippedWithAMessage) {
  const std::string path = testing::TempDir("fp") + "/bad.gpkg";
  AddGpkgLayer(path, "footprints", "", wkbPolygon, {"id"},
               {{"POLYGON ((0 0,10 10,10 0,0 10,0 0))", {{"id", "bowtie"}}},
                {"POLYGON ((0 0,10 0,10 0,0 0))", {{"id", "two"}}},
                {"POLYGON ((0 0,5 0,10 0,0 0))", {{"id", "flat"}}},
                {"POLYGON ((0 0,10 0,10 10,5 0,0 10,0 0))", {{"id", "touching"}}},
                {"POLYGON ((0 0,10 0,10 10,10 5,0 0))", {{"id", "spike"}}},
                {"POLYGON ((0 0,10 0,10 10,0 10,0 0))", {{"id", "good"}}}});
  std::vector<std::string> messages;
  const auto fps = Read(path, {}, &messages);
  ASSERT_EQ(fps.size(), 1u);
  EXPECT_EQ(fps[0].id, "good");
  ASSERT_EQ(messages.size(), 5u);
  EXPECT_EQ(messages[0].rfind(path + ": feature 1 skipped: exterior ring crosses itself", 0), 0u)
      << messages[0];
  EXPECT_EQ(messages[1], path + ": feature 2 skipped: fewer than 3 distinct vertices");
  EXPECT_EQ(messages[2], path + ": feature 3 skipped: zero area");
  EXPECT_EQ(messages[3].rfind(path + ": feature 4 skipped: exterior ring crosses itself", 0), 0u)
      << messages[3];
  EXPECT_EQ(messages[4],
            path + ": feature 5 skipped: exterior ring crosses itself (edges 1 and 3)");
}

TEST(FootprintReader, ExtentKeepsFootprintsWhoseBoxMeetsIt) {
  const std::string path = testing::TempDir("fp") + "/extent.gpkg";
  AddGpkgLayer(path, "footprints", "", wkbPolygon, {"id"},
               {{"POLYGON ((0 0,10 0,10 10,0 10,0 0))", {{"id", "west"}}},
                {"POLYGON ((100 0,110 0,110 10,100 10,100 0))", {{"id", "east"}}},
                {"POLYGON ((40 0,50 0,50 10,40 10,40 0))", {{"id", "touching"}}}});
  FootprintReadOptions o;
  o.extent = Eigen::Vector4d(50, -5, 200, 5);
  const auto fps = Read(path, o);
  ASSERT_EQ(fps.size(), 2u);
  EXPECT_EQ(fps[0].id, "east");
  EXPECT_EQ(fps[1].id, "touching");
}

TEST(FootprintReader, HolesAreCounted) {
  const std::string path = testing::TempDir("fp") + "/holes.gpkg";
  AddGpkgLayer(path, "footprints", "", wkbPolygon, {},
               {{"POLYGON ((0 0,30 0,30 10,0 10,0 0),(2 2,2 8,8 8,8 2,2 2),"
                 "(12 2,12 8,18 8,18 2,12 2))",
                 {}}});
  const auto fps = Read(path);
  ASSERT_EQ(fps.size(), 1u);
  EXPECT_EQ(fps[0].holes, 2);
  EXPECT_NEAR(SignedArea(fps[0].outline), 300.0, 1e-9);
}

// GeoJSON with mixed geometry types: the layer's type is unknown, the
// polygons are read and the rest named.
TEST(FootprintReader, GeoJsonLayerOfMixedTypesGivesItsPolygons) {
  const std::string path = testing::TempDir("fp") + "/mixed.geojson";
  testing::WriteText(path, R"({"type": "FeatureCollection", "features": [
  {"type": "Feature", "properties": {"id": "p"},
   "geometry": {"type": "Point", "coordinates": [13.4, 52.5]}},
  {"type": "Feature", "properties": {"id": "b"},
   "geometry": {"type": "Polygon", "coordinates":
     [[[13.4, 52.5], [13.4, 52.501], [13.401, 52.501], [13.401, 52.5], [13.4, 52.5]]]}}]}
)");
  // A geographic block CRS: the same CRS, degrees to metres by the frame.
  const LocalFrame frame("EPSG:4326", {13.4, 52.5, 40});
  FootprintReadOptions o;
  o.block_crs = "EPSG:4326";
  std::vector<std::string> messages;
  const auto fps = Read(path, o, &messages, frame);
  ASSERT_EQ(fps.size(), 1u);
  EXPECT_EQ(fps[0].id, "b");
  // 0.001° x 0.001° at 52.5° N: 67.9 m x 111.3 m.
  EXPECT_NEAR(SignedArea(fps[0].outline), 67.9 * 111.3, 20);
  EXPECT_LT(fps[0].outline[0].norm(), 1e-6);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_TRUE(AnyContains(messages, "skipped: Point is not a polygon")) << messages.size();
}

}  // namespace
}  // namespace roofsweep
