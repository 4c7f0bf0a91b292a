#include "io/orientation/vgg_annotations.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "algorithms/core/error.h"
#include "io/orientation/test_util.h"
#include "tests/support/shared_data.h"

namespace roofsweep::orientation {
namespace {

using testing::WriteFile;

std::string ErrorOf(const std::string& folder) {
  try {
    ReadVggLineAnnotations(folder);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(VggAnnotations, ReadsMerton1) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(set, "data/multiview/oxford-vgg/merton1");
  const VggLineAnnotations a = ReadVggLineAnnotations(set);
  ASSERT_EQ(a.views, (std::vector<std::string>{"001", "002", "003"}));
  EXPECT_EQ(a.lines[0].size(), 655u);
  EXPECT_EQ(a.rows.size(), 295u);
  EXPECT_EQ(a.lines3d.size(), a.rows.size());
  // 001.lines, first row: 5.7847987e+02 1.8000026e+02 ... (+0.5 px).
  EXPECT_NEAR(a.lines[0][0].p0.x(), 578.97987, 1e-5);
  EXPECT_EQ(a.rows[4], (std::vector<int>{4, 4, 4}));
}

TEST(VggAnnotations, ReadsModelHouseWithItsMirroredWorld) {
  ROOFSWEEP_SHARED_PATH_OR_SKIP(set, "data/multiview/oxford-vgg/model_house");
  const VggLineAnnotations a = ReadVggLineAnnotations(set);
  ASSERT_EQ(a.views.size(), 10u);
  EXPECT_EQ(a.views.front(), "house.000");
  ASSERT_FALSE(a.rows.empty());
  // "-1" marks an unseen line there.
  EXPECT_EQ(a.rows[1][7], -1);
  ASSERT_EQ(a.lines3d.size(), a.rows.size());
}

TEST(VggAnnotations, BadFilesNameFileAndLine) {
  const std::string dir = roofsweep::testing::TempDir("vgg_ann");
  WriteFile(dir + "/a.lines", "0 0 10 10\n1 1 20 20\n");
  WriteFile(dir + "/b.lines", "0 0 10 10\n");
  WriteFile(dir + "/nview-lines", "0 0\n1 *\n");
  EXPECT_EQ(ErrorOf(dir), "");
  WriteFile(dir + "/nview-lines", "0 0\n1 1\n");
  EXPECT_NE(ErrorOf(dir).find("nview-lines:2: line id 1 out of range for b.lines"),
            std::string::npos)
      << ErrorOf(dir);
  WriteFile(dir + "/nview-lines", "0 0 0\n");
  EXPECT_NE(ErrorOf(dir).find("nview-lines:1: 3 columns for 2 views"), std::string::npos);
  WriteFile(dir + "/nview-lines", "0 0\n");
  WriteFile(dir + "/b.lines", "0 0 10 x\n");
  EXPECT_NE(ErrorOf(dir).find("b.lines:1:"), std::string::npos) << ErrorOf(dir);
  std::filesystem::remove(dir + "/nview-lines");
  WriteFile(dir + "/b.lines", "0 0 10 10\n");
  EXPECT_NE(ErrorOf(dir).find("no nview-lines file"), std::string::npos);
}

}  // namespace
}  // namespace roofsweep::orientation
