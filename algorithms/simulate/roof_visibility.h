#pragma once

#include <Eigen/Core>
#include <vector>

#include "algorithms/simulate/camera_layout.h"
#include "algorithms/simulate/renderer.h"
#include "algorithms/simulate/scene.h"

namespace roofsweep {
namespace sim {

// How much of one true roof polygon each view sees. Trees over garden
// sheds and the block's edge hide roofs from all but one view or from
// every view; no method reconstructs those, so the evaluation tells them
// apart from the roofs it could have found (roofsweep eval, "seen in two
// views").
struct RoofPolygonVisibility {
  int building = -1, surface = -1, polygon = -1;  // into Scene::city
  // Mean of the exterior ring's vertices (closing vertex excluded), local
  // frame: how the evaluation finds the polygon again in the written model.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  // Per view: the pixels where the polygon is the visible surface over its
  // projected area (the whole projection, inside the image or not).
  std::vector<float> seen;
};

// The roof polygons of scene.city, in building, surface, polygon order,
// with what `views` see of them (Renderer::RenderGeometry per view).
// Deterministic.
std::vector<RoofPolygonVisibility> RoofVisibility(const Renderer& renderer, const Scene& scene,
                                                  const std::vector<SimulatedView>& views);

}  // namespace sim
}  // namespace roofsweep
