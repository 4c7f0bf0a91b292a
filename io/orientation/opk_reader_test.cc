#include "io/orientation/opk_reader.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "io/core/image_io.h"
#include "io/orientation/test_util.h"
#include "tests/support/shared_data.h"

namespace fs = std::filesystem;

namespace roofsweep::orientation {
namespace {

using testing::CameraOf;
using testing::WriteFile;

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(OpkReader, NgiCsvWithYamlCameraAndPrj) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(dir, "data/multiview/orthority-ngi-aerial");
  ImportOptions options;
  options.camera_file = dir + "/ngi_int_param.yaml";
  const BlockManifest m = ReadOpk({dir + "/ngi_xyz_opk.csv"}, options);
  ASSERT_EQ(m.images.size(), 4u);
  EXPECT_NE(m.crs.find("+proj=tmerc"), std::string::npos);
  EXPECT_NE(m.crs.find("+lon_0=25"), std::string::npos);
  ASSERT_EQ(m.cameras.size(), 1u);
  const Camera& c = m.cameras[0];
  EXPECT_EQ(c.id, "Integraph DMC");
  EXPECT_EQ(c.width, 640);
  EXPECT_EQ(c.height, 1152);
  EXPECT_DOUBLE_EQ(c.fx, 120.0 * 640 / 92.16);  // 833.3 px: 0.144 mm pixels
  EXPECT_DOUBLE_EQ(c.fy, 120.0 * 1152 / 165.888);
  EXPECT_DOUBLE_EQ(c.cx, 320);
  EXPECT_DOUBLE_EQ(c.cy, 576);
  EXPECT_NEAR(c.pixel_size_mm, 0.144, 1e-12);
  for (const auto& image : m.images) {
    const ImageInfo info = ProbeImage(image.path);
    EXPECT_EQ(info.width, 640);
    EXPECT_EQ(info.height, 1152);
    // DMC at ~5250 m over a 148-781 m DEM.
    EXPECT_GT(image.position.z(), 5000);
    EXPECT_LT(image.position.z(), 5500);
    // Nadir: the camera looks down (PATB z points back, i.e. up).
    EXPECT_GT(image.rotation(2, 2), 0.99);
  }
  const auto* first = testing::FindImage(m, "3324c_2015_1004_05_0182_RGB");
  ASSERT_NE(first, nullptr);
  EXPECT_DOUBLE_EQ(first->position.x(), -55094.504);
}

TEST(OpkReader, HeaderlessTextMatchesTheCsv) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(dir, "data/multiview/orthority-ngi-aerial");
  ImportOptions options;
  options.camera_file = dir + "/ngi_int_param.yaml";
  const BlockManifest csv = ReadOpk({dir + "/ngi_xyz_opk.csv"}, options);
  const BlockManifest txt = ReadOpk({dir + "/camera_pos_ori.txt"}, options);
  EXPECT_TRUE(txt.crs.empty());  // no camera_pos_ori.prj
  ASSERT_EQ(txt.images.size(), 4u);
  for (const auto& a : txt.images) {
    const auto* b = testing::FindImage(csv, a.name);
    ASSERT_NE(b, nullptr);
    EXPECT_LT((a.position - b->position).norm(), 0.001);  // csv rounds to mm
    EXPECT_LT(RotationAngleDeg(a.rotation, b->rotation), 0.001);
  }
}

TEST(OpkReader, OdmCsvWithQuotesAndCameraColumn) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(dir, "data/multiview/orthority-odm-drone");
  ImportOptions options;
  options.crs = "EPSG:32651";
  options.camera_file = dir + "/opensfm/reconstruction.json";
  options.image_dir = dir + "/images";
  const BlockManifest m = ReadOpk({dir + "/odm_xyz_opk.csv"}, options);
  ASSERT_EQ(m.images.size(), 4u);
  EXPECT_EQ(m.crs, "EPSG:32651");
  for (const auto& image : m.images) {
    const ImageInfo info = ProbeImage(image.path);
    EXPECT_EQ(CameraOf(m, image).width, info.width);
    EXPECT_EQ(CameraOf(m, image).height, info.height);
    EXPECT_NEAR(image.position.z(), 186.5, 0.5);  // ~100 m over a 57-113 m DSM
  }
  EXPECT_NEAR(m.cameras[0].fx, 0.6664614123723713 * 1368, 1e-9);
  EXPECT_NEAR(m.cameras[0].cx, 684 - 0.0015460447606643697 * 1368, 1e-9);
}

TEST(OpkReader, MetashapeTextWithCalibrationXml) {
  const std::string dir = roofsweep::testing::TempDir("metashape");
  const Eigen::Matrix3d r = OpkToRotation(1.5, -2.25, 93.0);
  char line[1024];
  std::snprintf(line, sizeof line,
                "IMG_1.JPG\t500000.1\t5400000.2\t900.3\t1.5\t-2.25\t93.0\t%.10f\t%.10f\t%.10f\t"
                "%.10f\t%.10f\t%.10f\t%.10f\t%.10f\t%.10f\n",
                r(0, 0), r(1, 0), r(2, 0), r(0, 1), r(1, 1), r(2, 1), r(0, 2), r(1, 2), r(2, 2));
  WriteFile(dir + "/cams.txt",
            std::string("# Cameras (1)\n# PhotoID, X, Y, Z, Omega, Phi, Kappa, r11, r12, r13, "
                        "r21, r22, r23, r31, r32, r33\n") +
                line);
  WriteFile(dir + "/calib.xml",
            "<?xml version=\"1.0\"?>\n<calibration>\n  <projection>frame</projection>\n"
            "  <width>6000</width>\n  <height>4000</height>\n  <f>5000.5</f>\n"
            "  <cx>-12.5</cx>\n  <cy>7.25</cy>\n  <b1>0.5</b1>\n  <b2>0.25</b2>\n"
            "  <k1>-0.1</k1>\n  <k2>0.02</k2>\n  <k3>-0.003</k3>\n  <p1>0.0004</p1>\n"
            "  <p2>-0.0005</p2>\n</calibration>\n");
  ImportOptions options;
  options.check_images = false;
  const BlockManifest m = ReadOpk({dir + "/cams.txt", dir + "/calib.xml"}, options);
  ASSERT_EQ(m.images.size(), 1u);
  EXPECT_LT((m.images[0].rotation - r).cwiseAbs().maxCoeff(), 1e-12);
  const Camera& c = m.cameras[0];
  EXPECT_DOUBLE_EQ(c.fx, 5001.0);
  EXPECT_DOUBLE_EQ(c.fy, 5000.5);
  EXPECT_DOUBLE_EQ(c.skew, 0.25);
  EXPECT_DOUBLE_EQ(c.cx, 2987.5);
  EXPECT_DOUBLE_EQ(c.cy, 2007.25);
  EXPECT_DOUBLE_EQ(c.p1, -0.0005);  // Metashape P2
  EXPECT_DOUBLE_EQ(c.p2, 0.0004);   // Metashape P1

  // A matrix that is neither R nor R^T is refused at its line.
  std::snprintf(
      line, sizeof line,
      "IMG_1.JPG\t500000.1\t5400000.2\t900.3\t1.5\t-2.25\t93.0\t1\t0\t0\t0\t1\t0\t0\t0\t1\n");
  WriteFile(dir + "/bad.txt", std::string("# Cameras (1)\n# PhotoID, X, Y, Z, Omega, Phi, Kappa, "
                                          "r11, r12, r13, r21, r22, r23, r31, r32, r33\n") +
                                  line);
  EXPECT_NE(ErrorOf([&] {
              ReadOpk({dir + "/bad.txt", dir + "/calib.xml"}, options);
            }).find("bad.txt:3: the r11..r33 matrix is neither"),
            std::string::npos);
}

class OpkBadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = roofsweep::testing::TempDir("opk_bad");
    WriteFile(dir_ + "/cam.yaml", "c:\n  im_size: [100, 80]\n  focal_len: 1.0\n");
    options_.camera_file = dir_ + "/cam.yaml";
    options_.check_images = false;
  }
  std::string Import(const std::string& text) {
    WriteFile(dir_ + "/o.csv", text);
    return ErrorOf([&] { ReadOpk({dir_ + "/o.csv"}, options_); });
  }
  std::string dir_;
  ImportOptions options_;
};

TEST_F(OpkBadInput, WrongColumnCount) {
  EXPECT_NE(Import("filename,x,y,z,omega,phi,kappa\na,1,2,3,0,0,0\nb,1,2,3,0,0\n")
                .find("o.csv:3: wrong column count: expected 7"),
            std::string::npos);
}

TEST_F(OpkBadInput, NonNumeric) {
  EXPECT_NE(Import("filename,x,y,z,omega,phi,kappa\na,1,2,3,0,zero,0\n")
                .find("o.csv:2: phi: 'zero' is not a number"),
            std::string::npos);
}

TEST_F(OpkBadInput, NaN) {
  EXPECT_NE(Import("a 1 2 3 0 0 0\nb 1 nan 3 0 0 0\n").find("o.csv:2: Y: 'nan' is not a finite"),
            std::string::npos);
}

TEST_F(OpkBadInput, DuplicateImageName) {
  EXPECT_NE(Import("a.tif 1 2 3 0 0 0\n\na.jpg 1 2 3 0 0 0\n")
                .find("o.csv:3: duplicate image name 'a' (first at "),
            std::string::npos);
}

TEST_F(OpkBadInput, MissingColumn) {
  EXPECT_NE(Import("filename,x,y,z,roll,pitch,yaw\na,1,2,3,0,0,0\n")
                .find("o.csv:1: header has no 'omega' column (roll/pitch/yaw"),
            std::string::npos);
}

TEST_F(OpkBadInput, UnknownCameraColumn) {
  EXPECT_NE(Import("filename x y z omega phi kappa camera\na 1 2 3 0 0 0 'other cam'\n")
                .find("o.csv:2: unknown camera id 'other cam'"),
            std::string::npos);
}

TEST_F(OpkBadInput, MissingImage) {
  options_.check_images = true;
  EXPECT_NE(Import("a 1 2 3 0 0 0\n").find("o.csv:1: missing image file for 'a'"),
            std::string::npos);
}

TEST_F(OpkBadInput, ZeroFocal) {
  WriteFile(dir_ + "/cam.yaml", "c:\n  im_size: [100, 80]\n  focal_len: 0\n");
  EXPECT_NE(Import("a 1 2 3 0 0 0\n").find("cam.yaml:3: zero or negative focal length"),
            std::string::npos);
}

TEST_F(OpkBadInput, NoCameraFile) {
  options_.camera_file.clear();
  EXPECT_NE(Import("a 1 2 3 0 0 0\n").find("OPK files carry no interior orientation"),
            std::string::npos);
}

}  // namespace
}  // namespace roofsweep::orientation
