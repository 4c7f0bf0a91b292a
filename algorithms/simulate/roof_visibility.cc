#include "algorithms/simulate/roof_visibility.h"

#include <cmath>
#include <map>
#include <tuple>

#include "algorithms/buildings/convex_polygon2.h"
#include "algorithms/geometry/view.h"

namespace roofsweep {
namespace sim {

std::vector<RoofPolygonVisibility> RoofVisibility(const Renderer& renderer, const Scene& scene,
                                                  const std::vector<SimulatedView>& views) {
  std::vector<RoofPolygonVisibility> out;
  std::map<std::tuple<int, int, int>, size_t> index;
  for (size_t b = 0; b < scene.city.buildings.size(); ++b) {
    const Building& building = scene.city.buildings[b];
    for (size_t s = 0; s < building.surfaces.size(); ++s) {
      if (building.surfaces[s].type != SurfaceType::kRoof) continue;
      for (size_t p = 0; p < building.surfaces[s].polygons.size(); ++p) {
        const auto& ring = building.surfaces[s].polygons[p].exterior;
        RoofPolygonVisibility v;
        v.building = static_cast<int>(b);
        v.surface = static_cast<int>(s);
        v.polygon = static_cast<int>(p);
        size_t n = ring.size();
        if (n > 1 && ring.front() == ring.back()) --n;
        for (size_t k = 0; k < n; ++k) v.centroid += ring[k];
        if (n > 0) v.centroid /= static_cast<double>(n);
        v.seen.assign(views.size(), 0.0f);
        index[{v.building, v.surface, v.polygon}] = out.size();
        out.push_back(std::move(v));
      }
    }
  }
  // Roof faces of the renderer, by the polygon they belong to.
  const std::vector<FaceInfo>& faces = renderer.faces();
  std::vector<long> roof_of(faces.size(), -1);
  for (size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].kind != FaceKind::kRoof) continue;
    const auto it = index.find({faces[f].building, faces[f].surface, faces[f].polygon});
    if (it != index.end()) roof_of[f] = static_cast<long>(it->second);
  }
  for (size_t v = 0; v < views.size(); ++v) {
    const GeometryMaps maps = renderer.RenderGeometry(views[v].camera, views[v].pose);
    std::vector<double> visible(out.size(), 0.0);
    for (int y = 0; y < maps.face.rows; ++y) {
      const int* row = maps.face.ptr<int>(y);
      for (int x = 0; x < maps.face.cols; ++x)
        if (row[x] >= 0 && roof_of[row[x]] >= 0) visible[roof_of[row[x]]] += 1;
    }
    for (size_t i = 0; i < out.size(); ++i) {
      if (visible[i] == 0) continue;
      const RoofPolygonVisibility& r = out[i];
      const auto& ring =
          scene.city.buildings[r.building].surfaces[r.surface].polygons[r.polygon].exterior;
      // Projected area by the shoelace formula over the projected ring: a
      // roof polygon lies in front of every nadir view.
      Ring2 q;
      for (const Eigen::Vector3d& X : ring) {
        const auto p = Project(views[v].camera, views[v].pose, X);
        if (!p) break;
        q.push_back(*p);
      }
      if (q.size() < 3 || q.size() < ring.size()) continue;
      const double area = std::abs(SignedArea(q));
      if (area > 0) out[i].seen[v] = static_cast<float>(std::min(1.0, visible[i] / area));
    }
  }
  return out;
}

}  // namespace sim
}  // namespace roofsweep
