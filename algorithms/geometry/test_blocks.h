#pragma once

// Synthetic blocks for tests.
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/geometry/block.h"

namespace roofsweep {

// One nadir view per centre (named prefix0, prefix1, ...) of an ideal camera "c":
// 1000 x 1000 px, f = 1000 px, principal point at the centre, image x
// along +x and y along -y of the world. Ground at z = 0, buildings up to
// 20 m: from 100 m up, 10 cm GSD.
inline Block NadirTestBlock(const std::vector<Eigen::Vector3d>& centres,
                            const std::string& prefix = "v") {
  Block b;
  Camera c;
  c.id = "c";
  c.width = c.height = 1000;
  c.fx = c.fy = 1000;
  c.cx = c.cy = 500;
  b.cameras.push_back(c);
  for (size_t k = 0; k < centres.size(); ++k) {
    View v;
    v.name = prefix + std::to_string(k);
    v.camera = 0;
    v.pose.R = Eigen::Vector3d(1, -1, -1).asDiagonal();
    v.pose.C = centres[k];
    b.views.push_back(v);
  }
  b.ground.height = 0;
  b.max_building_height = 20;
  return b;
}

// A square-celled grid whose north-west corner is (x0, y0), holding
// height(x, y) at every cell centre: DTMs and DSMs for tests.
template <class HeightFn>
GroundModel::Grid SampledGrid(double x0, double y0, double cell, int rows, int cols,
                              HeightFn&& height) {
  GroundModel::Grid g;
  g.x0 = x0;
  g.y0 = y0;
  g.dx = g.dy = cell;
  g.rows = rows;
  g.cols = cols;
  g.z.reserve(static_cast<size_t>(rows) * cols);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      g.z.push_back(static_cast<float>(height(x0 + (c + 0.5) * cell, y0 - (r + 0.5) * cell)));
  return g;
}

}  // namespace roofsweep
