#include "io/core/block_manifest.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <Eigen/Geometry>
#include <GeographicLib/LocalCartesian.hpp>
#include <GeographicLib/TransverseMercator.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

#include "algorithms/core/error.h"
#include "algorithms/geometry/rotation.h"
#include "io/core/image_io.h"
#include "io/core/local_frame.h"
#include "tests/support/shared_data.h"

namespace fs = std::filesystem;

namespace roofsweep {
namespace {

constexpr double kGrs80A = 6378137.0;
constexpr double kGrs80F = 1 / 298.257222101;

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

void WriteText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::vector<std::string> Listing(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// A small UTM 33 block: 2 strips of 3 nadir-ish images at 1000 m above a
// 100 m ground.
BlockManifest SyntheticBlock(const std::string& dir) {
  BlockManifest m;
  m.crs = "EPSG:25833";
  Camera cam;
  cam.id = "dmc";
  cam.width = 1000;
  cam.height = 800;
  cam.fx = cam.fy = 1200.5;
  cam.cx = 501.25;
  cam.cy = 399.75;
  cam.k1 = -0.0123;
  cam.p2 = 1e-4;
  cam.pixel_size_mm = 0.012;
  m.cameras.push_back(cam);
  for (int s = 0; s < 2; ++s) {
    for (int i = 0; i < 3; ++i) {
      ManifestImage im;
      im.name = "img_" + std::to_string(s) + std::to_string(i);
      im.path = dir + "/images/" + im.name + ".tif";
      im.camera = "dmc";
      im.position =
          Eigen::Vector3d(400000.0 + 600.0 * i + 0.123, 5800000.0 + 700.0 * s, 1100.0 + i);
      im.rotation = OpkToRotation(0.5 * i - 0.3, -0.2 + 0.1 * s, s == 0 ? 0.7 : 180.4);
      m.images.push_back(im);
    }
  }
  m.ground_height = 100.0;
  m.max_building_height = 45.5;
  m.footprints = dir + "/fp.gpkg";
  m.footprints_layer = "buildings";
  m.aoi = Eigen::Vector4d(400100, 5800100, 401100, 5800600);
  m.base_dir = dir;
  return m;
}

void ExpectSameManifest(const BlockManifest& a, const BlockManifest& b) {
  EXPECT_EQ(a.crs, b.crs);
  EXPECT_EQ(a.height_type, b.height_type);
  EXPECT_EQ(a.geoid_undulation, b.geoid_undulation);
  ASSERT_EQ(a.cameras.size(), b.cameras.size());
  for (size_t i = 0; i < a.cameras.size(); ++i) {
    const Camera &x = a.cameras[i], &y = b.cameras[i];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.width, y.width);
    EXPECT_EQ(x.height, y.height);
    for (auto f : {&Camera::fx, &Camera::fy, &Camera::cx, &Camera::cy, &Camera::skew, &Camera::k1,
                   &Camera::k2, &Camera::k3, &Camera::p1, &Camera::p2, &Camera::pixel_size_mm}) {
      EXPECT_EQ(x.*f, y.*f);
    }
  }
  ASSERT_EQ(a.images.size(), b.images.size());
  for (size_t i = 0; i < a.images.size(); ++i) {
    EXPECT_EQ(a.images[i].name, b.images[i].name);
    EXPECT_EQ(fs::path(a.base_dir) / a.images[i].path, fs::path(b.base_dir) / b.images[i].path);
    EXPECT_EQ(a.images[i].camera, b.images[i].camera);
    EXPECT_EQ(a.images[i].position, b.images[i].position);  // exact: shortest round-trip digits
    EXPECT_LT((a.images[i].rotation - b.images[i].rotation).norm(), 1e-11) << i;
  }
  EXPECT_EQ(a.ground_height, b.ground_height);
  EXPECT_EQ(a.max_building_height, b.max_building_height);
  EXPECT_EQ(a.footprints_layer, b.footprints_layer);
  EXPECT_EQ(a.aoi.has_value(), b.aoi.has_value());
  if (a.aoi && b.aoi) {
    EXPECT_EQ(*a.aoi, *b.aoi);
  }
}

TEST(BlockManifest, WriteReadRoundTrip) {
  const std::string dir = testing::TempDir();
  BlockManifest m = SyntheticBlock(dir);
  m.images[4].rotation = OpkToRotation(10, 88.5, -30);  // beyond the OPK limit
  m.images[5].path = "/elsewhere/x.tif";
  const std::string path = dir + "/block.json";
  WriteManifest(m, path, false);
  const BlockManifest back = ReadManifest(path);
  EXPECT_EQ(back.source, path);
  EXPECT_EQ(back.base_dir, dir);
  ExpectSameManifest(m, back);
  EXPECT_EQ(back.images[0].path, "images/img_00.tif");  // relative below the manifest
  EXPECT_EQ(back.images[5].path, "/elsewhere/x.tif");
  EXPECT_EQ(back.footprints, "fp.gpkg");
  const std::string text = ManifestToJson(back, path);
  EXPECT_NE(text.find("\"rotation\": ["), std::string::npos);
  EXPECT_NE(text.find("\"opk\": ["), std::string::npos);
  EXPECT_NE(text.find("\"position\": [400000.123, 5800000.0, 1100.0]"), std::string::npos) << text;
  // Same text again after a second round.
  WriteManifest(back, path, true);
  EXPECT_EQ(ManifestToJson(ReadManifest(path), path), text);
  EXPECT_EQ(Listing(dir), std::vector<std::string>{"block.json"});
}

TEST(BlockManifest, LocalBlockWithoutCrsAndNameFromPath) {
  const std::string dir = testing::TempDir();
  WriteText(dir + "/b.json", R"({
    "roofsweep_block": "1.0",
    "cameras": [{"id": "c", "width": 100, "height": 80, "fx": 90, "fy": 90, "cx": 50, "cy": 40}],
    "images": [{"path": "sub/frame_7.png", "camera": "c", "position": [1, 2, 3], "opk": [0, 0, 0]}]
  })");
  const BlockManifest m = ReadManifest(dir + "/b.json");
  EXPECT_TRUE(m.crs.empty());
  EXPECT_EQ(m.images[0].name, "frame_7");
  EXPECT_EQ(m.height_type, "ellipsoidal");
  EXPECT_EQ(m.max_building_height, 60.0);
  const Block block = ManifestToBlock(m);
  EXPECT_FALSE(block.frame.HasCrs());
  EXPECT_EQ(block.views[0].pose.C, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(block.views[0].pose.R, PatbToCv(Eigen::Matrix3d::Identity()));
  EXPECT_EQ(block.views[0].image_path, dir + "/sub/frame_7.png");
  EXPECT_FALSE(block.ground.Known());
}

const char* kGood = R"({
  "roofsweep_block": "1.0",
  "crs": "EPSG:25833",
  "cameras": [{"id": "c", "width": 100, "height": 80, "fx": 90, "fy": 90, "cx": 50, "cy": 40}],
  "images": [
    {"name": "a", "path": "a.png", "camera": "c", "position": [400000, 5800000, 900], "opk": [0, 0, 0]},
    {"name": "b", "path": "b.png", "camera": "c", "position": [400300, 5800000, 900], "opk": [0, 0, 0]}
  ],
  "ground": {"height": 100}
})";

std::string Edited(const std::string& from, const std::string& to) {
  std::string s = kGood;
  const size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

std::string ReadError(const std::string& dir, const std::string& text) {
  WriteText(dir + "/m.json", text);
  return ErrorOf([&] { ReadManifest(dir + "/m.json"); });
}

TEST(BlockManifest, SchemaErrorsNameTheJsonPointer) {
  const std::string dir = testing::TempDir();
  const std::string file = dir + "/m.json";
  EXPECT_EQ(ReadError(dir, kGood), "");
  std::string msg = ReadError(dir, Edited("\"fy\": 90, ", ""));
  EXPECT_EQ(msg.rfind(file + ": /cameras/0: ", 0), 0u) << msg;
  EXPECT_NE(msg.find("'fy'"), std::string::npos) << msg;

  msg = ReadError(dir, Edited("\"camera\": \"c\", \"position\": [400300",
                              "\"camera\": 3, \"position\": [400300"));
  EXPECT_EQ(msg.rfind(file + ": /images/1/camera: ", 0), 0u) << msg;
  EXPECT_NE(msg.find("found 3"), std::string::npos) << msg;

  msg = ReadError(
      dir, Edited("\"position\": [400000, 5800000, 900]", "\"position\": [400000, 5800000]"));
  EXPECT_EQ(msg.rfind(file + ": /images/0/position: ", 0), 0u) << msg;

  msg = ReadError(
      dir, Edited("\"opk\": [0, 0, 0]}", "\"opk\": [0, 0, 0], \"rotation\": [1,0,0,0,1,0,0,0,1]}"));
  EXPECT_EQ(msg.rfind(file + ": /images/0: ", 0), 0u) << msg;
  msg = ReadError(dir, Edited(", \"opk\": [0, 0, 0]}", "}"));
  EXPECT_EQ(msg.rfind(file + ": /images/0: Missing required property 'opk'", 0), 0u) << msg;
  EXPECT_EQ(ReadError(dir, Edited("\"opk\": [0, 0, 0]}", "\"rotation\": [1,0,0,0,1,0,0,0,1]}")),
            "");

  msg = ReadError(dir, Edited("\"ground\"", "\"grund\""));
  EXPECT_EQ(msg.rfind(file + ": /", 0), 0u) << msg;
  EXPECT_NE(msg.find("grund"), std::string::npos) << msg;

  msg = ReadError(dir, Edited("\"1.0\"", "\"2.0\""));
  EXPECT_EQ(msg.rfind(file + ": /roofsweep_block: ", 0), 0u) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos);
}

TEST(BlockManifest, ZeroFocalLength) {
  const std::string dir = testing::TempDir();
  const std::string msg = ReadError(dir, Edited("\"fx\": 90", "\"fx\": 0"));
  EXPECT_EQ(msg.rfind(dir + "/m.json: /cameras/0/fx: ", 0), 0u) << msg;
  BlockManifest m = SyntheticBlock(dir);
  m.source = "blk.json";
  m.cameras[0].fx = 0;
  const std::string v = ErrorOf([&] { ValidateManifest(m, false); });
  EXPECT_EQ(v.rfind("blk.json: /cameras/0: camera 'dmc': focal length", 0), 0u) << v;
}

TEST(BlockManifest, JsonSyntaxErrorsGiveLineAndColumn) {
  const std::string dir = testing::TempDir();
  const std::string msg =
      ReadError(dir, "{\n  \"roofsweep_block\": \"1.0\",\n  \"cameras\": [,]\n}\n");
  EXPECT_EQ(msg.rfind(dir + "/m.json:3: column 15: invalid JSON", 0), 0u) << msg;
  EXPECT_EQ(msg.find("json.exception"), std::string::npos) << msg;
  EXPECT_NE(ReadError(dir, "").find("m.json:1: column"), std::string::npos);
}

TEST(BlockManifest, DuplicateNamesAndUnknownCamera) {
  const std::string dir = testing::TempDir();
  std::string msg = ReadError(dir, Edited("\"name\": \"b\"", "\"name\": \"a\""));
  EXPECT_EQ(msg, dir + "/m.json: /images/1/name: duplicate image name 'a' (also /images/0/name)");
  msg = ReadError(dir, Edited("\"camera\": \"c\", \"position\": [400300",
                              "\"camera\": \"zz\", \"position\": [400300"));
  EXPECT_EQ(msg, dir + "/m.json: /images/1/camera: unknown camera 'zz'");
}

TEST(BlockManifest, NanIsRefusedAndNothingIsWritten) {
  const std::string dir = testing::TempDir();
  BlockManifest m = SyntheticBlock(dir);
  m.images[2].position.y() = std::numeric_limits<double>::quiet_NaN();
  const std::string msg = ErrorOf([&] { ValidateManifest(m, false); });
  EXPECT_NE(msg.find("/images/2/position: is not finite"), std::string::npos) << msg;
  EXPECT_THROW(WriteManifest(m, dir + "/nan.json", false), Error);
  m = SyntheticBlock(dir);
  m.images[0].rotation(0, 1) = 0.3;
  EXPECT_NE(
      ErrorOf([&] { ValidateManifest(m, false); }).find("/images/0/rotation: is not a rotation"),
      std::string::npos);
  EXPECT_THROW(WriteManifest(SyntheticBlock(dir), dir + "/no/such/folder/b.json", false), Error);
  EXPECT_TRUE(Listing(dir).empty());
}

TEST(BlockManifest, ExistingFileNeedsOverwrite) {
  const std::string dir = testing::TempDir();
  const std::string path = dir + "/b.json";
  WriteText(path, "keep me");
  const std::string msg = ErrorOf([&] { WriteManifest(SyntheticBlock(dir), path, false); });
  EXPECT_NE(msg.find("already exists"), std::string::npos) << msg;
  std::ifstream in(path);
  std::string content;
  std::getline(in, content);
  EXPECT_EQ(content, "keep me");
  WriteManifest(SyntheticBlock(dir), path, true);
  EXPECT_EQ(ReadManifest(path).images.size(), 6u);
  EXPECT_EQ(Listing(dir), std::vector<std::string>{"b.json"});
}

TEST(BlockManifest, ImagesAreCheckedWhenAsked) {
  const std::string dir = testing::TempDir();
  WriteText(dir + "/m.json", kGood);
  const BlockManifest m = ReadManifest(dir + "/m.json");
  std::string msg = ErrorOf([&] { ValidateManifest(m, true); });
  EXPECT_EQ(msg.rfind(dir + "/m.json: /images/0/path: " + dir + "/a.png: no such file", 0), 0u)
      << msg;
  WriteImage(dir + "/a.png", cv::Mat(80, 100, CV_8UC3, cv::Scalar(1, 2, 3)));
  WriteImage(dir + "/b.png", cv::Mat(100, 80, CV_8UC3, cv::Scalar(1, 2, 3)));
  msg = ErrorOf([&] { ValidateManifest(m, true); });
  EXPECT_EQ(
      msg, dir + "/m.json: /images/1: " + dir + "/b.png is 80x100 pixels but camera 'c' is 100x80");
  WriteImage(dir + "/b.png", cv::Mat(80, 100, CV_8UC3, cv::Scalar(1, 2, 3)));
  EXPECT_NO_THROW(ValidateManifest(m, true));
}

Eigen::Matrix3d Rz(double deg) {
  return Eigen::AngleAxisd(deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

TEST(BlockManifest, UtmBlockAgreesWithLocalFrameAndGeographicLib) {
  const std::string dir = testing::TempDir();
  BlockManifest m = SyntheticBlock(dir);
  m.source = dir + "/b.json";
  const Block block = ManifestToBlock(m);
  ASSERT_EQ(block.views.size(), 6u);
  EXPECT_EQ(block.frame.crs, "EPSG:25833");
  EXPECT_EQ(block.max_building_height, 45.5);
  EXPECT_EQ(block.footprints_path, dir + "/fp.gpkg");

  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const ManifestImage& im : m.images) mean += im.position / 6.0;
  const LocalFrame frame("EPSG:25833", Eigen::Vector3d(mean.x(), mean.y(), 100.0));
  ASSERT_TRUE(block.ground.height.has_value());
  EXPECT_NEAR(*block.ground.height, 0.0, 1e-6);

  // Independent model: GeographicLib transverse Mercator + LocalCartesian.
  const GeographicLib::TransverseMercator tm(kGrs80A, kGrs80F, GeographicLib::Constants::UTM_k0());
  double lat0, lon0, g0, k0;
  tm.Reverse(15.0, mean.x() - 500000.0, mean.y(), lat0, lon0, g0, k0);
  EXPECT_NEAR(block.frame.origin_lat, lat0, 1e-9);
  EXPECT_NEAR(block.frame.origin_lon, lon0, 1e-9);
  const GeographicLib::LocalCartesian lc(lat0, lon0, 100.0,
                                         GeographicLib::Geocentric(kGrs80A, kGrs80F));
  for (size_t i = 0; i < m.images.size(); ++i) {
    const View& v = block.views[i];
    const ManifestImage& im = m.images[i];
    EXPECT_EQ(v.name, im.name);
    EXPECT_EQ(v.camera, 0);
    EXPECT_LT((v.pose.C - frame.ToLocal(im.position)).norm(), 1e-9);
    EXPECT_LT((v.pose.R - PatbToCv(frame.GridToLocal(im.position) * im.rotation)).norm(), 1e-12);

    double lat, lon, gamma, k;
    tm.Reverse(15.0, im.position.x() - 500000.0, im.position.y(), lat, lon, gamma, k);
    Eigen::Vector3d c;
    std::vector<double> enu(9);
    lc.Forward(lat, lon, im.position.z(), c.x(), c.y(), c.z(), enu);
    EXPECT_LT((v.pose.C - c).norm(), 1e-4) << i;
    const Eigen::Matrix3d enu_p =
        Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(enu.data());
    const Eigen::Matrix3d want = PatbToCv(enu_p * Rz(-gamma) * im.rotation);
    // 3e-8: the grid axes at flying height lean by ~1e-8 rad more than on
    // the ellipsoid, where GeographicLib's gamma is defined.
    EXPECT_LT((v.pose.R - want).norm(), 3e-8) << i;
  }
  // The area of interest becomes the box around its four corners at ground
  // height, turned by the convergence (about -1.1 degrees here).
  ASSERT_TRUE(block.aoi.has_value());
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const Eigen::Vector2d& c :
       {Eigen::Vector2d(400100, 5800100), Eigen::Vector2d(401100, 5800100),
        Eigen::Vector2d(401100, 5800600), Eigen::Vector2d(400100, 5800600)}) {
    const Eigen::Vector3d l = frame.ToLocal({c.x(), c.y(), 100.0});
    lo = lo.cwiseMin(l.head<2>());
    hi = hi.cwiseMax(l.head<2>());
  }
  EXPECT_LT((*block.aoi - Eigen::Vector4d(lo.x(), lo.y(), hi.x(), hi.y())).norm(), 1e-6);
  EXPECT_GT(hi.y() - lo.y(), 500.0 + 1000.0 * std::sin(1.0 * M_PI / 180));
}

// DTM in ETRS89 geographic degrees whose height is linear in lon/lat, so
// that bilinear resampling must reproduce it exactly.
std::string WriteLinearDtm(const std::string& path, double lon0, double lat0, double* slope_lon,
                           double* slope_lat) {
  *slope_lon = 2000.0;  // m per degree
  *slope_lat = -3000.0;
  GDALAllRegister();
  const int w = 120, h = 100;
  const double step = 0.0005;
  GDALDataset* ds = GetGDALDriverManager()->GetDriverByName("GTiff")->Create(path.c_str(), w, h, 1,
                                                                             GDT_Float32, nullptr);
  double gt[6] = {lon0 - w / 2 * step, step, 0, lat0 + h / 2 * step, 0, -step};
  ds->SetGeoTransform(gt);
  OGRSpatialReference srs;
  srs.importFromEPSG(4258);
  ds->SetSpatialRef(&srs);
  std::vector<float> z(static_cast<size_t>(w * h));
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const double lon = gt[0] + (c + 0.5) * step, lat = gt[3] - (r + 0.5) * step;
      z[static_cast<size_t>(r * w + c)] =
          static_cast<float>(100.0 + *slope_lon * (lon - lon0) + *slope_lat * (lat - lat0));
    }
  }
  ds->GetRasterBand(1)->SetNoDataValue(-9999);
  EXPECT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, w, h, z.data(), w, h, GDT_Float32, 0, 0),
            CE_None);
  GDALClose(ds);
  return path;
}

// A linear DTM in geographic coordinates about the synthetic block's middle
// (UTM 33N 400600, 5800350), written to `path`.
struct LinearDtm {
  std::string path;
  double lat0 = 0, lon0 = 0, slope_lon = 0, slope_lat = 0;
};

LinearDtm LinearDtmUnderSyntheticBlock(const std::string& path) {
  const GeographicLib::TransverseMercator tm(kGrs80A, kGrs80F, GeographicLib::Constants::UTM_k0());
  LinearDtm d;
  double g, k;
  tm.Reverse(15.0, 400600.0 - 500000.0, 5800350.0, d.lat0, d.lon0, g, k);
  d.path = WriteLinearDtm(path, d.lon0, d.lat0, &d.slope_lon, &d.slope_lat);
  return d;
}

TEST(BlockManifest, DtmInAnotherCrsIsResampledIntoTheLocalFrame) {
  const std::string dir = testing::TempDir();
  BlockManifest m = SyntheticBlock(dir);
  m.ground_height.reset();
  const LinearDtm dtm = LinearDtmUnderSyntheticBlock(dir + "/dtm.tif");
  const double lat0 = dtm.lat0, lon0 = dtm.lon0, slope_lon = dtm.slope_lon,
               slope_lat = dtm.slope_lat;
  m.dtm = dtm.path;
  const GeographicLib::TransverseMercator tm(kGrs80A, kGrs80F, GeographicLib::Constants::UTM_k0());
  double g, k;
  const Block block = ManifestToBlock(m);
  ASSERT_TRUE(block.ground.grid.has_value());
  const GroundModel::Grid& grid = *block.ground.grid;
  EXPECT_GT(grid.rows, 10);
  EXPECT_GT(grid.cols, 10);
  EXPECT_NEAR(grid.dx, 0.0005 * M_PI / 180 * kGrs80A * std::cos(lat0 * M_PI / 180), 0.5);

  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const ManifestImage& im : m.images) mean += im.position / 6.0;
  double latm, lonm;
  tm.Reverse(15.0, mean.x() - 500000.0, mean.y(), latm, lonm, g, k);
  const double h_origin = 100.0 + slope_lon * (lonm - lon0) + slope_lat * (latm - lat0);
  EXPECT_NEAR(block.frame.origin_h, h_origin, 1e-3);
  const GeographicLib::LocalCartesian lc(latm, lonm, h_origin,
                                         GeographicLib::Geocentric(kGrs80A, kGrs80F));

  int valid = 0;
  double worst = 0;
  for (int r = 0; r < grid.rows; r += 3) {
    for (int c = 0; c < grid.cols; c += 3) {
      const float z = grid.z[static_cast<size_t>(r * grid.cols + c)];
      if (std::isnan(z)) continue;
      ++valid;
      const double x = grid.x0 + (c + 0.5) * grid.dx, y = grid.y0 - (r + 0.5) * grid.dy;
      double lat, lon, h;
      lc.Reverse(x, y, z, lat, lon, h);
      worst = std::max(worst,
                       std::abs(h - (100.0 + slope_lon * (lon - lon0) + slope_lat * (lat - lat0))));
    }
  }
  EXPECT_GT(valid, 50);
  std::printf("linear DTM: %d cells checked, worst height error %.2e m\n", valid, worst);
  EXPECT_LT(worst, 1e-3);  // lattice interpolation: L² / 4R = 0.2 mm for L = 68 m
  EXPECT_NEAR(block.ground.HeightAt(0, 0), 0.0, 0.01);
}

// The ground in the block CRS itself (for eval): the geographic DTM's
// heights at UTM positions, the constant height, or nothing.
TEST(BlockManifest, GroundInTheCrsFollowsTheDtm) {
  const std::string dir = testing::TempDir();
  BlockManifest m = SyntheticBlock(dir);
  const Eigen::Vector4d box(400400, 5800200, 400800, 5800500);
  ASSERT_TRUE(m.ground_height.has_value());
  const GroundModel constant = ManifestGroundInCrs(m, box);
  EXPECT_FALSE(constant.grid.has_value());
  EXPECT_EQ(constant.HeightAt(400600, 5800350), *m.ground_height);
  m.ground_height.reset();
  EXPECT_FALSE(ManifestGroundInCrs(m, box).Known());
  const LinearDtm dtm = LinearDtmUnderSyntheticBlock(dir + "/dtm.tif");
  m.dtm = dtm.path;
  const GroundModel g = ManifestGroundInCrs(m, box);
  ASSERT_TRUE(g.grid.has_value());
  const GeographicLib::TransverseMercator tm(kGrs80A, kGrs80F, GeographicLib::Constants::UTM_k0());
  for (const Eigen::Vector2d& e :
       {Eigen::Vector2d(400600, 5800350), Eigen::Vector2d(400450, 5800220),
        Eigen::Vector2d(400777, 5800490)}) {
    double lat, lon, gamma, k;
    tm.Reverse(15.0, e.x() - 500000.0, e.y(), lat, lon, gamma, k);
    const double expected =
        100.0 + dtm.slope_lon * (lon - dtm.lon0) + dtm.slope_lat * (lat - dtm.lat0);
    EXPECT_NEAR(g.HeightAt(e.x(), e.y()), expected, 0.01) << e.transpose();
  }
}

TEST(BlockManifest, ASurfaceModelGivesTheTerrainUnderIt) {
  const std::string dir = testing::TempDir();
  BlockManifest m = SyntheticBlock(dir);
  m.ground_height.reset();
  const std::string raster = LinearDtmUnderSyntheticBlock(dir + "/surface.tif").path;
  BlockManifest as_dtm = m, as_dsm = m;
  as_dtm.dtm = raster;
  as_dsm.dsm = raster;
  as_dsm.terrain_window_m = 100;  // 3 cells of the raster's 35 m
  const Block a = ManifestToBlock(as_dtm), b = ManifestToBlock(as_dsm);
  ASSERT_TRUE(b.ground.grid.has_value());
  // A planar slope comes through the opening unchanged.
  EXPECT_NEAR(b.ground.HeightAt(0, 0), a.ground.HeightAt(0, 0), 1e-3);
  EXPECT_NEAR(b.ground.HeightAt(30, -20), a.ground.HeightAt(30, -20), 1e-3);
  // Written and read back with its window.
  WriteManifest(as_dsm, dir + "/dsm_block.json", true);
  const BlockManifest back = ReadManifest(dir + "/dsm_block.json");
  EXPECT_EQ(std::filesystem::path(back.dsm).filename(), "surface.tif");
  EXPECT_TRUE(back.dtm.empty());
  EXPECT_DOUBLE_EQ(back.terrain_window_m, 100);
  BlockManifest both = as_dsm;
  both.dtm = raster;
  EXPECT_THROW(ValidateManifest(both, false), Error);
  both.dtm.clear();
  both.terrain_window_m = 0;
  EXPECT_THROW(ValidateManifest(both, false), Error);
}

TEST(BlockManifest, RealAerialBlockWithDem) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(data, "data/multiview/orthority-ngi-aerial");
  std::ifstream prj(data + "/ngi_xyz_opk.prj");
  std::string crs;
  std::getline(prj, crs);
  BlockManifest m;
  m.crs = crs;
  Camera cam;
  cam.id = "dmc";
  cam.width = 640;
  cam.height = 1152;
  cam.fx = cam.fy = 120.0 / 0.144;
  cam.cx = 320;
  cam.cy = 576;
  cam.pixel_size_mm = 0.144;
  m.cameras.push_back(cam);
  std::ifstream eo(data + "/camera_pos_ori.txt");
  std::string name;
  double x, y, z, o, p, k;
  while (eo >> name >> x >> y >> z >> o >> p >> k) {
    ManifestImage im;
    im.name = name;
    im.path = name + ".tif";
    im.camera = "dmc";
    im.position = {x, y, z};
    im.rotation = OpkToRotation(o, p, k);
    m.images.push_back(im);
  }
  ASSERT_EQ(m.images.size(), 4u);
  m.dtm = "dem.tif";
  m.base_dir = data;
  EXPECT_NO_THROW(ValidateManifest(m, true));
  const Block block = ManifestToBlock(m);
  ASSERT_TRUE(block.ground.grid.has_value());
  const GroundModel::Grid& grid = *block.ground.grid;
  int valid = 0;
  for (float v : grid.z) valid += std::isfinite(v) ? 1 : 0;
  EXPECT_GT(valid, static_cast<int>(0.8 * grid.z.size())) << grid.rows << "x" << grid.cols;
  // Heights within the DEM's 148-781 m range, once back in the CRS.
  double lo = 1e9, hi = -1e9;
  for (float v : grid.z) {
    if (!std::isfinite(v)) continue;
    lo = std::min<double>(lo, v);
    hi = std::max<double>(hi, v);
  }
  EXPECT_GT(lo + block.frame.origin_h, 140.0);
  EXPECT_LT(hi + block.frame.origin_h, 800.0);
  // Every image centre looks down onto the grid.
  for (const View& v : block.views) {
    const double h = block.ground.HeightAt(v.pose.C.x(), v.pose.C.y());
    EXPECT_TRUE(std::isfinite(h)) << v.name;
    EXPECT_GT(v.pose.C.z() - h, 4000.0) << v.name;
  }
}

}  // namespace
}  // namespace roofsweep
