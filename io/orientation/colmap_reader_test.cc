#include "io/orientation/colmap_reader.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "io/orientation/opk_reader.h"
#include "io/orientation/test_util.h"
#include "tests/support/shared_data.h"

namespace roofsweep::orientation {
namespace {

struct TruePose {
  std::string name;
  Eigen::Matrix3d R_cv;  // world -> camera
  Eigen::Vector3d C;
};

std::vector<TruePose> RandomPoses(int n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<TruePose> poses;
  for (int i = 0; i < n; ++i) {
    Eigen::Vector4d q(u(rng), u(rng), u(rng), u(rng));
    q.normalize();
    TruePose p;
    p.name = "img_" + std::to_string(i) + ".jpg";
    p.R_cv = QuaternionToRotation(q[0], q[1], q[2], q[3]);
    // A local frame (COLMAP's is arbitrary): at UTM magnitudes (5e6 m) double
    // rounding alone in C = -R^T t is ~3e-9 m, above the 1e-9 asked for.
    p.C = Eigen::Vector3d(300 * u(rng), 300 * u(rng), 800 + 50 * u(rng));
    poses.push_back(p);
  }
  return poses;
}

std::string Fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

void WriteColmap(const std::string& dir, const std::vector<TruePose>& poses) {
  testing::WriteFile(dir + "/cameras.txt",
                     "# Camera list\n1 PINHOLE 6000 4000 5000 5001 3000.5 1999.5\n"
                     "2 OPENCV 6000 4000 5000 5000 3000 2000 -0.1 0.01 0.001 -0.002\n");
  std::string images = "# Image list with two lines of data per image\n";
  for (size_t i = 0; i < poses.size(); ++i) {
    const Eigen::Vector4d q = RotationToQuaternion(poses[i].R_cv);
    const Eigen::Vector3d t = -poses[i].R_cv * poses[i].C;
    images += std::to_string(i + 1);
    for (int k = 0; k < 4; ++k) images += " " + Fmt("%.17g", q[k]);
    for (int k = 0; k < 3; ++k) images += " " + Fmt("%.17g", t[k]);
    images += " " + std::to_string(i % 2 + 1) + " " + poses[i].name + "\n";
    images += i == 0 ? "\n" : "10.5 20.5 -1 30.5 40.5 7\n";  // points line, may be empty
  }
  testing::WriteFile(dir + "/images.txt", images);
}

TEST(ColmapReader, RoundTripsPoses) {
  const std::string dir = roofsweep::testing::TempDir("colmap");
  const auto poses = RandomPoses(6);
  WriteColmap(dir, poses);
  ImportOptions options;
  options.check_images = false;
  const BlockManifest m = ReadColmap({dir}, options);
  ASSERT_EQ(m.images.size(), poses.size());
  ASSERT_EQ(m.cameras.size(), 2u);
  EXPECT_TRUE(m.crs.empty());
  EXPECT_DOUBLE_EQ(m.cameras[0].fy, 5001);
  EXPECT_DOUBLE_EQ(m.cameras[1].p2, -0.002);
  for (size_t i = 0; i < poses.size(); ++i) {
    const ManifestImage& image = m.images[i];
    EXPECT_EQ(image.name, "img_" + std::to_string(i));
    EXPECT_EQ(image.camera, std::to_string(i % 2 + 1));
    EXPECT_LT((PatbToCv(image.rotation) - poses[i].R_cv).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LT((image.position - poses[i].C).cwiseAbs().maxCoeff(), 1e-9);
  }
}

// The same poses written as COLMAP and as OPK (orthority headerless text +
// YAML camera) must import to the same manifest rotations and positions.
TEST(ColmapReader, AgreesWithOpk) {
  const std::string dir = roofsweep::testing::TempDir("colmap_opk");
  const auto poses = RandomPoses(5);
  WriteColmap(dir, poses);
  std::string opk;
  for (const auto& p : poses) {
    const Eigen::Vector3d a = RotationToOpk(CvToPatb(p.R_cv));
    opk += p.name.substr(0, p.name.size() - 4);
    for (int k = 0; k < 3; ++k) opk += " " + Fmt("%.17g", p.C[k]);
    for (int k = 0; k < 3; ++k) opk += " " + Fmt("%.17g", a[k]);
    opk += "\n";
  }
  testing::WriteFile(dir + "/pos_ori.txt", opk);
  testing::WriteFile(dir + "/cam.yaml",
                     "cam:\n  type: pinhole\n  im_size: [6000, 4000]\n  focal_len: 0.8\n");
  ImportOptions options;
  options.check_images = false;
  options.camera_file = dir + "/cam.yaml";
  const BlockManifest from_opk = ReadOpk({dir + "/pos_ori.txt"}, options);
  const BlockManifest from_colmap = ReadColmap({dir + "/cameras.txt"}, options);
  ASSERT_EQ(from_opk.images.size(), from_colmap.images.size());
  for (size_t i = 0; i < poses.size(); ++i) {
    EXPECT_EQ(from_opk.images[i].name, from_colmap.images[i].name);
    EXPECT_LT((from_opk.images[i].rotation - from_colmap.images[i].rotation).cwiseAbs().maxCoeff(),
              1e-9);
    EXPECT_LT((from_opk.images[i].position - from_colmap.images[i].position).cwiseAbs().maxCoeff(),
              1e-9);
  }
  // orthority: f = focal_len * width, principal point at the centre.
  EXPECT_DOUBLE_EQ(from_opk.cameras[0].fx, 4800);
  EXPECT_DOUBLE_EQ(from_opk.cameras[0].cx, 3000);
  EXPECT_DOUBLE_EQ(from_opk.cameras[0].cy, 2000);
}

TEST(ColmapReader, RefusesRationalDistortion) {
  const std::string dir = roofsweep::testing::TempDir("colmap_full");
  testing::WriteFile(dir + "/cameras.txt",
                     "1 FULL_OPENCV 100 100 50 50 50 50 0.1 0 0 0 0 0.2 0 0\n");
  testing::WriteFile(dir + "/images.txt", "1 1 0 0 0 0 0 0 1 a.jpg\n\n");
  ImportOptions options;
  options.check_images = false;
  try {
    ReadColmap({dir}, options);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cameras.txt:1: FULL_OPENCV with non-zero k4"),
              std::string::npos)
        << e.what();
  }
}

TEST(ColmapReader, UnknownCameraId) {
  const std::string dir = roofsweep::testing::TempDir("colmap_cam");
  testing::WriteFile(dir + "/cameras.txt", "1 PINHOLE 100 100 50 50 50 50\n");
  testing::WriteFile(dir + "/images.txt", "# c\n1 1 0 0 0 0 0 0 3 a.jpg\n\n");
  ImportOptions options;
  options.check_images = false;
  try {
    ReadColmap({dir}, options);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("images.txt:2: unknown camera id 3"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace roofsweep::orientation
