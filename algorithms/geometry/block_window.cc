#include "algorithms/geometry/block_window.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace roofsweep {

BlockWindows CropBlockToRegion(const Block& block, const Eigen::Vector4d& region, double z_min,
                               double z_max, int margin_px) {
  BlockWindows out;
  out.block = block;
  out.block.views.clear();
  out.block.cameras.clear();
  // The box's twelve edges, each sampled at nine points. Corner k has x
  // from bit 0, y from bit 1 and z from bit 2; an edge joins two corners
  // that differ in one bit.
  const auto corner = [&](int k) {
    return Eigen::Vector3d(region[(k & 1) ? 2 : 0], region[(k & 2) ? 3 : 1],
                           (k & 4) ? z_max : z_min);
  };
  std::vector<Eigen::Vector3d> samples;
  constexpr int kSteps = 8;
  for (int a = 0; a < 8; ++a)
    for (int bit : {1, 2, 4}) {
      if (a & bit) continue;
      const Eigen::Vector3d p = corner(a), q = corner(a | bit);
      for (int k = 0; k <= kSteps; ++k) samples.push_back(p + (q - p) * (double(k) / kSteps));
    }
  for (size_t v = 0; v < block.views.size(); ++v) {
    const View& view = block.views[v];
    const Camera& camera = block.CameraOf(view);
    const PixelWindow image{0, 0, camera.width, camera.height};
    double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
    bool behind = false;
    for (const Eigen::Vector3d& p : samples) {
      const std::optional<Eigen::Vector2d> q = Project(camera, view.pose, p);
      if (!q || !q->allFinite()) {
        behind = true;
        break;
      }
      lo_x = std::min(lo_x, q->x()), hi_x = std::max(hi_x, q->x());
      lo_y = std::min(lo_y, q->y()), hi_y = std::max(hi_y, q->y());
    }
    PixelWindow w = image;
    if (!behind) {
      const double x0 = std::max(0.0, std::floor(lo_x) - margin_px);
      const double y0 = std::max(0.0, std::floor(lo_y) - margin_px);
      const double x1 = std::min<double>(camera.width, std::ceil(hi_x) + margin_px);
      const double y1 = std::min<double>(camera.height, std::ceil(hi_y) + margin_px);
      if (!(x1 > x0) || !(y1 > y0)) continue;  // the region lies beside this image
      w = {static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1 - x0),
           static_cast<int>(y1 - y0)};
    }
    Camera cropped = camera;
    cropped.cx -= w.x;
    cropped.cy -= w.y;
    cropped.width = w.width;
    cropped.height = w.height;
    View kept = view;
    kept.camera = static_cast<int>(out.block.cameras.size());
    out.block.cameras.push_back(std::move(cropped));
    out.block.views.push_back(std::move(kept));
    out.source_view.push_back(static_cast<int>(v));
    out.windows.push_back(w);
  }
  return out;
}

}  // namespace roofsweep
