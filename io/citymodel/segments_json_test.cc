// 3D lines read back for `run -lines`: the reprojection residual roofsweep
// wrote beside each line comes back with it, and is unknown (NaN) where the
// source has none; the CRS comes back as the code it was written with.
#include "io/citymodel/segments_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "io/citymodel/ogr_citymodel.h"
#include "tests/support/shared_data.h"

namespace roofsweep {
namespace {

TEST(ReadSegments, TheResidualOfAWrittenLineComesBack) {
  const std::string path = testing::TempDir("segments") + "/lines3d.gpkg";
  std::vector<LayerFeature> lines(2);
  lines[0].lines = {{{500000, 5400000, 100}, {500010, 5400000, 101}}};
  lines[0].reals["rms_px"] = 0.37;
  lines[1].lines = {{{500000, 5400005, 100}, {500000, 5400015, 102}}};
  lines[1].reals["rms_px"] = 1.25;
  lines[0].strings["depth_from"] = "stereo";
  lines[1].strings["depth_from"] = "stereo";
  lines[0].integers["views"] = 3;
  lines[1].integers["views"] = 5;
  // Its depth from the lines at its ends: the residual is no measurement.
  lines.push_back(lines[1]);
  lines[2].strings["depth_from"] = "junctions";
  // Two views: a line through two planes fits them exactly.
  lines.push_back(lines[1]);
  lines[3].integers["views"] = 2;
  lines[0].strings["observations"] = "s01_i001:7 s02_i002:31";
  lines[1].strings["observations"] = "name with space:3";        // cannot be told apart
  lines[2].strings["observations"] = "s01_i001:-1 s02_i002:-2";  // -2 is no id
  lines[3].strings["observations"] = "s01_i001:-1 s02_i002:4";   // -1: segment not known
  FeatureLayerOptions o;
  o.crs = "EPSG:25832";
  WriteFeatureLayer(path, "lines3d", LayerGeometry::kLineStringZ, lines, o);
  const SegmentSet set = ReadSegments(path);
  ASSERT_EQ(set.segments.size(), 4u);
  EXPECT_DOUBLE_EQ(set.segments[0].rms_px, 0.37);
  EXPECT_DOUBLE_EQ(set.segments[1].rms_px, 1.25);
  EXPECT_DOUBLE_EQ(set.segments[1].segment.b.z(), 102);
  EXPECT_TRUE(std::isnan(set.segments[2].rms_px));
  EXPECT_TRUE(std::isnan(set.segments[3].rms_px));
  using Obs = std::vector<std::pair<std::string, int>>;
  EXPECT_EQ(set.segments[0].observations, (Obs{{"s01_i001", 7}, {"s02_i002", 31}}));
  EXPECT_TRUE(set.segments[1].observations.empty());
  EXPECT_TRUE(set.segments[2].observations.empty());
  EXPECT_EQ(set.segments[3].observations, (Obs{{"s01_i001", -1}, {"s02_i002", 4}}));
  EXPECT_EQ(FormatObservations(set.segments[0].observations), "s01_i001:7 s02_i002:31");
  // The layer's CRS is stored promoted to 3D, without a top-level code; it
  // must still read back as the block's, or run -lines cannot tell a file in
  // another CRS from its own.
  EXPECT_EQ(set.crs, "EPSG:25832");
}

TEST(ReadSegments, NoResidualFieldMeansUnknown) {
  const std::string dir = testing::TempDir("segments");
  const std::string path = dir + "/edges.json";
  std::ofstream(path) << R"({"type": "roofsweep_segments", "segments": [)"
                      << R"({"a": [0, 0, 5], "b": [4, 0, 5], "kind": "ridge", "building": 3}]})";
  const SegmentSet set = ReadSegments(path);
  ASSERT_EQ(set.segments.size(), 1u);
  EXPECT_TRUE(std::isnan(set.segments[0].rms_px));

  const std::string gpkg = dir + "/plain.gpkg";
  std::vector<LayerFeature> lines(1);
  lines[0].lines = {{{0, 0, 5}, {4, 0, 5}}};
  WriteFeatureLayer(gpkg, "edges", LayerGeometry::kLineStringZ, lines, {});
  const SegmentSet plain = ReadSegments(gpkg);
  ASSERT_EQ(plain.segments.size(), 1u);
  EXPECT_TRUE(std::isnan(plain.segments[0].rms_px));
  EXPECT_EQ(plain.crs, "");  // written without one
}

}  // namespace
}  // namespace roofsweep
