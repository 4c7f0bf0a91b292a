#include "io/orientation/opensfm_reader.h"

#include <gtest/gtest.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <GeographicLib/UTMUPS.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/core/image_io.h"
#include "io/orientation/opk_reader.h"
#include "io/orientation/test_util.h"
#include "tests/support/shared_data.h"

namespace fs = std::filesystem;

namespace roofsweep::orientation {
namespace {

using testing::CameraOf;
using testing::FindImage;

// OpenSfM's own perspective projection (normalised, centre-of-pixel origin),
// shifted to roofsweep's corner origin.
Eigen::Vector2d OpenSfmProject(const nlohmann::json& cam, const nlohmann::json& shot,
                               const Eigen::Vector3d& X) {
  const Eigen::Vector3d r(shot["rotation"][0], shot["rotation"][1], shot["rotation"][2]);
  const Eigen::Vector3d t(shot["translation"][0], shot["translation"][1], shot["translation"][2]);
  const Eigen::Vector3d x = AxisAngleToRotation(r) * X + t;
  const double u = x.x() / x.z(), v = x.y() / x.z();
  const double r2 = u * u + v * v;
  const double d = 1 + cam["k1"].get<double>() * r2 + cam["k2"].get<double>() * r2 * r2;
  const double f = cam["focal"];
  const double w = cam["width"], h = cam["height"], s = std::max(w, h);
  return {s * f * d * u + (w - 1) / 2 + 0.5, s * f * d * v + (h - 1) / 2 + 0.5};
}

TEST(OpenSfmReader, BerlinImportsAndReprojectsItsPoints) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(path, "data/multiview/opensfm-berlin/reconstruction_example.json");
  const BlockManifest m = ReadOpenSfm({path}, ImportOptions());
  ASSERT_EQ(m.images.size(), 3u);
  EXPECT_EQ(m.crs, "EPSG:32633");
  // Street-level photos of facades: the 5th percentile of the point heights
  // (33.4 m) lies above the cameras, so no ground is claimed.
  EXPECT_FALSE(m.ground_height.has_value());
  for (const auto& image : m.images) {
    const Camera& c = CameraOf(m, image);
    const ImageInfo info = ProbeImage(image.path);
    EXPECT_EQ(c.width, info.width);
    EXPECT_EQ(c.height, info.height);
    EXPECT_DOUBLE_EQ(c.cx, 3264 / 2.0);
  }

  // Through the io/core local frame, the imported block must project the
  // reconstruction's points where OpenSfM does.
  const Block block = ManifestToBlock(m);
  std::ifstream in(path);
  const nlohmann::json rec = nlohmann::json::parse(in)[0];
  const nlohmann::json& cam = rec["cameras"].begin().value();
  const auto& lla = rec["reference_lla"];
  GeographicLib::LocalCartesian reference(lla["latitude"], lla["longitude"], lla["altitude"]);
  GeographicLib::LocalCartesian local(block.frame.origin_lat, block.frame.origin_lon,
                                      block.frame.origin_h);
  double worst = 0;
  size_t n = 0;
  for (const auto& [id, point] : rec["points"].items()) {
    const Eigen::Vector3d X(point["coordinates"][0], point["coordinates"][1],
                            point["coordinates"][2]);
    double lat, lon, h, x, y, z;
    reference.Reverse(X.x(), X.y(), X.z(), lat, lon, h);
    local.Forward(lat, lon, h, x, y, z);
    for (const auto& view : block.views) {
      const auto& shot = rec["shots"][view.name + ".jpg"];
      const Eigen::Vector3d xc =
          AxisAngleToRotation(
              Eigen::Vector3d(shot["rotation"][0], shot["rotation"][1], shot["rotation"][2])) *
              X +
          Eigen::Vector3d(shot["translation"][0], shot["translation"][1], shot["translation"][2]);
      if (xc.z() <= 0) continue;
      const auto p = Project(block.CameraOf(view), view.pose, Eigen::Vector3d(x, y, z));
      ASSERT_TRUE(p.has_value());
      worst = std::max(worst, (*p - OpenSfmProject(cam, shot, X)).norm());
      ++n;
    }
  }
  std::cout << "[ opensfm ] Berlin: " << n << " point projections, worst difference " << worst
            << " px\n";
  EXPECT_GT(n, 1000u);
  EXPECT_LT(worst, 0.01);
}

// orthority's odm_xyz_opk.csv holds the same ODM cameras in UTM 51N, but
// converted naively: ENU offsets added to the UTM coordinates of
// reference_lla and ENU angles taken as grid angles, ignoring the meridian
// convergence (-0.856 deg here) and grid scale. The test shows that this is
// what the csv holds, and that roofsweep's rigorous conversion differs from
// it by exactly the convergence (the rigorous one is checked by projection
// in BerlinImportsAndReprojectsItsPoints).
TEST(OpenSfmReader, OdmCsvIsTheNaiveConversionOfTheReconstruction) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(dir, "data/multiview/orthority-odm-drone");
  const std::string path = dir + "/opensfm/reconstruction.json";
  const BlockManifest sfm = ReadOpenSfm({path}, ImportOptions());
  EXPECT_EQ(sfm.crs, "EPSG:32651");
  EXPECT_FALSE(sfm.ground_height.has_value());  // no points in this file
  ImportOptions options;
  options.crs = "EPSG:32651";
  options.camera_file = path;
  options.image_dir = dir + "/images";
  const BlockManifest csv = ReadOpk({dir + "/odm_xyz_opk.csv"}, options);
  ASSERT_EQ(sfm.images.size(), 4u);
  ASSERT_EQ(csv.images.size(), 4u);

  std::ifstream in(path);
  const nlohmann::json rec = nlohmann::json::parse(in)[0];
  const double lat0 = rec["reference_lla"]["latitude"], lon0 = rec["reference_lla"]["longitude"];
  int zone;
  bool north;
  double e0, n0, gamma, k;
  GeographicLib::UTMUPS::Forward(lat0, lon0, zone, north, e0, n0, gamma, k);
  double worst_naive_pos = 0, worst_naive_deg = 0, worst_pos = 0;
  for (const auto& a : sfm.images) {
    const ManifestImage* b = FindImage(csv, a.name);
    ASSERT_NE(b, nullptr) << a.name;
    EXPECT_EQ(a.path, b->path);
    const auto& shot = rec["shots"][a.name];
    const Eigen::Matrix3d R = AxisAngleToRotation(
        Eigen::Vector3d(shot["rotation"][0], shot["rotation"][1], shot["rotation"][2]));
    const Eigen::Vector3d C =
        -R.transpose() *
        Eigen::Vector3d(shot["translation"][0], shot["translation"][1], shot["translation"][2]);
    worst_naive_pos =
        std::max(worst_naive_pos, (Eigen::Vector3d(e0, n0, 0) + C - b->position).norm());
    worst_naive_deg = std::max(worst_naive_deg, RotationAngleDeg(CvToPatb(R), b->rotation));
    worst_pos = std::max(worst_pos, (a.position - b->position).norm());
    // Rigorous minus naive: a turn about the vertical by the convergence.
    EXPECT_NEAR(RotationAngleDeg(a.rotation, b->rotation), std::abs(gamma), 0.01);
    EXPECT_EQ(CameraOf(sfm, a).width, 1368);
    EXPECT_EQ(CameraOf(sfm, a).height, 912);
  }
  std::cout << "[ opensfm ] ODM csv vs naive conversion: " << worst_naive_pos << " m, "
            << worst_naive_deg << " deg; vs roofsweep: " << worst_pos << " m (convergence " << gamma
            << " deg)\n";
  EXPECT_LT(worst_naive_pos, 0.01);   // csv has mm
  EXPECT_LT(worst_naive_deg, 0.005);  // csv has 3 decimals
  EXPECT_GT(worst_pos, 1.0);
}

TEST(OpenSfmReader, RefusesFisheye) {
  const std::string dir = roofsweep::testing::TempDir("osfm_fisheye");
  testing::WriteFile(dir + "/reconstruction.json",
                     R"([{"cameras": {"c": {"projection_type": "fisheye", "width": 10, "height": 10,
                          "focal": 0.5}}, "shots": {"a.jpg": {"camera": "c", "rotation": [0,0,0],
                          "translation": [0,0,0]}}}])");
  ImportOptions options;
  options.check_images = false;
  try {
    ReadOpenSfm({dir + "/reconstruction.json"}, options);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(
        std::string(e.what()).find("/0/cameras/c/projection_type: 'fisheye' is not supported"),
        std::string::npos)
        << e.what();
  }
}

TEST(OpenSfmReader, SyntaxErrorNamesTheLine) {
  const std::string dir = roofsweep::testing::TempDir("osfm_syntax");
  testing::WriteFile(dir + "/reconstruction.json", "[{\n\"cameras\": {},\n\"shots\": {,}\n}]\n");
  try {
    ReadOpenSfm({dir + "/reconstruction.json"}, ImportOptions());
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("reconstruction.json:3: invalid JSON"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace roofsweep::orientation
