#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/geometry/camera.h"
#include "algorithms/geometry/view.h"

namespace roofsweep {

// Terrain under the block in the local frame: a constant height, or a grid
// (a DTM resampled by io), or nothing known.
struct GroundModel {
  std::optional<double> height;  // constant z in the local frame

  // Regular grid, row-major, z in the local frame; NaN where there is no
  // data. Cell (r, c) centre is (x0 + (c + 0.5) dx, y0 - (r + 0.5) dy).
  struct Grid {
    double x0 = 0, y0 = 0, dx = 0, dy = 0;
    int rows = 0, cols = 0;
    std::vector<float> z;
  };
  std::optional<Grid> grid;

  bool Known() const { return height.has_value() || grid.has_value(); }
  // Height at (x, y), bilinear on the grid; falls back to `height`, then NaN.
  double HeightAt(double x, double y) const;
  // The ground near (x, y) as a plane (n, d), n . X + d = 0, unit n with
  // n.z > 0: through HeightAt(x, y), tilted by the DTM's slope between
  // (x, y) -+ `radius` along x and along y (level where that is unknown).
  // NaN where the height is. On a hillside a level plane at the height
  // under a roof's centre misses the terrain at its edges by slope x radius.
  Eigen::Vector4d PlaneAt(double x, double y, double radius) const;
};

// How the local frame relates to the block's CRS. Pure description: the
// transformation itself lives in io (PROJ), algorithms never need it.
struct FrameInfo {
  std::string crs;  // definition as given ("EPSG:25833"); empty: no CRS
  // Origin of the local ENU frame, geographic (degrees) + ellipsoidal height.
  double origin_lat = 0, origin_lon = 0, origin_h = 0;
  bool HasCrs() const { return !crs.empty(); }
};

// An oriented image block in its local frame (ENU metres when there is a
// CRS, the block's own Cartesian frame otherwise).
struct Block {
  std::string source;  // file it was read from, for messages
  FrameInfo frame;
  std::vector<Camera> cameras;
  std::vector<View> views;
  GroundModel ground;
  // The surface model (DSM) the ground was derived from, when the block
  // gives one (manifest ground/dsm): not used by the reconstruction, only to
  // check its 3D lines on real blocks (eval::LinesOnSurface).
  std::optional<GroundModel::Grid> surface;
  double max_building_height = 60.0;  // m above ground; bounds disparities
  std::string footprints_path;        // optional OGR dataset
  std::string footprints_layer;
  // Optional area of interest in the local frame: min x, min y, max x, max y.
  std::optional<Eigen::Vector4d> aoi;

  const Camera& CameraOf(const View& v) const { return cameras.at(static_cast<size_t>(v.camera)); }
  int FindView(const std::string& name) const;  // -1 when absent
};

}  // namespace roofsweep
