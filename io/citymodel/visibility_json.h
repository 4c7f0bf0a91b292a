#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace roofsweep {

// groundtruth_visibility.json, written by `roofsweep simulate` beside its
// ground truth and read by `roofsweep eval`: for each true roof polygon,
// the share of it each view sees (sim::RoofVisibility), so that the
// evaluation can tell the roofs no two views show from the method's misses
// (ScoreSeenPlanes). Coordinates are in the file's CRS.
struct RoofVisibilityFile {
  std::string crs;
  std::vector<std::string> views;  // image names, in the order of `seen`
  struct Polygon {
    std::string building;  // gml:id of its building in groundtruth.gml
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    std::vector<float> seen;  // per view, 0..1
  };
  std::vector<Polygon> polygons;
};

// The shares are rounded to 0.001. Written under a temporary name and
// renamed; refuses an existing file unless `overwrite`.
void WriteRoofVisibilityJson(const RoofVisibilityFile& file, const std::string& path,
                             bool overwrite);

// Throws Error naming the file (and the polygon's index) when it is not
// such a file or a polygon has no centroid of three numbers or no list of
// numbers `seen`.
RoofVisibilityFile ReadRoofVisibilityJson(const std::string& path);

}  // namespace roofsweep
