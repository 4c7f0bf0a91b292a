#pragma once

#include <Eigen/Core>
#include <vector>

#include "algorithms/simulate/scene.h"

namespace roofsweep {
namespace sim {

// Uniform grid over the ground regions so that a lookup tests the few
// regions of one cell instead of all of them (a town has thousands of
// gardens, paths, beds and markings). Same answer as GroundLayout::MaterialAt.
class GroundIndex {
 public:
  void Build(const GroundLayout& g, const Eigen::Vector4d& area);
  int MaterialAt(const Eigen::Vector2d& p) const;

 private:
  static constexpr double kCell = 4.0;
  const GroundLayout* layout_ = nullptr;
  double x0_ = 0, y0_ = 0;
  int nx_ = 0, ny_ = 0;
  std::vector<std::vector<int>> cells_;
};

}  // namespace sim
}  // namespace roofsweep
