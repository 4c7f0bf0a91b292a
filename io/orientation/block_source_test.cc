#include "io/orientation/block_source.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "io/core/image_io.h"
#include "io/orientation/test_util.h"
#include "tests/support/shared_data.h"

namespace fs = std::filesystem;

namespace roofsweep {
namespace {

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

void ExpectCamerasMatchImages(const BlockManifest& m) {
  for (const auto& image : m.images) {
    const Camera& c = orientation::testing::CameraOf(m, image);
    const ImageInfo info = ProbeImage(image.path);
    EXPECT_EQ(c.width, info.width) << image.path;
    EXPECT_EQ(c.height, info.height) << image.path;
  }
}

TEST(BlockSource, Formats) {
  const auto& f = ImportFormats();
  for (const char* name : {"opk", "pix4d", "metashape", "colmap", "opensfm", "vgg"}) {
    EXPECT_NE(std::find(f.begin(), f.end(), name), f.end()) << name;
  }
}

TEST(BlockSource, UnknownFormat) {
  EXPECT_NE(ErrorOf([] {
              ImportBlock("bundler", {"x"}, ImportOptions());
            }).find("unknown import format 'bundler' (known: opk, pix4d"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { OpenBlockManifest("bundler:/tmp"); }).find("unknown block format"),
            std::string::npos);
}

TEST(BlockSource, ImportsNgiAerial) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(dir, "data/multiview/orthority-ngi-aerial");
  ImportOptions options;
  options.camera_file = dir + "/ngi_int_param.yaml";
  const BlockManifest m = ImportBlock("opk", {dir + "/ngi_xyz_opk.csv"}, options);
  EXPECT_EQ(m.images.size(), 4u);
  EXPECT_FALSE(m.crs.empty());
  ExpectCamerasMatchImages(m);
}

TEST(BlockSource, ImportsOdmBothWays) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(dir, "data/multiview/orthority-odm-drone");
  ImportOptions options;
  options.crs = "EPSG:32651";
  options.camera_file = dir + "/opensfm/reconstruction.json";
  options.image_dir = dir + "/images";
  const BlockManifest csv = ImportBlock("opk", {dir + "/odm_xyz_opk.csv"}, options);
  EXPECT_EQ(csv.images.size(), 4u);
  ExpectCamerasMatchImages(csv);
  const BlockManifest sfm = OpenBlockManifest(dir + "/opensfm/reconstruction.json");
  EXPECT_EQ(sfm.images.size(), 4u);
  EXPECT_EQ(sfm.crs, "EPSG:32651");
  ExpectCamerasMatchImages(sfm);
  for (const auto& image : sfm.images) EXPECT_NEAR(image.position.z(), 186.5, 1.0);
}

TEST(BlockSource, OpensBerlinByItsContent) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(path, "data/multiview/opensfm-berlin/reconstruction_example.json");
  const BlockManifest m = OpenBlockManifest(path);
  EXPECT_EQ(m.images.size(), 3u);
  ExpectCamerasMatchImages(m);
  const Block b = OpenBlock(path);
  EXPECT_EQ(b.views.size(), 3u);
  EXPECT_TRUE(b.frame.HasCrs());
  // Street-level photos: the SfM points' low percentile lies above the
  // cameras, so no ground is claimed (opensfm_reader.cc).
  EXPECT_FALSE(b.ground.Known());
}

TEST(BlockSource, OpensVggSets) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(root, "data/multiview/oxford-vgg");
  const BlockManifest merton = OpenBlockManifest("vgg:" + root + "/merton1");
  EXPECT_EQ(merton.images.size(), 3u);
  ExpectCamerasMatchImages(merton);
  const BlockManifest house = OpenBlockManifest(root + "/model_house");  // found by its *.P
  EXPECT_EQ(house.images.size(), 10u);
  ExpectCamerasMatchImages(house);
  EXPECT_NE(ErrorOf([&] { OpenBlockManifest("vgg:" + root + "/library"); }).find("no image file"),
            std::string::npos);
}

TEST(BlockSource, OpensColmapFolderAndManifestRoundTrip) {
  const std::string dir = roofsweep::testing::TempDir("bs_colmap");
  orientation::testing::WriteFile(dir + "/cameras.txt", "1 SIMPLE_RADIAL 64 48 60 32 24 0.01\n");
  orientation::testing::WriteFile(dir + "/images.txt",
                                  "1 1 0 0 0 1 2 3 1 a.png\n\n2 0 1 0 0 0 0 5 1 b.png\n\n");
  WriteImage(dir + "/a.png", cv::Mat(48, 64, CV_8UC3, cv::Scalar(0, 0, 0)));
  WriteImage(dir + "/b.png", cv::Mat(48, 64, CV_8UC3, cv::Scalar(0, 0, 0)));
  const BlockManifest m = OpenBlockManifest(dir);
  ASSERT_EQ(m.images.size(), 2u);
  EXPECT_EQ(OpenBlockManifest("colmap:" + dir + "/images.txt").images.size(), 2u);
  // Written as block.json, the folder now opens as a manifest.
  const std::string out = dir + "/block";
  fs::create_directories(out);
  WriteManifest(m, out + "/block.json", false);
  const BlockManifest back = OpenBlockManifest(out);
  ASSERT_EQ(back.images.size(), 2u);
  EXPECT_LT((back.images[1].position - m.images[1].position).norm(), 1e-9);
  EXPECT_LT(RotationAngleDeg(back.images[1].rotation, m.images[1].rotation), 1e-7);
}

TEST(BlockSource, MissingPath) {
  EXPECT_NE(ErrorOf([] { OpenBlockManifest("/nonexistent/block.json"); }).find("no such file"),
            std::string::npos);
}

}  // namespace
}  // namespace roofsweep
