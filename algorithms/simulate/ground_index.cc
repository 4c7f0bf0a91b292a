#include "algorithms/simulate/ground_index.h"

#include <algorithm>
#include <cmath>

namespace roofsweep {
namespace sim {

void GroundIndex::Build(const GroundLayout& g, const Eigen::Vector4d& area) {
  layout_ = &g;
  const double margin = 400;
  x0_ = area[0] - margin, y0_ = area[1] - margin;
  nx_ = static_cast<int>(std::ceil((area[2] - area[0] + 2 * margin) / kCell));
  ny_ = static_cast<int>(std::ceil((area[3] - area[1] + 2 * margin) / kCell));
  cells_.assign(static_cast<size_t>(nx_) * ny_, {});
  for (size_t r = 0; r < g.regions.size(); ++r) {
    const GroundRegion& reg = g.regions[r];
    const Eigen::Vector2d n(-reg.axis.y(), reg.axis.x());
    const Eigen::Vector2d ext =
        (reg.half_size.x() * reg.axis).cwiseAbs() + (reg.half_size.y() * n).cwiseAbs();
    const int cx0 =
        std::max(0, static_cast<int>(std::floor((reg.center.x() - ext.x() - x0_) / kCell)));
    const int cx1 =
        std::min(nx_ - 1, static_cast<int>(std::floor((reg.center.x() + ext.x() - x0_) / kCell)));
    const int cy0 =
        std::max(0, static_cast<int>(std::floor((reg.center.y() - ext.y() - y0_) / kCell)));
    const int cy1 =
        std::min(ny_ - 1, static_cast<int>(std::floor((reg.center.y() + ext.y() - y0_) / kCell)));
    for (int cy = cy0; cy <= cy1; ++cy)
      for (int cx = cx0; cx <= cx1; ++cx)
        cells_[static_cast<size_t>(cy) * nx_ + cx].push_back(static_cast<int>(r));
  }
}

int GroundIndex::MaterialAt(const Eigen::Vector2d& p) const {
  const int cx = static_cast<int>(std::floor((p.x() - x0_) / kCell));
  const int cy = static_cast<int>(std::floor((p.y() - y0_) / kCell));
  if (cx < 0 || cy < 0 || cx >= nx_ || cy >= ny_) return layout_->MaterialAt(p);
  const auto& list = cells_[static_cast<size_t>(cy) * nx_ + cx];
  for (auto it = list.rbegin(); it != list.rend(); ++it)
    if (layout_->regions[*it].Contains(p)) return layout_->regions[*it].material;
  return layout_->base_material;
}

}  // namespace sim
}  // namespace roofsweep
