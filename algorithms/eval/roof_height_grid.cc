#include "algorithms/eval/roof_height_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "algorithms/core/error.h"
#include "algorithms/eval/plan_view.h"

namespace roofsweep::eval {
namespace {

// A scanline fill of our own rather than cv::fillPoly: OpenCV rounds
// vertices to pixel corners and draws boundary pixels (antialiasing off),
// which biases RMSZ at roof edges; this samples exactly at cell centres and
// evaluates each polygon's own plane equation there.
void FillPolygon(const Polygon3& poly, const Eigen::Vector3d& n, RoofHeightGrid* grid) {
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> edges;
  double ymin = std::numeric_limits<double>::infinity(), ymax = -ymin;
  auto add_ring = [&](const std::vector<Eigen::Vector3d>& ring) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const Eigen::Vector2d a = ring[i].head<2>(), b = ring[(i + 1) % ring.size()].head<2>();
      edges.emplace_back(a, b);
      ymin = std::min(ymin, a.y());
      ymax = std::max(ymax, a.y());
    }
  };
  add_ring(poly.exterior);
  for (const auto& h : poly.holes) add_ring(h);
  const Eigen::Vector3d p0 = poly.exterior[0];
  const int r0 = std::max(0, static_cast<int>(std::floor((ymin - grid->origin.y()) / grid->cell)));
  const int r1 = std::min(grid->rows - 1,
                          static_cast<int>(std::floor((ymax - grid->origin.y()) / grid->cell)));
  std::vector<double> xs;
  for (int r = r0; r <= r1; ++r) {
    const double y = grid->origin.y() + (r + 0.5) * grid->cell;
    xs.clear();
    for (auto [a, b] : edges) {
      // Half-open rule: a vertex exactly on the scanline counts once.
      if ((a.y() <= y) == (b.y() <= y)) continue;
      // The same edge in two neighbouring polygons (opposite directions)
      // must give the very same crossing, or a cell centre on it could fall
      // into neither.
      if (a.y() > b.y()) std::swap(a, b);
      xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
    }
    std::sort(xs.begin(), xs.end());
    for (size_t i = 0; i + 1 < xs.size(); i += 2) {
      // Cell centres x_c = origin + (c + 0.5) cell with xs[i] <= x_c < xs[i+1].
      const int c0 =
          std::max(0, static_cast<int>(std::ceil((xs[i] - grid->origin.x()) / grid->cell - 0.5)));
      const int c1 = std::min(
          grid->cols - 1,
          static_cast<int>(std::ceil((xs[i + 1] - grid->origin.x()) / grid->cell - 0.5)) - 1);
      for (int c = c0; c <= c1; ++c) {
        const double x = grid->origin.x() + (c + 0.5) * grid->cell;
        const double z = p0.z() - (n.x() * (x - p0.x()) + n.y() * (y - p0.y())) / n.z();
        float& cell = grid->z[static_cast<size_t>(r) * grid->cols + c];
        if (std::isnan(cell) || z > cell) cell = static_cast<float>(z);
      }
    }
  }
}

}  // namespace

RoofHeightGrid RasteriseRoofs(const CityModel& model, const Eigen::Vector2d& origin, double cell,
                              int cols, int rows, double vertical_roof_deg) {
  if (!(cell > 0)) throw Error("roof height grid: cell size must be positive");
  if (cols < 0 || rows < 0 || static_cast<double>(cols) * rows > 4e8)
    throw Error("roof height grid: " + std::to_string(cols) + " x " + std::to_string(rows) +
                " cells is too many; use a larger rmsz_grid_m");
  RoofHeightGrid grid;
  grid.origin = origin;
  grid.cell = cell;
  grid.cols = cols;
  grid.rows = rows;
  grid.z.assign(static_cast<size_t>(cols) * rows, std::numeric_limits<float>::quiet_NaN());
  const double min_nz = std::sin((90.0 - vertical_roof_deg) * M_PI / 180.0);
  for (const auto& b : model.buildings)
    for (const auto& s : b.surfaces) {
      if (s.type != SurfaceType::kRoof) continue;
      for (const auto& p : s.polygons) {
        if (p.exterior.size() < 3) continue;
        const Eigen::Vector3d n = UpwardNormal(p);
        if (n.z() < min_nz || n.z() <= 0) continue;
        FillPolygon(p, n, &grid);
      }
    }
  return grid;
}

HeightComparison CompareHeights(const RoofHeightGrid& result, const RoofHeightGrid& reference) {
  if (result.cols != reference.cols || result.rows != reference.rows)
    throw Error("roof height grid: the two grids differ in size");
  HeightComparison h;
  double sum = 0, sum2 = 0;
  for (size_t i = 0; i < result.z.size(); ++i) {
    const bool a = !std::isnan(result.z[i]), b = !std::isnan(reference.z[i]);
    if (a && b) {
      const double d = static_cast<double>(result.z[i]) - reference.z[i];
      ++h.cells_both;
      sum += d;
      sum2 += d * d;
    } else if (a) {
      ++h.cells_result;
    } else if (b) {
      ++h.cells_reference;
    }
  }
  if (h.cells_both > 0) {
    h.rms = std::sqrt(sum2 / h.cells_both);
    h.mean = sum / h.cells_both;
  }
  return h;
}

std::optional<GridSpan> SpanGrid(const CityModel& a, const CityModel& b, double c) {
  const auto ba = a.Bounds(), bb = b.Bounds();
  const double x0 = std::min(ba(0), bb(0)), y0 = std::min(ba(1), bb(1));
  const double x1 = std::max(ba(3), bb(3)), y1 = std::max(ba(4), bb(4));
  if (!std::isfinite(x0) || !std::isfinite(x1)) return std::nullopt;
  GridSpan g;
  g.origin = Eigen::Vector2d(std::floor(x0 / c) * c, std::floor(y0 / c) * c);
  const double cols_d = std::ceil((x1 - g.origin.x()) / c) + 1;
  const double rows_d = std::ceil((y1 - g.origin.y()) / c) + 1;
  if (cols_d * rows_d > 4e8)
    throw Error("RMSZ grid of " + std::to_string(static_cast<long long>(cols_d * rows_d)) +
                " cells is too large; use a larger rmsz_grid_m");
  g.cols = static_cast<int>(cols_d);
  g.rows = static_cast<int>(rows_d);
  return g;
}

}  // namespace roofsweep::eval
