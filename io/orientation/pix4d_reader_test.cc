#include "io/orientation/pix4d_reader.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <opencv2/core.hpp>

#include "io/core/image_io.h"
#include "io/orientation/opk_reader.h"
#include "io/orientation/test_util.h"
#include "tests/support/shared_data.h"

namespace roofsweep::orientation {
namespace {

// The Pix4D test vector of ecosystem-notes §3 (DSC_0157.JPG), as Pix4D
// writes it: 7 text lines and a blank, then one 10-line block.
const char* kCalibrated =
    "fileName imageWidth imageHeight \n"
    "camera matrix K [3x3]\n"
    "radial distortion [3x1]\n"
    "tangential distortion [2x1]\n"
    "camera position t [3x1]\n"
    "camera rotation R [3x3]\n"
    "camera model m = K [R|-Rt] X\n"
    "\n"
    "DSC_0157.JPG 7360 4912\n"
    "7363.51850023951465118444 0 3686.33719996831450771424\n"
    "0 7363.51850023951465118444 2439.04083412635009153746\n"
    "0 0 1\n"
    "-0.09005921067656787182 0.10773972435740564180 -0.01257054987797603419\n"
    "-0.00029570539858373248 -0.00027422056492206067\n"
    "114.12600004808672338186 378.81985574952466322429 -2.31159761431545440757\n"
    "-0.49632901575943477734 0.86794436424468834890 -0.01816834310427051929\n"
    "0.86649900151927328196 0.49400145706385401034 -0.07170802455019638366\n"
    "-0.05326338781351704077 -0.05133362440616233424 -0.99726018196053234366\n"
    "\n";
const char* kExternal =
    "imageName X Y Z Omega Phi Kappa X_sigma Y_sigma Z_sigma Omega_sigma Phi_sigma Kappa_sigma\n"
    "DSC_0157.JPG 332081.126000 3488911.819856 4093.688402 -2.946680 3.053212 119.804001 "
    "0.01 0.01 0.02 0.001 0.001 0.001\n";

struct Pix4dProject {
  std::string dir, ccp, external;
};

Pix4dProject WriteProject(const std::string& tag) {
  Pix4dProject p;
  p.dir = roofsweep::testing::TempDir(tag);
  p.ccp = testing::WriteFile(p.dir + "/proj_calibrated_camera_parameters.txt", kCalibrated);
  p.external =
      testing::WriteFile(p.dir + "/proj_calibrated_external_camera_parameters.txt", kExternal);
  testing::WriteFile(p.dir + "/proj_offset.xyz", "331967 3488533 4096\n");
  testing::WriteFile(p.dir + "/proj_wkt.prj", "EPSG:32650\n");
  return p;
}

TEST(Pix4dReader, BothFilesGiveTheSamePose) {
  const Pix4dProject p = WriteProject("pix4d");
  ImportOptions options;
  options.check_images = false;
  const BlockManifest a = ReadPix4d({p.ccp}, options);
  const BlockManifest b = ReadOpk({p.external}, options);  // finds the ccp beside it for K
  ASSERT_EQ(a.images.size(), 1u);
  ASSERT_EQ(b.images.size(), 1u);
  EXPECT_EQ(a.images[0].name, "DSC_0157");
  EXPECT_EQ(b.images[0].name, "DSC_0157");
  EXPECT_EQ(a.crs, "EPSG:32650");
  EXPECT_LT((a.images[0].rotation - b.images[0].rotation).cwiseAbs().maxCoeff(), 1e-8);
  // t + offset against the external file's 6 decimals.
  EXPECT_LT((a.images[0].position - b.images[0].position).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_NEAR(a.images[0].position.x(), 332081.126, 1e-6);
  const Camera& c = a.cameras[0];
  EXPECT_EQ(c.width, 7360);
  EXPECT_EQ(c.height, 4912);
  EXPECT_DOUBLE_EQ(c.fx, 7363.51850023951465118444);
  EXPECT_DOUBLE_EQ(c.cx, 3686.33719996831450771424);
  EXPECT_DOUBLE_EQ(c.p1, -0.00029570539858373248);  // T1 = OpenCV p1
  EXPECT_DOUBLE_EQ(c.p2, -0.00027422056492206067);
  EXPECT_DOUBLE_EQ(c.k3, -0.01257054987797603419);
  // The OPK import takes the same interior orientation from the ccp.
  EXPECT_DOUBLE_EQ(b.cameras[0].fx, c.fx);
}

TEST(Pix4dReader, CamFileInMillimetres) {
  // Pix4D .cam for the same camera: 7360 px over 35.9 mm.
  const std::string dir = roofsweep::testing::TempDir("pix4d_cam");
  const double pixel = 35.9 / 7360;
  char cam[512];
  std::snprintf(cam, sizeof cam,
                "Pix4D camera calibration file 0\n"
                "#Focal Length mm assuming a sensor width of %.17gx%.17gmm\n"
                "F %.17g\n#Principal Point mm\nPx %.17g\nPy %.17g\n"
                "#Symmetrical Lens Distortion Coeffs\nK1 -0.09\nK2 0.1\nK3 -0.01\n"
                "#Tangential Lens Distortion Coeffs\nT1 -0.0003\nT2 -0.0002\n",
                7360 * pixel, 4912 * pixel, 7363.5185 * pixel, 3686.3372 * pixel,
                2439.0408 * pixel);
  testing::WriteFile(dir + "/p_pix4d_calibrated_internal_camera_parameters.cam", cam);
  testing::WriteFile(dir + "/ext.txt", kExternal);
  // A .cam needs the image for its size in pixels: without it, a clear error.
  ImportOptions options;
  options.check_images = false;
  options.camera_file = dir + "/p_pix4d_calibrated_internal_camera_parameters.cam";
  try {
    ReadOpk({dir + "/ext.txt"}, options);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("ext.txt:2: missing image file"), std::string::npos)
        << e.what();
  }
}

TEST(Pix4dReader, CamFileScaledByTheImageSize) {
  const std::string dir = roofsweep::testing::TempDir("pix4d_cam_px");
  testing::WriteFile(dir + "/c.cam",
                     "Pix4D camera calibration file 0\n"
                     "#Focal Length mm assuming a sensor width of 8x6mm\n"
                     "F 4\n#Principal Point mm\nPx 4.1\nPy 2.9\nK1 0.01\nK2 0\nK3 0\n"
                     "T1 0.001\nT2 0.002\n");
  testing::WriteFile(dir + "/ext.txt", kExternal);
  WriteImage(dir + "/DSC_0157.png", cv::Mat(120, 160, CV_8UC3, cv::Scalar(1, 2, 3)));
  ImportOptions options;
  options.camera_file = dir + "/c.cam";
  const BlockManifest m = ReadOpk({dir + "/ext.txt"}, options);
  ASSERT_EQ(m.cameras.size(), 1u);
  const Camera& c = m.cameras[0];
  EXPECT_EQ(c.width, 160);
  EXPECT_EQ(c.height, 120);
  EXPECT_DOUBLE_EQ(c.fx, 80);  // F * w_px / W_mm
  EXPECT_DOUBLE_EQ(c.fy, 80);
  EXPECT_DOUBLE_EQ(c.cx, 82);
  EXPECT_DOUBLE_EQ(c.cy, 58);
  EXPECT_DOUBLE_EQ(c.pixel_size_mm, 0.05);
  EXPECT_DOUBLE_EQ(c.p2, 0.002);
}

TEST(Pix4dReader, NeedsTheOffset) {
  const Pix4dProject p = WriteProject("pix4d_offset");
  std::filesystem::remove(p.dir + "/proj_offset.xyz");
  ImportOptions options;
  options.check_images = false;
  EXPECT_THROW(ReadPix4d({p.ccp}, options), Error);
}

TEST(Pix4dReader, TruncatedBlockNamesTheLine) {
  const std::string dir = roofsweep::testing::TempDir("pix4d_bad");
  std::string text = kCalibrated;
  text = text.substr(0, text.find("-0.49632901575943477734"));
  testing::WriteFile(dir + "/x_calibrated_camera_parameters.txt", text);
  testing::WriteFile(dir + "/x_offset.xyz", "0 0 0\n");
  ImportOptions options;
  options.check_images = false;
  try {
    ReadPix4d({dir + "/x_calibrated_camera_parameters.txt"}, options);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("x_calibrated_camera_parameters.txt:9: truncated"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace roofsweep::orientation
